#include "workloads/dynamics/link_constants.hpp"

namespace dynamics {

LinkConstants link_constants(const RobotModel& model, int p) {
  const LinkInertia& link = model.joints[static_cast<std::size_t>(p)].link;
  const Eigen::Vector3d& r = link.com;
  LinkConstants k;
  k.mass = link.mass;
  k.first_moment = link.mass * r;
  // Parallel-axis theorem; off-diagonal terms come out exactly 0 where a component of r̄ is 0.
  const Eigen::Matrix3d about_com = link.inertia.asDiagonal();
  k.inertia =
      about_com + link.mass * (r.squaredNorm() * Eigen::Matrix3d::Identity() - r * r.transpose());
  k.second_moment = 0.5 * k.inertia.trace() * Eigen::Matrix3d::Identity() - k.inertia;
  return k;
}

}  // namespace dynamics
