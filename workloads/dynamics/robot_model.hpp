// The robot model: a serial arm described by standard Denavit-Hartenberg rows and per-link inertial
// data. Like Pinocchio's Model it is a description only; algorithms read it and never modify it.
// Workspaces and results live elsewhere (DynamicsData). Loading from a file is a tool's job
// (tools/robot_file.hpp).
#pragma once

#include <Eigen/Core>
#include <array>
#include <string>

namespace dynamics {

// The processor farm reproduces a six-joint arm (the Stanford arm); fixed-size types throughout.
constexpr int kJoints = 6;

template <class S>
using JointVectorT = Eigen::Matrix<S, kJoints, 1>;
using JointVector = JointVectorT<double>;
using JointMatrix = Eigen::Matrix<double, kJoints, kJoints>;

enum class JointType { revolute, prismatic };

// Standard DH: A_i = Rz(theta) Tz(d) Tx(a) Rx(alpha), lengths in m, angles in rad. The joint
// variable q_i adds to theta (revolute) or to d (prismatic); the row holds the constant part (the
// offset).
struct DhRow {
  double a = 0;
  double alpha = 0;
  double d = 0;
  double theta = 0;
};

// Inertial data of the link moved by a joint, in that link's DH frame i.
struct LinkInertia {
  double mass = 0;  // kg
  // Centre of mass r̄ in frame i, m.
  Eigen::Vector3d com = Eigen::Vector3d::Zero();
  // (Ixx, Iyy, Izz) about the centre of mass, kg m^2; products of inertia are zero.
  Eigen::Vector3d inertia = Eigen::Vector3d::Zero();
};

// Range of the joint variable: rad (revolute) or m (prismatic); min <= max.
struct JointLimits {
  double min = 0;
  double max = 0;
};

struct Joint {
  JointType type = JointType::revolute;
  DhRow dh;
  LinkInertia link;
  JointLimits limits;
};

struct RobotModel {
  std::string name;
  std::array<Joint, kJoints> joints;
  Eigen::Vector3d gravity = Eigen::Vector3d(0, 0, -9.81);  // m/s^2 in frame 0
};

const char* to_string(JointType type);

// True when every q_i lies within its joint's limits.
bool within_limits(const RobotModel& model, const JointVector& q);

// cos and sin of a constant DH angle, exact (0, +-1) at multiples of 90 degrees: twist angles of
// real arms are such multiples, and std::cos(-pi/2) = 6e-17 would hide a structural zero.
struct CosSin {
  double cos = 1;
  double sin = 0;
};
CosSin exact_cos_sin(double angle);

}  // namespace dynamics
