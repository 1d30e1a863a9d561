#include "tools/scene.hpp"
#include "tools/scene_faults.hpp"

#include <toml++/toml.h>

#include <algorithm>
#include <cctype>
#include <climits>
#include <cmath>
#include <filesystem>
#include <initializer_list>
#include <optional>
#include <set>

#include "network/families.hpp"
#include "network/input_file.hpp"
#include "network/toml_limits.hpp"
#include "network/toml_util.hpp"
#include "network/topology_file.hpp"
#include "sdk/plugin_loader.hpp"
#include "t800/cost_model.hpp"
#include "workloads/registry.hpp"

namespace tools {

namespace {

namespace fs = std::filesystem;
using network::ConfigError;
using network::join;
using network::number;
using network::number_text;
using network::plural;
using network::pos_of;
using network::SourcePos;
using network::type_name;

// "P0, P1, ..." (at most 16 names, then how many more).
std::string processor_names(const network::Topology& topology) {
  std::vector<std::string> names;
  for (const network::ProcessorSpec& p : topology.processors) {
    if (names.size() == 16) {
      names.push_back("and " + std::to_string(topology.processors.size() - 16) + " more");
      break;
    }
    names.push_back(p.name);
  }
  return join(names);
}

std::string article(const std::string& noun) {
  return std::string("aeiou").find(noun.front()) == std::string::npos ? "a " : "an ";
}

bool bare_key_part(const std::string& part) {
  if (part.empty()) return false;
  for (char c : part)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_' && c != '-') return false;
  return true;
}

std::string trim(const std::string& text) {
  const auto first = text.find_first_not_of(" \t");
  if (first == std::string::npos) return "";
  return text.substr(first, text.find_last_not_of(" \t") - first + 1);
}

std::string toml_quoted(const std::string& text) {
  std::string quoted = "\"";
  for (char c : text) {
    if (c == '"' || c == '\\') quoted += '\\';
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7F) {
      quoted += ' ';  // control characters cannot appear in a basic string
      continue;
    }
    quoted += c;
  }
  return quoted + "\"";
}

// "key = value" parsed as its own document named after the flag, so every node it creates (the
// value and any intermediate tables) reports the flag as its position. A value that is not valid
// TOML ("P1", "../x.toml") is taken as a bare string.
toml::table parse_override(const std::string& key, const std::string& value,
                           const std::string& flag) {
  const auto parse = [&](const std::string& document) {
    network::check_toml_limits(document, flag, false);
    return toml::parse(std::string_view(document), std::string_view(flag));
  };
  const bool one_line = value.find_first_of("\r\n") == std::string::npos;
  if (one_line) {
    try {
      return parse(key + " = " + value);
    } catch (const toml::parse_error&) {
      // fall through: a bare string
    }
  }
  try {
    return parse(key + " = " + toml_quoted(value));
  } catch (const toml::parse_error& e) {  // not expected: the value is quoted, the key checked
    throw ConfigError({flag, 0, 0}, std::string(e.description()));
  }
}

// Applies one override and returns its key.
std::string apply_override(toml::table& root, const std::string& text) {
  const std::string flag = "--set " + text;
  const SourcePos at{flag, 0, 0};
  const auto eq = text.find('=');
  if (eq == std::string::npos)
    throw ConfigError(at, "malformed override: expected KEY=VALUE, e.g. --set workload.bytes=4000");
  const std::string key = trim(text.substr(0, eq));
  std::vector<std::string> parts;
  for (std::size_t start = 0;;) {
    const auto dot = key.find('.', start);
    parts.push_back(key.substr(start, dot == std::string::npos ? dot : dot - start));
    if (dot == std::string::npos) break;
    start = dot + 1;
  }
  for (const std::string& part : parts)
    if (!bare_key_part(part))
      throw ConfigError(at, "malformed override key '" + key +
                                "': expected a dotted key of letters, digits, '_' and '-', e.g. "
                                "workload.bytes=4000");
  toml::table parsed = parse_override(key, trim(text.substr(eq + 1)), flag);
  // Walk down both trees; graft the parsed subtree where the scene has nothing yet.
  toml::table* dst = &root;
  toml::table* src = &parsed;
  std::string prefix;
  for (std::size_t i = 0; i < parts.size(); ++i) {
    auto it = src->find(parts[i]);
    toml::node* existing = dst->get(parts[i]);
    if (i + 1 == parts.size() || !existing) {
      dst->insert_or_assign(it->first, std::move(it->second));
      return key;
    }
    prefix += (prefix.empty() ? "" : ".") + parts[i];
    if (!existing->is_table())
      throw ConfigError(at, "cannot set '" + key + "': '" + prefix + "' is " +
                                article(type_name(*existing)) + type_name(*existing) +
                                ", not a table");
    dst = existing->as_table();
    src = it->second.as_table();
  }
  return key;  // not reached: the last part always returns
}

// Scene reading -----------------------------------------------------------------------------------

class SceneReader {
 public:
  SceneReader(const toml::table& root, std::string file) : root_(root), file_(std::move(file)) {}
  Scene read();

