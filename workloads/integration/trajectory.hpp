// A passive trajectory (τ = 0, no friction) integrated with the paper's chain: the dynamics
// (D, c, h) and Gaussian elimination for q̈, in REAL32 or REAL64, watched through its total energy.
#pragma once

#include <string>
#include <vector>

#include "workloads/dynamics/robot_model.hpp"
#include "workloads/dynamics/subtask.hpp"
#include "workloads/elimination/gauss.hpp"
#include "workloads/integration/integrators.hpp"

namespace integration {

struct PassiveSettings {
  Method method = Method::rk4;
  bool real64 = true;
  double dt = 1e-3;  // s
  int steps = 10000;
  int energy_every = 1;  // steps between energy samples
  elimination::PivotRule rule;
  dynamics::JointVector q0 = dynamics::JointVector::Zero();
  dynamics::JointVector qd0 = dynamics::JointVector::Zero();
};

struct PassiveResult {
  double e0 = 0;             // J, at t = 0
  double max_abs_drift = 0;  // max |E(t) - E(0)| over the samples, J
  double final_drift = 0;    // E(T) - E(0), J
  double max_kinetic = 0;  // max ½ q̇ᵀDq̇ over the samples: the energy scale of the motion, J
  int steps_done = 0;
  int limit_exits = 0;             // samples outside the joint limits (reported, never clamped)
  double first_limit_exit_s = -1;  // time of the first such sample; -1 if none
  std::string failure;             // non-empty when the solver failed and the run stopped
  dynamics::JointVector q_end = dynamics::JointVector::Zero();
  double relative_drift() const { return max_kinetic > 0 ? max_abs_drift / max_kinetic : 0; }
};

// `subtasks` select the dynamics model for q̈ (the full model conserves energy; the paper's drops
// Coriolis terms and need not); the energy is always measured with the exact potential and D.
PassiveResult run_passive(const dynamics::RobotModel& model,
                          const std::vector<dynamics::Subtask>& subtasks,
                          const PassiveSettings& settings);

}  // namespace integration
