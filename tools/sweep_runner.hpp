// Runs commands as child processes, a few at a time, capturing what each prints. Sweeps run every
// point in its own process because SystemC elaborates one simulation per process (docs/architecture.md).
#pragma once

#include <cstddef>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

namespace tools {

// How one child ended.
struct ChildOutcome {
  int exit_code = -1;      // when it exited; -1 otherwise
  int signal = 0;          // the signal that ended it, or 0
  bool timed_out = false;  // killed by us after the time limit
  std::string out, err;    // its standard output and error
  double wall_s = 0;
};

struct ChildPool {
  int parallel = 1;      // how many children at a time (at least 1)
  double timeout_s = 0;  // per child; 0 = no limit
  // Called as each child ends (in order of ending), with its index in `commands`.
  std::function<void(std::size_t, const ChildOutcome&)> done;
  // Called about four times a second while children run (to refresh a progress bar); may be empty.
  std::function<void()> tick;
};

// Thrown by run_children when SIGINT, SIGTERM or SIGHUP arrived while it ran: the running children
// were killed and reaped first (and `done` was not called for them), so nothing outlives the sweep.
struct Interrupted : std::runtime_error {
  explicit Interrupted(int signal);
  int signal;
};

// Runs every command (argv[0] is a path, not searched in PATH), stdin from /dev/null; returns when
// all have ended. A command that cannot be started ends with exit code 127 and the reason in `err`.
// Children die with this process, even by SIGKILL (spawn_child); throws Interrupted.
void run_children(const std::vector<std::vector<std::string>>& commands, const ChildPool& pool);

}  // namespace tools