 private:
  SourcePos pos(const toml::node& node) const { return pos_of(node.source(), file_); }
  [[noreturn]] void fail(const toml::node& node, const std::string& message) const {
    throw ConfigError(pos(node), message);
  }
  void check_keys(const toml::table& table, const std::vector<std::string>& valid,
                  const std::string& where) const;
  const toml::table& table(const toml::node& node, const std::string& key) const;
  std::string text(const toml::node& node, const std::string& key) const;
  std::string text_or(const toml::table& table, const std::string& key, std::string fallback) const;

  t800::LinkConfig link_config(const toml::table* net, const network::Topology& topology) const;
  void apply_processor_keys(const toml::table& net, t800::ProcessorConfig& config) const;
  void apply_processor_keys(const toml::table& net, network::Topology& topology) const;
  network::Topology topology(const toml::table* net, SourcePos& origin) const;
  network::Topology generated(const toml::table& net, const toml::node& family) const;
  network::Topology from_file(const toml::node& path) const;
  void workload(Scene& scene) const;
  void plugin(const toml::node& path, const toml::node* kind) const;
  void placement(Scene& scene) const;
  void calibration(Scene& scene) const;
  void calibration_values(const toml::table& t, Scene& scene) const;
  void fidelity(Scene& scene) const;
  void compiler(Scene& scene) const;
  bool boolean(const toml::table& t, const std::string& key, bool fallback) const;
  std::string scene_relative(const std::string& name) const;
  workloads::ParamValue fallback(const workloads::ParamSpec& spec) const;
  workloads::ParamValue param(const workloads::ParamSpec& spec, const toml::node& value,
                              const network::Topology& topology) const;

