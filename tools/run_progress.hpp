// What a long `t800sim run` shows on stderr while it simulates. On a terminal, one line redrawn a
// few times a second: steps done of all, elapsed time and the time left at the pace so far.
// Otherwise (a log, a sweep's child) nothing, except one line stating the expected length when a
// run turns out to be long (over a minute, judged after five seconds), so that a log says what to
// wait for.
#pragma once

#include <chrono>
#include <cstdint>

namespace tools {

class RunProgress {
 public:
  explicit RunProgress(bool terminal);
  ~RunProgress() { end(); }
  RunProgress(const RunProgress&) = delete;
  RunProgress& operator=(const RunProgress&) = delete;

  void update(std::int64_t done, std::int64_t total);
  void end();  // clears the line, for what is printed next

 private:
  bool terminal_;
  bool drawn_ = false, stated_ = false;
  std::chrono::steady_clock::time_point start_, last_draw_;
};

}  // namespace tools
