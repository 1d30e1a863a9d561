// Running simulations in child processes. SystemC can elaborate and run only once per process, so
// anything that needs several simulations (calibration, the paper tables, sweeps) runs `t800sim run
// ... --json` again as a child and reads its JSON report back.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace tools {

struct ChildOutput {
  int exit_code = -1;  // -1: could not start or killed by a signal
  int status = 0;      // as wait4 gave it (WIFSIGNALED, WTERMSIG, ...)
  std::string out, err;
  double wall_s = 0;    // from just before fork to wait4's return
  long maxrss_kib = 0;  // the child's peak resident memory (rusage)
};

// The path of the running t800sim executable.
std::string self_executable();

// Starts the program argv[0] (a path, not searched in PATH) with stdin from /dev/null, stdout and stderr
// onto the given descriptors and SYSTEMC_DISABLE_COPYRIGHT_MESSAGE=1. The child dies with this process
// (PR_SET_PDEATHSIG): a sweep killed by SIGKILL, which it cannot catch, takes its running points with
// it. Returns the child's pid, or -1 with errno set.
int spawn_child(const std::vector<std::string>& argv, int out_fd, int err_fd);

// Runs `exe` with `args` (no shell involved, SYSTEMC_DISABLE_COPYRIGHT_MESSAGE=1) and captures
// stdout and stderr, its wall time and peak memory.
ChildOutput run_program(const std::string& exe, const std::vector<std::string>& args);
// The same, for this executable.
ChildOutput run_self(const std::vector<std::string>& args);

// `t800sim run SCENE --json --set O...` in a child. Throws std::runtime_error carrying the child's
// error message when it fails (bad input, deadlock, crash).
nlohmann::json run_scene_child(const std::string& scene, const std::vector<std::string>& overrides);

}  // namespace tools
