// `t800sim occam build SOURCE.occ --toolset DIR`: an occam program compiled, linked and collected
// into a bootable file by an INMOS occam toolset the user has (D7205A: oc, ilink, icollect), every
// tool running on t800sim's own instruction-set simulator (`t800sim boot TOOL.btl`), so the host
// needs nothing of INMOS's. The program is a host program as the toolset makes them: a PROC
// taking the host channels (CHAN OF SP fs, ts, []INT memory), linked with hostio.lib for one T800.
//
//   t800sim occam build prog.occ --toolset ~/d7205 -o prog.btl   then   t800sim boot prog.btl
//
// Nothing of the toolset is part of t800sim: without a toolset the command says what is missing.
#include <unistd.h>

#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "tools/child_run.hpp"
#include "tools/commands.hpp"

namespace tools {

namespace {

namespace fs = std::filesystem;

struct OccamBuildArgs {
  std::string source, toolset, output, work_dir;
  std::vector<std::string> separately;  // units compiled apart and linked in (#USE "name.t8c")
  std::vector<std::string> oc_options;  // -k (no range checks), -u (no run-time checks), ...
  double max_host_s = 900;              // a tool that spins is stopped
};

// What the build uses of a D7205A toolset; every missing one is named at once.
const std::vector<std::string> kToolsetFiles{"itools/oc.btl", "itools/ilink.btl",
                                             "itools/icollect.btl", "libs/hostio.lib",
                                             "libs/occam8.lnk"};

fs::path checked_toolset(const std::string& dir) {
  if (dir.empty()) throw std::invalid_argument("--toolset: give the toolset's directory");
  const fs::path root(dir);
  if (!fs::is_directory(root))
    throw std::invalid_argument("--toolset " + dir +
                                ": not a directory (give the INMOS D7205A toolset's directory, "
                                "the one holding itools/ and libs/)");
  std::string missing;
  for (const std::string& f : kToolsetFiles)
    if (!fs::is_regular_file(root / f)) missing += (missing.empty() ? "" : ", ") + f;
  if (!missing.empty())
    throw std::invalid_argument("--toolset " + dir + ": not a D7205A occam toolset, it has no " +
                                missing);
  return fs::absolute(root);
}

// A source is an occam file whose name oc takes as its unit's: letters, digits, '.' and '_'.
fs::path checked_source(const std::string& path, const char* what) {
  const fs::path p(path);
  if (p.extension() != ".occ")
    throw std::invalid_argument(fmt::format("{} {}: not an occam source (NAME.occ)", what, path));
  if (!fs::is_regular_file(p))
    throw std::invalid_argument(fmt::format("{} {}: no such file", what, path));
  for (char c : p.stem().string())
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '.' && c != '_')
      throw std::invalid_argument(fmt::format(
          "{} {}: oc takes a unit's name from its file name: letters, digits, '.' and '_' only",
          what, path));
  return fs::absolute(p);
}

// The directory the tools see as their host's: the sources beside one another, the toolset's
// libraries beneath it (the iserver is sandboxed to --host-dir; ISEARCH=libs/ points oc and ilink
// at them).
class WorkDir {
 public:
  explicit WorkDir(const std::string& given) {
    if (!given.empty()) {
      path_ = fs::absolute(given);
      fs::create_directories(path_);
      return;
    }
    std::string pattern = (fs::temp_directory_path() / "t800sim-occam.XXXXXX").string();
    if (!mkdtemp(pattern.data())) throw std::runtime_error("cannot create a temporary directory");
    path_ = pattern;
    temporary_ = true;
  }
  ~WorkDir() {
    std::error_code ignored;
    if (temporary_ && !kept_) fs::remove_all(path_, ignored);
  }
  WorkDir(const WorkDir&) = delete;
  WorkDir& operator=(const WorkDir&) = delete;
  const fs::path& path() const { return path_; }
  void keep() { kept_ = true; }  // a failed tool's files, for the user to look at
  bool temporary() const { return temporary_; }

