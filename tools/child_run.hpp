// Running simulations in child processes. SystemC can elaborate and run only once per process, so anything
// that needs several simulations (calibration, the paper tables, sweeps) runs `t800sim run ... --json` again
// as a child and reads its JSON report back.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace tools {

struct ChildOutput {
  int exit_code = -1;  // -1: could not start or killed by a signal
  std::string out, err;
};

// The path of the running t800sim executable.
std::string self_executable();

// Runs this executable with `args` (no shell involved) and captures stdout and stderr.
ChildOutput run_self(const std::vector<std::string>& args);

// `t800sim run SCENE --json --set O...` in a child. Throws std::runtime_error carrying the child's error
// message when it fails (bad input, deadlock, crash).
nlohmann::json run_scene_child(const std::string& scene, const std::vector<std::string>& overrides);

}  // namespace tools
