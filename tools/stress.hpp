// `t800sim stress`: how far the paper's numerics can be trusted.
//  (a) the arm's D at many states over the joint space (a fifth of the joints near a limit):
//      condition numbers, pivot growth, forward and backward error of simple interchange and
//      partial pivoting in REAL32 and REAL64, against a long double reference;
//  (b) random 6 x 6 matrices with prescribed condition numbers (SPD and nonsymmetric), and
//      well-conditioned matrices whose elimination meets a tiny non-zero pivot: where the paper's
//      strategy fails, and whether the failure is detected;
//  (c) a passive trajectory (τ = 0, no friction): total-energy drift of RK4 and semi-implicit
//      Euler in REAL64 and REAL32.
// Every figure in the README's "Gaussian elimination and numerical stability" comes from here.
#pragma once

#include <cstdint>
#include <string>

#include "workloads/run/result_value.hpp"

namespace tools {

struct StressOptions {
  bool quick = false;  // fewer states and matrices, 1 s of trajectory instead of 10
  int states = 0;      // arm states; 0 = 100000 (5000 with quick)
  std::uint64_t seed = 1;
  std::string robot = "configs/robots/stanford.toml";
};

// The whole report as a value tree (JSON keys: README, "Gaussian elimination and numerical
// stability"). Throws std::runtime_error when the robot file cannot be found.
workloads::ResultValue run_stress(const StressOptions& options);

// The summary tables of a report, as text.
std::string stress_summary(const workloads::ResultValue& report);

}  // namespace tools
