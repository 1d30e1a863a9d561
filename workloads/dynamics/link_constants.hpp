// Per-link constants the kernels use, derived from the model once per kernel (not counted: an occam
// program has them as literals, like Paul's tables of pseudo-inertia terms). All about the origin
// of the link's DH frame, in that frame's axes.
#pragma once

#include <Eigen/Core>

#include "workloads/dynamics/robot_model.hpp"

namespace dynamics {

struct LinkConstants {
  double mass = 0;  // m
  // m r̄
  Eigen::Vector3d first_moment = Eigen::Vector3d::Zero();
  // I_o = I_c + m (|r̄|² E − r̄ r̄ᵀ), the inertia tensor about the frame's origin
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();
  // P_o = ∫ r rᵀ dm = ½ tr(I_o) E − I_o, the 3x3 block of the pseudo-inertia matrix J
  Eigen::Matrix3d second_moment = Eigen::Matrix3d::Zero();
};

// Constants of the link moved by joint p (0-based).
LinkConstants link_constants(const RobotModel& model, int p);

}  // namespace dynamics
