// Many terms at one configuration, for the zero analysis (subtask_set.hpp), which evaluates every
// term of the arm at dozens of configurations while a farm is set up. A worker's kernel builds the
// chains ^{i-1}T_p of its own joints (frames.hpp); a chain depends only on its joint, so here each
// of the six is built once and shared by every term. The arithmetic on each chain and each link's
// contribution is the kernel's, in the kernel's order: every value, and its structure, is bit for
// bit what evaluate_term gives (tests/dynamics/term_sweep_test.cpp).
#pragma once

#include <vector>

#include "workloads/dynamics/folded.hpp"
#include "workloads/dynamics/robot_model.hpp"
#include "workloads/dynamics/subtask.hpp"
#include "workloads/dynamics/worker_input.hpp"

namespace dynamics {

// evaluate_term(model, terms[t], input) for every t.
std::vector<Folded<double>> evaluate_terms(const RobotModel& model,
                                           const std::vector<Subtask>& terms,
                                           const WorkerInput<double>& input);

}  // namespace dynamics
