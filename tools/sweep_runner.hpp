// Runs commands as child processes, a few at a time, capturing what each prints. Sweeps run every
// point in its own process because SystemC elaborates one simulation per process (docs/architecture.md).
#pragma once

#include <cstddef>
#include <functional>
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

// Runs every command (argv[0] is a path, not searched in PATH), stdin from /dev/null; returns when
// all have ended. A command that cannot be started ends with exit code 127 and the reason in `err`.
void run_children(const std::vector<std::vector<std::string>>& commands, const ChildPool& pool);

}  // namespace tools