 private:
  fs::path path_;
  bool temporary_ = false, kept_ = false;
};

// One toolset program run on t800sim; its output is shown only when it fails.
void run_tool(const fs::path& toolset, const std::string& tool,
              const std::vector<std::string>& arguments, WorkDir& work, double max_host_s) {
  std::vector<std::string> args{"boot",
                                (toolset / "itools" / (tool + ".btl")).string(),
                                "--host-dir",
                                work.path().string(),
                                "--max-host-s",
                                fmt::format("{}", max_host_s),
                                "--"};
  args.insert(args.end(), arguments.begin(), arguments.end());
  const ChildOutput out = run_self(args);
  std::string line = tool;
  for (const std::string& a : arguments) line += " " + a;
  if (out.exit_code == 0) {
    std::cout << fmt::format("  {} ({:.1f} s)\n", line, out.wall_s);
    return;
  }
  work.keep();
  std::cerr << out.out << out.err;
  throw std::runtime_error(fmt::format("{} failed (exit {}); its files are in {}", line,
                                       out.exit_code, work.path().string()));
}

int build(const OccamBuildArgs& args) {
  const fs::path toolset = checked_toolset(args.toolset);
  const fs::path source = checked_source(args.source, "SOURCE");
  std::vector<fs::path> units;
  for (const std::string& s : args.separately) units.push_back(checked_source(s, "--with"));
  const std::string name = source.stem().string();
  const fs::path output = fs::absolute(args.output.empty() ? name + ".btl" : args.output);
  if (!fs::is_directory(output.parent_path()))
    throw std::invalid_argument("-o " + output.string() + ": its directory does not exist");

  WorkDir work(args.work_dir);
  fs::copy(toolset / "libs", work.path() / "libs",
           fs::copy_options::recursive | fs::copy_options::overwrite_existing);
  for (const fs::path& s : units)
    fs::copy_file(s, work.path() / s.filename(), fs::copy_options::overwrite_existing);
  fs::copy_file(source, work.path() / source.filename(), fs::copy_options::overwrite_existing);
  setenv("ISEARCH", "libs/", 1);  // the children inherit it; relative to their host directory

  std::cout << fmt::format("occam build {} with {}:\n", source.string(), toolset.string());
  const auto compile = [&](const std::string& unit, const std::string& object) {
    std::vector<std::string> oc{unit, "-t8"};
    oc.insert(oc.end(), args.oc_options.begin(), args.oc_options.end());
    oc.insert(oc.end(), {"-o", object});
    run_tool(toolset, "oc", oc, work, args.max_host_s);
  };
  std::vector<std::string> link{name + ".t8h"};
  for (const fs::path& u : units) {
    compile(u.stem().string(), u.stem().string() + ".t8c");
    link.push_back(u.stem().string() + ".t8c");
  }
  compile(name, name + ".t8h");
  link.insert(link.end(), {"hostio.lib", "-f", "occam8.lnk", "-t8", "-o", name + ".c8h"});
  run_tool(toolset, "ilink", link, work, args.max_host_s);
  run_tool(toolset, "icollect", {name + ".c8h", "-t", "-p", name + ".map"}, work, args.max_host_s);
  const fs::path built = work.path() / (name + ".btl");
  if (!fs::is_regular_file(built))
    throw std::runtime_error("icollect wrote no " + built.filename().string());
  fs::copy_file(built, output, fs::copy_options::overwrite_existing);
  std::cout << fmt::format(
      "wrote {}{}\n", output.string(),
      work.temporary() ? "" : " (intermediate files in " + work.path().string() + ")");
  return kExitOk;
}

}  // namespace

void add_occam_command(CLI::App& app) {
  auto* occam = app.add_subcommand(
      "occam", "occam programs built by an INMOS toolset running on t800sim (docs/iss.md)");
  occam->require_subcommand(1);
  auto args = std::make_shared<OccamBuildArgs>();
  auto* cmd = occam->add_subcommand(
      "build",
      "Compile, link and collect an occam host program into a bootable file with the D7205A "
      "toolset's oc, ilink and icollect, each run on t800sim's ISS");
  cmd->add_option("source", args->source, "the program: NAME.occ, a PROC (CHAN OF SP fs, ts, ...)")
      ->required();
  cmd->add_option("--toolset", args->toolset,
                  "the INMOS D7205A toolset's directory (itools/, libs/); not part of t800sim")
      ->required()
      ->type_name("DIR");
  cmd->add_option("-o", args->output, "the bootable file (default: NAME.btl here)")
      ->type_name("FILE");
  cmd->add_option("--with", args->separately,
                  "a unit compiled apart and linked in (its #USE \"NAME.t8c\"); repeatable")
      ->type_name("NAME.occ");
  cmd->add_option("--oc", args->oc_options,
                  "an option for oc, e.g. --oc=-k (no range checks), --oc=-u; repeatable")
      ->type_name("OPTION")
      ->allow_extra_args(false);
  cmd->add_option("--work-dir", args->work_dir,
                  "build here and keep the intermediate files (default: a temporary directory)")
      ->type_name("DIR");
  cmd->add_option("--max-host-s", args->max_host_s,
                  "stop a tool that runs longer than this many seconds of host time")
      ->check(CLI::PositiveNumber);
  cmd->callback([args] { run_command([&] { return build(*args); }); });
}

}  // namespace tools
