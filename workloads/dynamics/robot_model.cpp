#include "workloads/dynamics/robot_model.hpp"

#include <cmath>

namespace dynamics {

const char* to_string(JointType type) {
  return type == JointType::revolute ? "revolute" : "prismatic";
}

bool within_limits(const RobotModel& model, const JointVector& q) {
  for (int i = 0; i < kJoints; ++i) {
    const JointLimits& limits = model.joints[static_cast<std::size_t>(i)].limits;
    if (!(q(i) >= limits.min && q(i) <= limits.max)) return false;  // NaN is outside
  }
  return true;
}

CosSin exact_cos_sin(double angle) {
  const double quarter_turns = angle / (M_PI / 2);
  const double nearest = std::round(quarter_turns);
  if (std::abs(quarter_turns - nearest) > 1e-12) return {std::cos(angle), std::sin(angle)};
  // angle = n * 90 deg: the unit circle's axis points, n mod 4 = 0, 1, 2, 3.
  static constexpr CosSin kAxis[] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};
  const long n = static_cast<long>(nearest);
  return kAxis[((n % 4) + 4) % 4];
}

}  // namespace dynamics
