#include "tools/run_inputs.hpp"

#include <filesystem>

#include "tools/robot_file.hpp"

namespace tools {

workloads::RunInputs inputs_from(const Scene& scene, bool keep_intervals) {
  workloads::RunInputs in;
  in.name = scene.name;
  in.topology = scene.topology;
  in.options.link = scene.link;
  in.options.code_efficiency = scene.code_efficiency;
  in.options.keep_intervals = keep_intervals;
  // Workloads that compute declare their arithmetic precision; the scene loader has validated the choice.
  if (scene.workload.has("precision"))
    in.options.precision = *t800::parse_precision(scene.workload.text("precision"));
  in.kind = scene.workload_kind;
  in.params = scene.workload;
  // A robot file is named relative to the scene that names it, like the scene's topology file.
  if (scene.workload.has("robot")) {
    const std::filesystem::path robot = scene.workload.text("robot");
    const std::filesystem::path resolved =
        robot.is_absolute() ? robot : std::filesystem::path(scene.file).parent_path() / robot;
    in.robot = std::make_shared<const dynamics::RobotModel>(load_robot(resolved.string()));
  }
  return in;
}

}  // namespace tools
