#include "workloads/dynamics/state.hpp"

namespace dynamics {

JointVector random_configuration(const RobotModel& model, std::mt19937_64& rng) {
  JointVector q;
  for (int i = 0; i < kJoints; ++i) {
    const JointLimits& limits = model.joints[static_cast<std::size_t>(i)].limits;
    q(i) = std::uniform_real_distribution<double>(limits.min, limits.max)(rng);
  }
  return q;
}

JointVector mid_configuration(const RobotModel& model) {
  JointVector q;
  for (int i = 0; i < kJoints; ++i) {
    const JointLimits& limits = model.joints[static_cast<std::size_t>(i)].limits;
    q(i) = 0.5 * (limits.min + limits.max);
  }
  return q;
}

}  // namespace dynamics