  const toml::table& root_;
  std::string file_;
};

void SceneReader::check_keys(const toml::table& t, const std::vector<std::string>& valid,
                             const std::string& where) const {
  for (auto&& [key, value] : t) {
    bool known = false;
    for (const std::string& name : valid) known = known || key.str() == name;
    if (!known)
      throw ConfigError(pos_of(key.source(), file_), "unknown key '" + std::string(key.str()) +
                                                         "' in " + where + "; valid keys are " +
                                                         join(valid));
  }
}

const toml::table& SceneReader::table(const toml::node& node, const std::string& key) const {
  if (!node.is_table()) fail(node, "'" + key + "': expected a table, got " + type_name(node));
  return *node.as_table();
}

std::string SceneReader::text(const toml::node& node, const std::string& key) const {
  if (!node.is_string()) fail(node, "'" + key + "': expected a string, got " + type_name(node));
  return *node.value<std::string>();
}

std::string SceneReader::text_or(const toml::table& t, const std::string& key,
                                 std::string fallback) const {
  const toml::node* node = t.get(key);
  return node ? text(*node, key) : fallback;
}

// A network of T414s talks the T414's link protocol unless the scene says otherwise.
t800::LinkConfig SceneReader::link_config(const toml::table* network,
                                          const network::Topology& topology) const {
  static const toml::table empty;
  const toml::table& net = network ? *network : empty;
  t800::LinkConfig link;
  if (!topology.processors.empty())
    link.protocol = t800::processor_model(topology.processors.front().config.type).link_protocol;
  if (const toml::node* speed = net.get("link_speed_mbps")) {
    if (!speed->is_number())
      fail(*speed, "'network.link_speed_mbps': expected a number, got " + type_name(*speed));
    link.speed_mbps = number(*speed);
    if (!t800::is_valid_link_speed(link.speed_mbps))
      fail(*speed, "link speed " + number_text(*speed) +
                       " Mbit/s is not supported: a T800 link runs at 5, 10 or 20 Mbit/s");
  }
  if (const toml::node* protocol = net.get("link_protocol")) {
    const std::string name = text(*protocol, "network.link_protocol");
    auto parsed = t800::parse_link_protocol(name);
    if (!parsed)
      fail(*protocol, "unknown link protocol '" + name + "'; valid protocols are overlapped, t414");
    link.protocol = *parsed;
  }
  return link;
}

// `origin` receives where the network was given (Scene::origins).
network::Topology SceneReader::topology(const toml::table* net, SourcePos& origin) const {
  static const toml::table empty;
  const toml::table& n = net ? *net : empty;
  // Exactly one source of processors; naming the ones found makes a clash easy to fix.
  std::vector<std::pair<std::string, const toml::node*>> given;
  for (const char* key : {"topology", "family"})
    if (const toml::node* node = n.get(key))
      given.emplace_back("network." + std::string(key), node);
  if (const toml::node* inline_table = root_.get("topology"))
    given.emplace_back("[topology]", inline_table);
  if (given.empty())
    fail(net ? static_cast<const toml::node&>(*net) : root_,
         "no network given: set network.topology = \"../topologies/pair.toml\", or "
         "network.family = \"tree\" with network.workers = 3, or an inline [topology] table");
  if (given.size() > 1)
    fail(*given[1].second,
         "give only one of network.topology, network.family and [topology]; "
         "this scene has both " +
             given[0].first + " and " + given[1].first);
  origin = pos(*given[0].second);
  const bool family = given[0].first == "network.family";
  if (const toml::node* node = n.get("workers"); node && !family)
    fail(*node,
         "network.workers applies only to a generated network (network.family); a topology file "
         "lists its processors itself. Give a family as well (--set network.family=tree replaces "
         "the topology file), or compare topology files (sweep --vary "
         "network.topology=a.toml,b.toml)");
  if (family) return generated(n, *given[0].second);
  network::Topology t;
  if (given[0].first == "network.topology") {
    t = from_file(*given[0].second);
  } else {
    const toml::node& inline_table = *given[0].second;
    if (!inline_table.is_table())
      fail(inline_table, "'topology': expected a table, got " + type_name(inline_table) +
                             "; to name a topology file, use network.topology");
    t = network::parse_topology(*inline_table.as_table(), file_);
  }
  apply_processor_keys(n, t);
  return t;
}

// network.processor, network.memory, network.wait_states: the type and memory placement of every
// processor, generated or from a topology file (where they override its [[processor]] settings).
void SceneReader::apply_processor_keys(const toml::table& net,
                                       t800::ProcessorConfig& config) const {
  if (const toml::node* type = net.get("processor")) {
    const std::string name = text(*type, "network.processor");
    auto parsed_type = t800::parse_processor_type(name);
    if (!parsed_type)
      fail(*type, "unknown processor type '" + name + "'; valid types are " +
                      t800::processor_type_names());
    config.type = *parsed_type;
  }
  if (const toml::node* memory = net.get("memory")) {
    const std::string name = text(*memory, "network.memory");
    auto placement = t800::parse_placement(name);
    if (!placement)
      fail(*memory, "unknown memory placement '" + name +
                        "'; valid placements are auto (what fits on chip, the rest external), "
                        "onchip, external");
    config.memory.data = config.memory.code = *placement;
  }
  if (const toml::node* ws = net.get("wait_states")) {
    if (!ws->is_integer())
      fail(*ws, "'network.wait_states': expected an integer, got " + type_name(*ws));
    const std::int64_t n = *ws->value<std::int64_t>();
    if (n < 0 || n > 1000)
      fail(*ws, "network.wait_states = " + std::to_string(n) +
                    " is out of range: give the wait states per external access, 0 to 1000");
    config.memory.wait_states = static_cast<int>(n);
  }
}

void SceneReader::apply_processor_keys(const toml::table& net, network::Topology& topology) const {
  for (network::ProcessorSpec& spec : topology.processors) {
    t800::ProcessorConfig config = spec.config;
    apply_processor_keys(net, config);
    spec.config = config;
  }
}

network::Topology SceneReader::generated(const toml::table& net, const toml::node& family) const {
  const std::string name = text(family, "network.family");
  auto parsed = network::parse_family(name);
  if (!parsed)
    fail(family, "unknown network family '" + name + "'; valid families are " +
                     join(network::family_names()));
  const toml::node* workers = net.get("workers");
  if (!workers)
    fail(family, "network.family = \"" + name +
                     "\" needs network.workers, the number of workers besides P0 (e.g. 3)");
  if (!workers->is_integer())
    fail(*workers, "'network.workers': expected an integer, got " + type_name(*workers));
  const std::int64_t count = *workers->value<std::int64_t>();
  if (count < INT_MIN || count > INT_MAX)
    fail(*workers, "network.workers = " + std::to_string(count) + " is out of range");
  t800::ProcessorConfig config;
  apply_processor_keys(net, config);
  return network::generate(*parsed, static_cast<int>(count), config, pos(*workers));
}

// Relative paths are relative to the scene file, so scenes can be run from any directory.
network::Topology SceneReader::from_file(const toml::node& path) const {
  const std::string name = text(path, "network.topology");
  fs::path resolved(name);
  if (resolved.is_relative()) resolved = fs::path(file_).parent_path() / resolved;
  std::error_code ec;
  if (name.empty() || !fs::exists(resolved, ec))
    fail(path, "topology file '" + name + "' not found (looked for " + resolved.string() + ")");
  if (const std::string problem = network::not_regular_file(resolved.string()); !problem.empty())
    fail(path, "topology file '" + name + "': " + problem + "; give a topology file (TOML text)");
  return network::load_topology(resolved.string());
}

workloads::ParamValue SceneReader::param(const workloads::ParamSpec& spec, const toml::node& value,
                                         const network::Topology& topology) const {
  using workloads::ParamType;
  const std::string key = "workload." + spec.name;
  auto wrong_type = [&](const toml::node& node) {
    const std::string type = workloads::to_string(spec.type);
    fail(node, "'" + key + "': expected " + article(type) + type + ", got " + type_name(node));
  };
  auto check_range = [&](double x, const toml::node& node) {
    if ((spec.min && x < *spec.min) || (spec.max && x > *spec.max))
      fail(node, key + " = " + number_text(node) + " is outside the valid range " +
                     (spec.min ? number_text(*spec.min) : "-inf") + " to " +
                     (spec.max ? number_text(*spec.max) : "inf"));
  };
  switch (spec.type) {
    case ParamType::flag:
      if (!value.is_boolean()) wrong_type(value);
      return *value.value<bool>();
    case ParamType::integer: {
      if (!value.is_integer()) wrong_type(value);
      const std::int64_t n = *value.value<std::int64_t>();
      check_range(static_cast<double>(n), value);
      return n;
    }
    case ParamType::real: {
      if (!value.is_number()) wrong_type(value);  // an integer is a fine real
      const double x = number(value);
      if (!std::isfinite(x))
        fail(value, key + " is " + number_text(value) + ": give a finite number");
      check_range(x, value);
      return x;
    }
    case ParamType::text: {
      if (!value.is_string()) wrong_type(value);
      const std::string s = *value.value<std::string>();
      if (!spec.choices.empty()) {
        bool ok = false;
        for (const std::string& c : spec.choices) ok = ok || c == s;
        if (!ok)
          fail(value, key + " = \"" + s + "\" is not valid; choose one of " + join(spec.choices));
      }
      return s;
    }
    case ParamType::processor: {
      if (!value.is_string()) wrong_type(value);
      const std::string s = *value.value<std::string>();
      if (!s.empty() && topology.find(s) < 0)
        fail(value, key + " = \"" + s + "\": there is no processor '" + s +
                        "' in the topology; processors are " + processor_names(topology));
      return s;
    }
    case ParamType::input_file:
    case ParamType::output_file:
    case ParamType::robot_file:
      if (!value.is_string()) wrong_type(value);
      return scene_relative(*value.value<std::string>());
    case ParamType::precision: {
      if (!value.is_string()) wrong_type(value);
      const std::string s = *value.value<std::string>();
      if (!t800::parse_precision(s))
        fail(value, key + " = \"" + s + "\" is not valid; choose one of real32, real64");
      return s;
    }
    case ParamType::real_list: {
      if (!value.is_array()) wrong_type(value);
      std::vector<double> list;
      for (const toml::node& element : *value.as_array()) {
        if (!element.is_number())
          fail(element, "'" + key + "': expected an array of numbers, got an element of type " +
                            type_name(element));
        list.push_back(number(element));
        if (!std::isfinite(list.back()))
          fail(element, key + " contains " + number_text(element) + ": give finite numbers");
        check_range(list.back(), element);
      }
      return list;
    }
  }
  return {};
}

// A file a workload names is relative to the scene that names it, like the scene's topology file.
// (Whether it is there is the run's inputs' question: tools/run_inputs.cpp.)
std::string SceneReader::scene_relative(const std::string& name) const {
  if (name.empty()) return name;  // none
  fs::path resolved(name);
  if (resolved.is_relative()) resolved = fs::path(file_).parent_path() / resolved;
  return resolved.string();
}

workloads::ParamValue SceneReader::fallback(const workloads::ParamSpec& spec) const {
  if (!is_file(spec.type)) return spec.default_value;
  return scene_relative(std::get<std::string>(spec.default_value));
}

// workload.plugin, relative to the scene file: its kinds exist once it is loaded. An error names
// the kind the scene wanted from it, if it says.
void SceneReader::plugin(const toml::node& path, const toml::node* kind) const {
  const std::string name = text(path, "workload.plugin");
  if (name.empty()) fail(path, "workload.plugin is empty: give the path of a plugin (lib*.so)");
  try {
    t800sim::detail::load_plugin(scene_relative(name));
  } catch (const t800sim::detail::PluginError& e) {
    const std::optional<std::string> wanted =
        kind ? kind->value<std::string>() : std::optional<std::string>();
    fail(path, "workload.plugin" + (wanted ? " (for workload kind " + *wanted + ")" : "") + ": " +
                   e.what());
  }
}

void SceneReader::workload(Scene& scene) const {
  const toml::node* node = root_.get("workload");
  const toml::table* workload_table = node ? node->as_table() : nullptr;
  if (const toml::node* path = workload_table ? workload_table->get("plugin") : nullptr)
    plugin(*path, workload_table->get("kind"));
  std::vector<std::string> kinds;
  for (const workloads::WorkloadInfo& w : workloads::workload_catalog()) kinds.push_back(w.kind);
  if (!node) fail(root_, "no [workload] table: add one with kind = one of " + join(kinds));
  const toml::table& t = table(*node, "workload");
  const toml::node* kind = t.get("kind");
  if (!kind) fail(t, "[workload] has no kind: set kind = one of " + join(kinds));
  scene.workload_kind = text(*kind, "workload.kind");
  const workloads::WorkloadInfo* info = workloads::find_workload(scene.workload_kind);
  if (!info)
    fail(*kind,
         "unknown workload kind '" + scene.workload_kind + "'; valid kinds are " + join(kinds));
  std::vector<std::string> valid{"kind", "plugin"};
  for (const workloads::ParamSpec& p : info->params) valid.push_back(p.name);
  check_keys(t, valid, "[workload] of kind " + info->kind);
  scene.origins["workload"] = pos(t);
  for (const workloads::ParamSpec& spec : info->params) {
    const toml::node* value = t.get(spec.name);
    if (value) scene.origins["workload." + spec.name] = pos(*value);
    scene.workload.set(spec.name, value ? param(spec, *value, scene.topology) : fallback(spec));
    if (!value) scene.workload_defaults.push_back(spec.name);
  }
}

// [calibration] holds the one constant the paper's data may fit, and says how it was fitted: a
// fitted number without its provenance is not accepted. `file` names the project's calibration file
// (one source for every scene); a code_efficiency given in the scene itself (or by --set) takes
// precedence over the file's.
void SceneReader::calibration(Scene& scene) const {
  const toml::node* node = root_.get("calibration");
  if (!node) return;
  const toml::table& t = table(*node, "calibration");
  check_keys(t, {"file", "code_efficiency", "fitted"}, "[calibration]");
  if (const toml::node* file = t.get("file")) {
    const std::string name = text(*file, "calibration.file");
    const fs::path path = fs::path(file_).parent_path() / name;
    std::error_code ec;
    if (name.empty() || !fs::exists(path, ec))
      fail(*file,
           "calibration file '" + name + "' not found (looked for " + path.string() +
               "; calibration.file is relative to the scene file): copy the calibration file "
               "there, correct the path, or give code_efficiency and fitted in [calibration] "
               "instead");
    if (const std::string problem = network::not_regular_file(path.string()); !problem.empty())
      fail(*file,
           "calibration file '" + name + "': " + problem + "; give a calibration file (TOML text)");
    const toml::table shared = network::parse_toml_file(path.string(), "calibration file");
    const toml::node* inner = shared.get("calibration");
    if (!inner || !inner->is_table())
      fail(*file, "the calibration file " + path.string() + " has no [calibration] table");
    SceneReader(shared, path.string()).calibration_values(*inner->as_table(), scene);
  }
  if (t.contains("code_efficiency") || !t.contains("file")) calibration_values(t, scene);
}

void SceneReader::calibration_values(const toml::table& t, Scene& scene) const {
  check_keys(t, {"file", "code_efficiency", "fitted"}, "[calibration]");
  const toml::node* factor = t.get("code_efficiency");
  if (!factor)
    fail(t, "[calibration] has no code_efficiency: set code_efficiency = 1.0 (no calibration)");
  if (!factor->is_number())
    fail(*factor, "'calibration.code_efficiency': expected a number, got " + type_name(*factor));
  scene.code_efficiency = number(*factor);
  if (!(scene.code_efficiency >= 0.1 && scene.code_efficiency <= 100))
    fail(*factor,
         "code_efficiency " + number_text(scene.code_efficiency) +
             " is outside 0.1 .. 100 (cycles of compiled occam per ideal instruction cycle)");
  const toml::node* fitted = t.get("fitted");
  if (!fitted && scene.code_efficiency != 1.0)
    fail(t,
         "[calibration] sets code_efficiency but not `fitted`: say how and on what data it was "
         "fitted");
  scene.calibration_note = fitted ? text(*fitted, "calibration.fitted") : std::string();
}

bool SceneReader::boolean(const toml::table& t, const std::string& key, bool fallback) const {
  const toml::node* node = t.get(key);
  if (!node) return fallback;
  if (!node->is_boolean())
    fail(*node, "'fidelity." + key + "': expected true or false, got " + type_name(*node));
  return *node->value<bool>();
}

// [fidelity]: how much detail to model (t800/fidelity.hpp). Every key is optional; the defaults
// give the finest level's results.
void SceneReader::fidelity(Scene& scene) const {
  const toml::node* node = root_.get("fidelity");
  if (!node) return;
  const toml::table& t = table(*node, "fidelity");
  check_keys(t, {"links", "compute", "compute_cost", "skip_numerics", "reuse_steps"}, "[fidelity]");
  if (const toml::node* links = t.get("links")) {
    const std::string name = text(*links, "fidelity.links");
    const auto parsed = t800::parse_link_fidelity(name);
    if (!parsed)
      fail(*links, "unknown link fidelity '" + name + "'; valid levels are auto, message, packet");
    scene.fidelity.links = *parsed;
  }
  if (const toml::node* compute = t.get("compute")) {
    const std::string name = text(*compute, "fidelity.compute");
    const auto parsed = t800::parse_compute_fidelity(name);
    if (!parsed)
      fail(*compute, "unknown compute fidelity '" + name + "'; valid levels are auto, block, fine");
    scene.fidelity.compute = *parsed;
  }
  if (const toml::node* cost = t.get("compute_cost")) {
    const std::string name = text(*cost, "fidelity.compute_cost");
    const auto parsed = t800::parse_compute_cost(name);
    if (!parsed)
      fail(*cost, "unknown compute cost '" + name +
                      "'; valid are instructions (generated T800 code, timed instruction by "
                      "instruction) and mix (the faster op-count model)");
    scene.fidelity.compute_cost = *parsed;
  }
  scene.fidelity.skip_numerics = boolean(t, "skip_numerics", scene.fidelity.skip_numerics);
  scene.fidelity.reuse_steps = boolean(t, "reuse_steps", scene.fidelity.reuse_steps);
}

// [compiler]: how the occam compiler compiled the program. run_time_checks: its default
// subscript and FPU error checks (true), or the "no run-time error checking" option (false).
void SceneReader::compiler(Scene& scene) const {
  const toml::node* node = root_.get("compiler");
  if (!node) return;
  const toml::table& t = table(*node, "compiler");
  check_keys(t, {"run_time_checks"}, "[compiler]");
  scene.run_time_checks = boolean(t, "run_time_checks", scene.run_time_checks);
}

// [placement]: process = "P1", or group = ["P1", "P2", ...] (one per member) or "P1" (all), or
// "group[2]" = "P3". Whether the processes exist is the program's to say when it is built; whether
// the processors do is checked here.
void SceneReader::placement(Scene& scene) const {
  const toml::node* node = root_.get("placement");
  if (!node) return;
  const toml::table& t = table(*node, "placement");
  for (auto&& [key, value] : t) {
    workloads::PlacementEntry entry{std::string(key.str()), {}, pos(value)};
    auto add = [&](const toml::node& name) {
      if (!name.is_string())
        fail(name, "'placement." + entry.process +
                       "': expected a processor name or an array of them, got " + type_name(name));
      const std::string processor = *name.value<std::string>();
      if (scene.topology.find(processor) < 0)
        fail(name, "placement." + entry.process + ": there is no processor '" + processor +
                       "' in the topology; processors are " + processor_names(scene.topology));
      entry.processors.push_back(processor);
    };
    if (const toml::array* list = value.as_array()) {
      if (list->empty())
        fail(value, "placement." + entry.process + " is empty: give at least one processor");
      for (const toml::node& name : *list) add(name);
    } else {
      add(value);
    }
    scene.placement.push_back(std::move(entry));
  }
}

Scene SceneReader::read() {
  check_keys(root_,
             {"name", "description", "network", "topology", "workload", "placement", "calibration",
              "fidelity", "compiler", "fault"},
             "a scene");
  Scene scene;
  scene.file = file_;
  scene.name = text_or(root_, "name", fs::path(file_).stem().string());
  scene.description = text_or(root_, "description", "");
  const toml::table* net = nullptr;
  if (const toml::node* node = root_.get("network")) net = &table(*node, "network");
  if (net)
    check_keys(*net,
               {"topology", "family", "workers", "link_speed_mbps", "link_protocol", "processor",
                "memory", "wait_states"},
               "[network]");
  scene.topology = topology(net, scene.origins["network"]);
  scene.link = link_config(net, scene.topology);
  workload(scene);
  placement(scene);
  calibration(scene);
  fidelity(scene);
  compiler(scene);
  scene.faults = read_faults(root_.get("fault"), file_, scene.topology);
  return scene;
}

}  // namespace

