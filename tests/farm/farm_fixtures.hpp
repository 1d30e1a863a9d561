// Running the dynamics farm in-process (one simulation per test process) and the sequential
// reference.
#pragma once

#include <memory>
#include <string>

#include "network/families.hpp"
#include "tests/test_paths.hpp"
#include "tools/robot_file.hpp"
#include "workloads/params.hpp"
#include "workloads/registry.hpp"
#include "workloads/run/run.hpp"

namespace farm_test {

inline std::shared_ptr<const dynamics::RobotModel> stanford() {
  return std::make_shared<const dynamics::RobotModel>(
      tools::load_robot(test_paths::source_dir() + "/configs/robots/stanford.toml"));
}

// The catalogue's defaults for the farm, with the given settings.
inline workloads::Params farm_params(const std::string& schedule, const std::string& precision,
                                     const std::string& model = "paper",
                                     const std::string& window = "farm") {
  workloads::Params p;
  for (const auto& spec : workloads::find_workload("dynamics-farm")->params)
    p.set(spec.name, spec.default_value);
  p.set("schedule", schedule);
  p.set("precision", precision);
  p.set("model", model);
  p.set("tp_window", window);
  return p;
}

inline workloads::RunReport run_farm(int workers, const workloads::Params& params,
                                     double efficiency = 4.0) {
  workloads::RunInputs in;
  in.name = "farm-test";
  in.topology = network::generate(network::Family::tree, workers, {}, {"test", 0, 0});
  in.options.code_efficiency = efficiency;
  in.options.precision =
      params.text("precision") == "real32" ? t800::Precision::real32 : t800::Precision::real64;
  in.kind = "dynamics-farm";
  in.params = params;
  in.robot = stanford();
  return workloads::run(in);
}

}  // namespace farm_test
