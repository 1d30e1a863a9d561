#include "tools/run_inputs.hpp"

#include <algorithm>
#include <filesystem>

#include "network/input_file.hpp"
#include "tools/robot_file.hpp"
#include "workloads/registry.hpp"
#include "workloads/run/output_file.hpp"
#include "workloads/run/run.hpp"
#include "workloads/run/workload.hpp"
#include "workloads/setting_error.hpp"

namespace tools {

namespace {

void load_robot_of(const Scene& scene, const std::string& key, const std::string& path,
                   workloads::RunInputs& in) {
  try {
    in.robot = std::make_shared<const dynamics::RobotModel>(load_robot(path));
  } catch (const network::ConfigError& e) {
    if (e.where().line > 0) throw;  // an error inside the robot file already says where
    throw network::ConfigError(origin_of(scene, {key}), e.message() + " (" + key + ")");
  }
}

// Makes the workload as run() will, without a machine: its constructor checks the settings against
// the network and each other.
void check_workload(const Scene& scene, const workloads::RunInputs& in) {
  at_scene_keys(scene, [&] {
    workloads::make_workload(in.kind,
                             workloads::WorkloadContext{in.params, in.topology, in.robot.get()});
  });
}

// Files to read must be there now, not after the simulation.
void check_files(const Scene& scene, const workloads::WorkloadInfo& info,
                 const workloads::Params& params) {
  for (const workloads::ParamSpec& p : info.params) {
    if (p.type != workloads::ParamType::input_file || params.text(p.name).empty()) continue;
    const std::string& name = params.text(p.name);
    std::error_code ec;
    if (!std::filesystem::exists(name, ec))
      throw network::ConfigError(origin_of(scene, {"workload." + p.name}),
                                 "workload." + p.name + ": no such file " + name +
                                     " (names are relative to the scene file)");
    if (const std::string problem = network::not_regular_file(name); !problem.empty())
      throw network::ConfigError(origin_of(scene, {"workload." + p.name}),
                                 "workload." + p.name + ": " + name + ": " + problem);
  }
}

// Workloads that compute declare their arithmetic precision; the report says where the precision
// came from, above all when nobody chose it.
void precision_of(const Scene& scene, const workloads::WorkloadInfo& info,
                  workloads::RunInputs& in) {
  const workloads::ParamSpec* p = find_of_type(info, workloads::ParamType::precision);
  if (!p) {
    in.precision_source =
        "the simulator's default; workload " + scene.workload_kind + " declares no precision";
    return;
  }
  in.options.precision = *t800::parse_precision(scene.workload.text(p->name));
  const auto& defaults = scene.workload_defaults;
  const bool chosen = std::find(defaults.begin(), defaults.end(), p->name) == defaults.end();
  in.precision_source = chosen ? "workload." + p->name
                               : "the default of workload " + scene.workload_kind +
                                     "; set workload." + p->name + " to choose";
}

}  // namespace

void at_scene_keys(const Scene& scene, const std::function<void()>& code) {
  try {
    code();
  } catch (const workloads::SettingError& e) {
    throw network::ConfigError(origin_of(scene, e.keys()), e.what());
  }
}

workloads::RunInputs inputs_from(const Scene& scene) {
  workloads::RunInputs in;
  in.name = scene.name;
  in.topology = scene.topology;
  in.options.link = scene.link;
  in.options.code_efficiency = scene.code_efficiency;
  in.options.fidelity = scene.fidelity;
  in.options.checked = scene.run_time_checks;
  in.faults = scene.faults;
  in.kind = scene.workload_kind;
  in.params = scene.workload;
  in.placement = scene.placement;
  // tools/ knows the parameters' types, never a workload's parameter names: the scene loader has
  // validated each value and resolved file names against the scene.
  const workloads::WorkloadInfo& info = *workloads::find_workload(scene.workload_kind);
  precision_of(scene, info, in);
  if (const workloads::ParamSpec* robot = find_of_type(info, workloads::ParamType::robot_file);
      robot && !in.params.text(robot->name).empty())
    load_robot_of(scene, "workload." + robot->name, in.params.text(robot->name), in);
  check_files(scene, info, in.params);
  check_workload(scene, in);
  for (const workloads::ParamSpec& p : info.params)
    if (p.type == workloads::ParamType::output_file) {
      const std::string key = "workload." + p.name;
      try {
        workloads::check_output_path(in.params.text(p.name), key + " =");
      } catch (const std::invalid_argument& e) {
        throw network::ConfigError(origin_of(scene, {key}), e.what());
      }
    }
  return in;
}

std::string check_input(const std::string& path) {
  const std::string summary = check_file(path);
  if (summary.rfind("scene ", 0) != 0) return summary;
  const Scene scene = load_scene(path);
  const workloads::RunInputs inputs = inputs_from(scene);
  // Realised as run() realises it, short of simulating: what the program's build(), its placement
  // and its channels' routes refuse is refused here too.
  at_scene_keys(scene, [&] { workloads::realise(inputs); });
  return summary;
}

}  // namespace tools