SourcePos origin_of(const Scene& scene, const std::vector<std::string>& keys) {
  for (const std::string& key : keys)
    if (auto it = scene.origins.find(key); it != scene.origins.end()) return it->second;
  for (const std::string& key : keys)
    if (key.rfind("workload.", 0) == 0 && scene.origins.count("workload"))
      return scene.origins.at("workload");
  return {scene.file, 0, 0};
}

// An override that names the network's source (network.topology, network.family or [topology])
// replaces the scene file's source, so a family scene can be run on a topology file and the other
// way round (`sweep --vary network.topology=a.toml,b.toml`). Keys set by other overrides stay, so
// two overridden sources still clash. A topology file brings its own processors: the file's
// network.workers and network.processor go with the family.
void replace_network_source(toml::table& root, const std::string& key,
                            const std::set<std::string>& overridden) {
  static const std::vector<std::string> sources = {"network.topology", "network.family",
                                                   "topology"};
  if (std::find(sources.begin(), sources.end(), key) == sources.end()) return;
  std::vector<std::string> replaced;
  for (const std::string& other : sources)
    if (other != key) replaced.push_back(other);
  if (key != "network.family") replaced.push_back("network.workers");
  toml::table* net = root["network"].as_table();
  for (const std::string& other : replaced) {
    if (overridden.count(other)) continue;
    if (other == "topology")
      root.erase("topology");
    else if (net)
      net->erase(other.substr(std::string("network.").size()));
  }
}

