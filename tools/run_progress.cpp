#include "tools/run_progress.hpp"

#include <iostream>

#include <fmt/format.h>

#include "tools/sweep_progress.hpp"

namespace tools {

namespace {
constexpr double kRedrawS = 0.25, kJudgeAfterS = 5, kLongS = 60;
}

RunProgress::RunProgress(bool terminal)
    : terminal_(terminal), start_(std::chrono::steady_clock::now()), last_draw_(start_) {}

void RunProgress::end() {
  if (drawn_) std::cerr << "\r\033[K" << std::flush;
  drawn_ = false;
}

void RunProgress::update(std::int64_t done, std::int64_t total) {
  const auto now = std::chrono::steady_clock::now();
  if (std::chrono::duration<double>(now - last_draw_).count() < kRedrawS || done <= 0) return;
  last_draw_ = now;
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  const double expected = elapsed / double(done) * double(total);
  if (terminal_) {
    std::cerr << fmt::format("\r\033[Kstep {} of {} ({:.1f} %)  {}  about {} left", done, total,
                             100.0 * double(done) / double(total), clock_text(elapsed),
                             clock_text(expected - elapsed))
              << std::flush;
    drawn_ = true;
  } else if (!stated_ && elapsed >= kJudgeAfterS && expected >= kLongS) {
    std::cerr << fmt::format(
        "run: a long run: step {} of {} after {}; expected to take about {} in all\n", done, total,
        clock_text(elapsed), clock_text(expected));
    stated_ = true;
  }
}

}  // namespace tools
