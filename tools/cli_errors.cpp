#include "tools/cli_errors.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "network/toml_util.hpp"
#include "tools/paper_data.hpp"
#include "workloads/params.hpp"
#include "workloads/registry.hpp"

namespace tools {

namespace {

using network::join;

std::vector<std::string> command_names(const CLI::App& app) {
  std::vector<std::string> names;
  for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; }))
    names.push_back(sub->get_name());
  return names;
}

std::vector<std::string> option_names(const CLI::App& command) {
  std::vector<std::string> names;
  for (const CLI::Option* o : command.get_options())
    if (!o->get_lnames().empty())
      names.push_back("--" + o->get_lnames().front());
    else if (!o->get_snames().empty())
      names.push_back("-" + o->get_snames().front());
  return names;
}

bool looks_like_option(const std::string& arg) {
  return arg.size() > 1 && arg[0] == '-' &&
         !(std::isdigit(static_cast<unsigned char>(arg[1])) || arg[1] == '.');
}

// The scene key a mistaken option probably meant: [network] keys and workload parameters, by name.
std::optional<std::string> scene_key_for(const std::string& name) {
  for (const char* key :
       {"topology", "family", "workers", "link_speed_mbps", "link_protocol", "processor"})
    if (name == key) return "network." + name;
  for (const workloads::WorkloadInfo& w : workloads::workload_catalog())
    if (w.find(name)) return "workload." + name;
  return std::nullopt;
}

std::string unknown_option(const CLI::App& command, const std::vector<std::string>& args,
                           std::size_t at) {
  const std::string& arg = args[at];
  const auto eq = arg.find('=');
  const std::string flag = arg.rfind("--", 0) == 0 ? arg.substr(0, eq) : arg.substr(0, 2);
  std::string message = "unknown option " + flag + " for `t800sim " + command.get_name() + "`";
  const bool has_set = command.get_option_no_throw("--set") != nullptr;
  const auto name_at = flag.find_first_not_of('-');
  const std::string bare = name_at == std::string::npos ? "" : flag.substr(name_at);
  if (const auto key = scene_key_for(bare); key && has_set) {
    std::string value = "VALUE";
    if (eq != std::string::npos)
      value = arg.substr(eq + 1);
    else if (at + 1 < args.size() && !looks_like_option(args[at + 1]))
      value = args[at + 1];
    message += "; scene keys are set with --set KEY=VALUE: --set " + *key + "=" + value;
  }
  return message + "; its options are " + join(option_names(command)) + " (t800sim " +
         command.get_name() + " --help)";
}

std::string missing_scene(const CLI::App& command) {
  std::string message = "`t800sim " + command.get_name() + "` needs a scene file";
  const std::vector<std::string> scenes = shipped_scenes();
  if (scenes.empty()) return message + " (configs/scenes/*.toml in the repository)";
  return message + ", e.g. t800sim " + command.get_name() + " configs/scenes/" + scenes.front() +
         "; the scenes in configs/scenes/ are " + join(scenes);
}

}  // namespace

std::vector<std::string> shipped_scenes() {
  namespace fs = std::filesystem;
  std::vector<std::string> scenes;
  try {
    for (const fs::directory_entry& e :
         fs::directory_iterator(find_repository_file("configs/scenes")))
      if (e.path().extension() == ".toml") scenes.push_back(e.path().filename().string());
  } catch (const std::exception&) {
    return {};
  }
  std::sort(scenes.begin(), scenes.end());
  return scenes;
}

std::optional<std::string> explain_parse_error(const CLI::App& app,
                                               const std::vector<std::string>& args,
                                               const CLI::ParseError& error) {
  if (error.get_exit_code() == 0) return std::nullopt;  // --help and the like
  const std::string commands = join(command_names(app));
  if (args.empty())
    return "give a command: one of " + commands + " (t800sim --help; t800sim COMMAND --help)";
  if (looks_like_option(args[0]) && !app.get_option_no_throw(args[0].substr(0, args[0].find('='))))
    return "unknown option " + args[0] + "; give a command first: one of " + commands +
           " (t800sim --help)";
  if (looks_like_option(args[0])) return std::nullopt;
  const CLI::App* command = nullptr;
  try {
    command = app.get_subcommand(args[0]);
  } catch (const CLI::OptionNotFound&) {
    return "unknown command '" + args[0] + "'; the commands are " + commands + " (t800sim --help)";
  }
  for (std::size_t i = 1; i < args.size(); ++i) {
    if (args[i] == "--") break;
    // "--name=value", "-j4": the option's own name.
    const std::string flag =
        args[i].rfind("--", 0) == 0 ? args[i].substr(0, args[i].find('=')) : args[i].substr(0, 2);
    if (looks_like_option(args[i]) && !command->get_option_no_throw(flag))
      return unknown_option(*command, args, i);
  }
  const CLI::Option* scene = command->get_option_no_throw("scene");
  if (scene && scene->count() == 0 && dynamic_cast<const CLI::RequiredError*>(&error))
    return missing_scene(*command);
  return std::nullopt;
}

}  // namespace tools
