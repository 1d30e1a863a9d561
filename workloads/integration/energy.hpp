// The arm's total energy, to watch a passive trajectory with: kinetic ½ q̇ᵀ D(q) q̇ and potential
// V(q) = −Σ_p m_p gᵀ (T_p r̄_p), the height of every link's centre of mass in the gravity field.
// This V is the one the dynamics' gravity term derives from: h_i = −Σ_{p≥i} m_p gᵀ U_pi r̄_p
// = ∂V/∂q_i with U_pi = ∂T_p/∂q_i (Paul, Robot Manipulators, 1981, ch. 6), so with τ = 0 and no friction E = T + V is
// conserved by the exact motion (the tests check ∂V/∂q = h by finite differences). Evaluated in
// long double so that the measurement does not add to the drift it measures.
#pragma once

#include <vector>

#include "workloads/dynamics/robot_model.hpp"
#include "workloads/dynamics/subtask.hpp"

namespace integration {

// Position of link p's centre of mass in frame 0 (p = 0 .. kJoints-1).
Eigen::Matrix<long double, 3, 1> centre_of_mass(const dynamics::RobotModel& model,
                                                const dynamics::JointVector& q, int p);

long double potential_energy(const dynamics::RobotModel& model, const dynamics::JointVector& q);

// ½ q̇ᵀ D q̇, with D from the subtasks (its D terms; the paper and full models share them).
long double kinetic_energy(const dynamics::RobotModel& model,
                           const std::vector<dynamics::Subtask>& subtasks,
                           const dynamics::JointVector& q, const dynamics::JointVector& qd);

}  // namespace integration
