// What one round of the pipeline reports (PipelineOutcome), as the levels see it happen: each level
// writes its own observations here and none reads another's, so the levels stay processes that
// share nothing but channels. The diagnostics that need two levels' figures (the growth: L1's input
// against the largest element L3 saw) are combined here, not by a level.
#pragma once

#include <string>
#include <vector>

#include "workloads/elimination/gauss.hpp"
#include "workloads/pipeline/pipeline_program.hpp"

namespace workloads::levels {

class Report {
 public:
  PipelineOutcome outcome;

  // The client starts a round.
  void begin_round();
  // The first failure of a round is the one reported.
  void fail(int step, elimination::Status status, const std::string& what);
  // L1: the largest element of the system it got.
  void input_scale(long double scale) { input_scale_ = scale; }
  // L3: the largest element of a step's rows; the first step whose growth check failed.
  void rows_seen(long double largest);
  void unstable_from(int step) { first_unstable_ = step; }
  // Level 2's window: the first pivot row reaching a level-2 processor, the last row leaving one.
  void level2(double now_us, bool first);
  // L4: the solution, and whether L3 flagged the growth on its way; returns q̈ as recorded (empty
  // when the round failed).
  const std::vector<double>& solved(const std::vector<double>& x, bool finite, bool unstable,
                                    int steps);

 private:
  long double input_scale_ = 0;  // max |a_ij| of the input (diagnostic)
  long double largest_ = 0;      // max |a(k)_ij| seen by L3 (diagnostic)
  int first_unstable_ = -1;
};

}  // namespace workloads::levels
