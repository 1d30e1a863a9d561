// What one simulation models and what it may skip (issue 6): the link and compute levels of
// t800/fidelity.hpp, and the skips workloads may take. Every report states it.
#pragma once

#include "t800/fidelity.hpp"

namespace network {

struct Fidelity {
  t800::LinkFidelity links = t800::LinkFidelity::automatic;
  t800::ComputeFidelity compute = t800::ComputeFidelity::automatic;
  // Compute costed from generated T800 code (instructions) or by operation mixes (mix).
  t800::ComputeCost compute_cost = t800::ComputeCost::instructions;
  // Timing only: a workload whose schedule cannot depend on the data leaves out computing the
  // numbers (its report then has no numeric results). Workloads where the data can change the
  // schedule (row interchanges) still compute what decides it.
  bool skip_numerics = false;
  // A trajectory may reuse the simulated timing of a step proven identical to one it simulated.
  bool reuse_steps = true;
};

}  // namespace network
