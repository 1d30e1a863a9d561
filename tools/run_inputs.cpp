#include "tools/run_inputs.hpp"

#include <algorithm>
#include <filesystem>

#include "tools/robot_file.hpp"
#include "workloads/run/output_file.hpp"
#include "workloads/run/workload.hpp"
#include "workloads/setting_error.hpp"

namespace tools {

namespace {

void load_robot_of(const Scene& scene, const std::filesystem::path& resolved,
                   workloads::RunInputs& in) {
  try {
    in.robot = std::make_shared<const dynamics::RobotModel>(load_robot(resolved.string()));
  } catch (const network::ConfigError& e) {
    if (e.where().line > 0) throw;  // an error inside the robot file already says where
    throw network::ConfigError(e.where(), e.message() + " (workload.robot = \"" +
                                              scene.workload.text("robot") +
                                              "\", relative to the scene file " + scene.file + ")");
  }
}

// Makes the workload as run() will, without a machine: its constructor checks the settings against
// the network and each other.
void check_workload(const Scene& scene, const workloads::RunInputs& in) {
  try {
    workloads::make_workload(in.kind,
                             workloads::WorkloadContext{in.params, in.topology, in.robot.get()});
  } catch (const workloads::SettingError& e) {
    throw network::ConfigError(origin_of(scene, e.keys()), e.what());
  }
}

}  // namespace

workloads::RunInputs inputs_from(const Scene& scene, bool keep_intervals) {
  workloads::RunInputs in;
  in.name = scene.name;
  in.topology = scene.topology;
  in.options.link = scene.link;
  in.options.code_efficiency = scene.code_efficiency;
  in.options.keep_intervals = keep_intervals;
  in.options.fidelity = scene.fidelity;
  in.options.checked = scene.run_time_checks;
  // Workloads that compute declare their arithmetic precision; the scene loader has validated the
  // choice. The report says where the precision came from, above all when nobody chose it.
  const auto& defaults = scene.workload_defaults;
  if (scene.workload.has("precision")) {
    in.options.precision = *t800::parse_precision(scene.workload.text("precision"));
    in.precision_source = std::find(defaults.begin(), defaults.end(), "precision") == defaults.end()
                              ? "workload.precision"
                              : "the default of workload " + scene.workload_kind +
                                    "; set workload.precision to choose";
  } else {
    in.precision_source =
        "the simulator's default; workload " + scene.workload_kind + " declares no precision";
  }
  in.faults = scene.faults;
  in.kind = scene.workload_kind;
  in.params = scene.workload;
  in.placement = scene.placement;
  // Files a workload names (robot, torque table, trajectory output) are relative to the scene that
  // names them, like the scene's topology file.
  const auto relative_to_scene = [&](const std::string& name) {
    const std::filesystem::path path = scene.workload.text(name);
    return path.is_absolute() ? path : std::filesystem::path(scene.file).parent_path() / path;
  };
  for (const char* file : {"torque_csv", "output_csv"})
    if (scene.workload.has(file) && !scene.workload.text(file).empty())
      in.params.set(file, relative_to_scene(file).string());
  if (scene.workload.has("robot")) load_robot_of(scene, relative_to_scene("robot"), in);
  check_workload(scene, in);
  if (in.params.has("output_csv")) {
    try {
      workloads::check_output_path(in.params.text("output_csv"), "workload.output_csv =");
    } catch (const std::invalid_argument& e) {
      throw network::ConfigError(origin_of(scene, {"workload.output_csv"}), e.what());
    }
  }
  return in;
}

std::string check_input(const std::string& path) {
  const std::string summary = check_file(path);
  if (summary.rfind("scene ", 0) == 0) inputs_from(load_scene(path));
  return summary;
}

}  // namespace tools
