// A state of the arm, and configurations drawn inside the joint limits (for the structural-zero
// analysis and the tests).
#pragma once

#include <random>

#include "workloads/dynamics/robot_model.hpp"

namespace dynamics {

struct State {
  JointVector q = JointVector::Zero();   // rad or m
  JointVector qd = JointVector::Zero();  // rad/s or m/s
};

// Uniform in each joint's limits.
JointVector random_configuration(const RobotModel& model, std::mt19937_64& rng);

// The middle of each joint's range.
JointVector mid_configuration(const RobotModel& model);

}  // namespace dynamics