Scene load_scene(const std::string& path, const std::vector<std::string>& overrides) {
  toml::table root = network::parse_toml_file(path, "scene file");
  std::set<std::string> overridden;
  for (const std::string& text : overrides) {
    const std::string key = apply_override(root, text);
    overridden.insert(key);
    replace_network_source(root, key, overridden);
  }
  return SceneReader(root, path).read();
}

std::string check_file(const std::string& path) {
  const toml::table root = network::parse_toml_file(path, "file");
  // A scene is recognised by any table only a scene has, so a scene missing its [workload] is
  // reported as a scene ("no [workload] table"), not as a topology with unknown keys.
  bool scene_keys = false;
  for (const char* key : {"workload", "network", "topology", "calibration", "fidelity"})
    scene_keys = scene_keys || root.contains(key);
  if (scene_keys) {
    const Scene scene = load_scene(path);
    return "scene " + scene.name + ": " + plural(scene.topology.processors.size(), "processor") +
           ", " + plural(scene.topology.connections.size(), "link") + ", workload " +
           scene.workload_kind;
  }
  const network::Topology t = network::load_topology(path);
  const network::LinkEnd host = *t.host;
  return "topology " + t.name + ": " + plural(t.processors.size(), "processor") + ", " +
         plural(t.connections.size(), "link") + ", host " +
         t.processors[static_cast<std::size_t>(host.processor)].name + ".link" +
         std::to_string(host.link);
}

}  // namespace tools
