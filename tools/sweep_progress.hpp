// What a running sweep shows on stderr: on a terminal, a progress bar with an ETA that redraws in
// place; otherwise (a log file, CI) one line per finished point, so logs stay readable.
#pragma once

#include <chrono>
#include <cstddef>
#include <string>

#include "tools/sweep_result.hpp"

namespace tools {

class SweepProgress {
 public:
  SweepProgress(std::size_t total, bool terminal);
  void finished(const PointResult& point);  // after each point
  void tick();                              // now and then, to move the clock
  void end();                               // leaves the cursor on a fresh line

  std::size_t failed() const { return failed_; }

 private:
  void draw();
  double elapsed_s() const;

  std::size_t total_, done_ = 0, failed_ = 0;
  bool terminal_;
  std::chrono::steady_clock::time_point start_;
};

// "1:05" or "1:02:05".
std::string clock_text(double seconds);

}  // namespace tools
