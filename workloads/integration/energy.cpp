#include "workloads/integration/energy.hpp"

#include <cmath>

#include "workloads/dynamics/assembly.hpp"

namespace integration {

namespace {

using Matrix4 = Eigen::Matrix<long double, 4, 4>;

// A_i = Rz(theta) Tz(d) Tx(a) Rx(alpha), the joint variable added to theta or d.
Matrix4 dh_transform(const dynamics::Joint& joint, long double q) {
  const bool revolute = joint.type == dynamics::JointType::revolute;
  const long double theta = joint.dh.theta + (revolute ? q : 0.0L);
  const long double d = joint.dh.d + (revolute ? 0.0L : q);
  const dynamics::CosSin alpha = dynamics::exact_cos_sin(joint.dh.alpha);
  const long double ct = std::cos(theta), st = std::sin(theta);
  const long double ca = alpha.cos, sa = alpha.sin, a = joint.dh.a;
  Matrix4 t;
  t << ct, -st * ca, st * sa, a * ct,  //
      st, ct * ca, -ct * sa, a * st,   //
      0, sa, ca, d,                    //
      0, 0, 0, 1;
  return t;
}

}  // namespace

Eigen::Matrix<long double, 3, 1> centre_of_mass(const dynamics::RobotModel& model,
                                                const dynamics::JointVector& q, int p) {
  Matrix4 t = Matrix4::Identity();
  for (int i = 0; i <= p; ++i) t = t * dh_transform(model.joints[std::size_t(i)], q(i));
  const Eigen::Vector3d& com = model.joints[std::size_t(p)].link.com;
  Eigen::Matrix<long double, 4, 1> r(com.x(), com.y(), com.z(), 1.0L);
  return (t * r).head<3>();
}

long double potential_energy(const dynamics::RobotModel& model, const dynamics::JointVector& q) {
  const Eigen::Matrix<long double, 3, 1> g = model.gravity.cast<long double>();
  long double v = 0;
  for (int p = 0; p < dynamics::kJoints; ++p)
    v -= model.joints[std::size_t(p)].link.mass * g.dot(centre_of_mass(model, q, p));
  return v;
}

long double kinetic_energy(const dynamics::RobotModel& model,
                           const std::vector<dynamics::Subtask>& subtasks,
                           const dynamics::JointVector& q, const dynamics::JointVector& qd) {
  dynamics::DynamicsData<long double> data;
  dynamics::evaluate_all(model, data, subtasks, q, qd);
  const dynamics::JointVectorT<long double> v = qd.cast<long double>();
  return 0.5L * v.dot(data.D * v);
}

}  // namespace integration
