// What the master sends to every worker for one evaluation: the joint-dependent entries of the DH
// matrices A_i, i.e. cos and sin of theta_i = theta0_i + q_i for a revolute joint, d_i = d0_i + q_i
// for a prismatic one. The master computes the sines and cosines once (the paper's rule: avoid
// redundant computation; occam's SIN and COS are software routines) and broadcasts one message;
// every subtask needs only this message and the model's constants. Coriolis terms C_ijk need no q̇:
// the master forms c = Σ C_ijk q̇_j q̇_k itself (assembly.hpp).
#pragma once

#include <array>

#include "workloads/dynamics/counted.hpp"
#include "workloads/dynamics/folded.hpp"
#include "workloads/dynamics/robot_model.hpp"

namespace dynamics {

template <class S>
struct JointInput {
  S cos_theta = S(1);  // revolute joints only
  S sin_theta = S(0);  // revolute joints only
  S d = S(0);          // prismatic joints only
};

template <class S>
struct WorkerInput {
  std::array<JointInput<S>, kJoints> joints;
};

// REAL values in the message (2 per revolute joint, 1 per prismatic: 11 for the Stanford arm).
int worker_input_reals(const RobotModel& model);

// The master's preprocessing, templated on the scalar so that its cost can be counted. q arrives
// from the host in the precision of S (rounded to float for REAL32).
template <class S>
WorkerInput<S> make_worker_input(const RobotModel& model, const JointVector& q) {
  WorkerInput<S> input;
  for (int i = 0; i < kJoints; ++i) {
    const Joint& joint = model.joints[static_cast<std::size_t>(i)];
    JointInput<S>& out = input.joints[static_cast<std::size_t>(i)];
    note_loads<S>(1);  // q_i from the host's message
    if (joint.type == JointType::revolute) {
      const S theta =
          (Folded<S>::variable(as_scalar<S>(q(i))) + Folded<S>::constant(joint.dh.theta)).value();
      out.cos_theta = cosine(theta);
      out.sin_theta = sine(theta);
      note_stores<S>(2);
    } else {
      out.d = (Folded<S>::variable(as_scalar<S>(q(i))) + Folded<S>::constant(joint.dh.d)).value();
      note_stores<S>(1);
    }
  }
  return input;
}

// Op counts of make_worker_input (the master's work per evaluation; independent of q).
OpCounts count_input_ops(const RobotModel& model);

}  // namespace dynamics
