#include "workloads/pipeline/levels/report.hpp"

#include <algorithm>

namespace workloads::levels {

using elimination::Status;

void Report::begin_round() {
  outcome = PipelineOutcome();
  largest_ = 0;
  first_unstable_ = -1;
}

void Report::fail(int step, Status status, const std::string& what) {
  if (!outcome.failure.empty()) return;
  outcome.status = status;
  outcome.failed_step = step;
  outcome.failure = what;
}

void Report::rows_seen(long double largest) {
  largest_ = std::max(largest_, largest);
}

void Report::level2(double now_us, bool first) {
  if (!first) {
    outcome.level2_last_us = std::max(outcome.level2_last_us, now_us);
    return;
  }
  if (outcome.level2_first_us < 0 || now_us < outcome.level2_first_us)
    outcome.level2_first_us = now_us;
}

const std::vector<double>& Report::solved(const std::vector<double>& x, bool finite, bool unstable,
                                          int steps) {
  // Overlap: L3 saw a non-finite value and the pipeline drained.
  if (outcome.status == Status::non_finite) return outcome.qdd;
  if (!finite) {
    fail(steps, Status::non_finite, "level 4: back substitution overflowed");
    return outcome.qdd;
  }
  outcome.qdd = x;
  if (input_scale_ > 0 && largest_ > input_scale_)
    outcome.growth = static_cast<double>(largest_ / input_scale_);
  if (unstable)
    fail(first_unstable_, Status::unstable,
         "level 3: pivot growth above the limit from step " + std::to_string(first_unstable_));
  return outcome.qdd;
}

}  // namespace workloads::levels
