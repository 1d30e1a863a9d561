#include "tools/sweep_progress.hpp"

#include <cmath>
#include <iostream>

#include <fmt/format.h>

namespace tools {

namespace {
constexpr int kBarWidth = 30;
}

std::string clock_text(double seconds) {
  const long s = std::lround(std::max(0.0, seconds));
  if (s >= 3600) return fmt::format("{}:{:02}:{:02}", s / 3600, s / 60 % 60, s % 60);
  return fmt::format("{}:{:02}", s / 60, s % 60);
}

SweepProgress::SweepProgress(std::size_t total, bool terminal)
    : total_(total), terminal_(terminal), start_(std::chrono::steady_clock::now()) {
  if (terminal_) draw();
}

double SweepProgress::elapsed_s() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

void SweepProgress::finished(const PointResult& p) {
  ++done_;
  if (!p.ok()) ++failed_;
  const std::string tp = std::isnan(p.tp_us) ? "" : fmt::format("  Tp {:.3f} us", p.tp_us);
  const std::string line = fmt::format("[{}/{}] {}  {}{}  {:.2f} s", done_, total_,
                                       point_text(p.params), p.status, tp, p.wall_s);
  if (!terminal_) {
    std::cerr << line << "\n";
    return;
  }
  // On a terminal only failures get a line of their own (above the bar); successes just move the
  // bar.
  if (!p.ok()) std::cerr << "\r\033[K" << line << "\n";
  draw();
}

void SweepProgress::tick() {
  if (terminal_) draw();
}

void SweepProgress::draw() {
  const double fraction = total_ ? double(done_) / double(total_) : 1.0;
  const int filled = int(fraction * kBarWidth);
  const double elapsed = elapsed_s();
  // Points finish at the pace seen so far (with -j N, N at a time), so the rest takes as long per
  // point.
  const std::string eta =
      done_ ? "ETA " + clock_text(elapsed / double(done_) * double(total_ - done_))
            : std::string("ETA --:--");
  const std::string failures = failed_ ? fmt::format(", {} failed", failed_) : std::string();
  std::cerr << fmt::format("\r\033[K[{}{}] {}/{}{}  {}  {}", std::string(filled, '#'),
                           std::string(kBarWidth - filled, '.'), done_, total_, failures,
                           clock_text(elapsed), eta)
            << std::flush;
}

void SweepProgress::end() {
  if (terminal_) std::cerr << "\n";
}

}  // namespace tools
