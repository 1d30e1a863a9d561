// Shared by the dynamics tests: the Stanford arm from its config file, and the same arm as an
// Orocos KDL chain (the independent reference).
#pragma once

#include <kdl/chain.hpp>
#include <kdl/chaindynparam.hpp>
#include <kdl/jntarray.hpp>
#include <kdl/jntspaceinertiamatrix.hpp>
#include <string>

#include "tests/test_paths.hpp"
#include "tools/robot_file.hpp"
#include "workloads/dynamics/assembly.hpp"

namespace dynamics::testing {

inline std::string stanford_path() {
  return test_paths::source_dir() + "/configs/robots/stanford.toml";
}

inline const RobotModel& stanford() {
  static const RobotModel model = tools::load_robot(stanford_path());
  return model;
}

// D, c, h from KDL for the same model: DH frames as segment tips, inertia about the centre of mass
// in the link frame (KDL::RigidBodyInertia takes the rotational inertia about the cog,
// rigidbodyinertia.hpp).
class KdlArm {
 public:
  explicit KdlArm(const RobotModel& model)
      : chain_(make_chain(model)),
        solver_(chain_, KDL::Vector(model.gravity.x(), model.gravity.y(), model.gravity.z())) {}

  JointMatrix mass(const JointVector& q) {
    KDL::JntSpaceInertiaMatrix m(kJoints);
    solver_.JntToMass(to_kdl(q), m);
    return m.data;
  }
  JointVector coriolis(const JointVector& q, const JointVector& qd) {
    KDL::JntArray c(kJoints);
    solver_.JntToCoriolis(to_kdl(q), to_kdl(qd), c);
    return c.data;
  }
  JointVector gravity(const JointVector& q) {
    KDL::JntArray g(kJoints);
    solver_.JntToGravity(to_kdl(q), g);
    return g.data;
  }
  JointVector qdd(const JointVector& q, const JointVector& qd, const JointVector& tau) {
    return mass(q).ldlt().solve(tau - coriolis(q, qd) - gravity(q));
  }

 private:
  static KDL::Chain make_chain(const RobotModel& model) {
    KDL::Chain chain;
    for (const Joint& joint : model.joints) {
      const bool revolute = joint.type == JointType::revolute;
      const KDL::Joint kdl_joint(revolute ? KDL::Joint::RotZ : KDL::Joint::TransZ);
      // KDL's joint moves the segment root (Rz(q) or Tz(q)); the tip is the constant part of the DH
      // row.
      const KDL::Frame tip = KDL::Frame::DH(joint.dh.a, joint.dh.alpha, joint.dh.d, joint.dh.theta);
      const LinkInertia& link = joint.link;
      const KDL::RigidBodyInertia inertia(
          link.mass, KDL::Vector(link.com.x(), link.com.y(), link.com.z()),
          KDL::RotationalInertia(link.inertia.x(), link.inertia.y(), link.inertia.z(), 0, 0, 0));
      chain.addSegment(KDL::Segment(kdl_joint, tip, inertia));
    }
    return chain;
  }
  static KDL::JntArray to_kdl(const JointVector& v) {
    KDL::JntArray a(kJoints);
    a.data = v;
    return a;
  }

  KDL::Chain chain_;
  KDL::ChainDynParam solver_;
};

// max |a - b| / max |b|: a norm-wise relative error.
template <class A, class B>
double relative_error(const A& a, const B& b) {
  const double scale = b.cwiseAbs().maxCoeff();
  return (a - b).cwiseAbs().maxCoeff() / (scale > 0 ? scale : 1.0);
}

}  // namespace dynamics::testing
