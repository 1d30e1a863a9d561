// What the master sends to every worker for one evaluation: the joint-dependent entries of the DH
// matrices A_i, i.e. cos and sin of theta_i = theta0_i + q_i for a revolute joint, d_i = d0_i + q_i
// for a prismatic one. The master computes the sines and cosines once (the paper's rule: avoid
// redundant computation; occam's SIN and COS are software routines) and broadcasts one message;
// every subtask needs only this message and the model's constants. Coriolis terms C_ijk need no q̇:
// the master forms c = Σ C_ijk q̇_j q̇_k itself (assembly.hpp).
#pragma once

#include <array>
#include <memory>
#include <vector>

#include "workloads/dynamics/counted.hpp"
#include "workloads/dynamics/folded.hpp"
#include "workloads/dynamics/robot_model.hpp"
#include "workloads/occam/structure.hpp"

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

// The message's REALs in the order they are sent (cos, sin of each revolute joint; d of each
// prismatic one).
template <class S>
std::vector<S*> message_fields(const RobotModel& model, WorkerInput<S>& input) {
  std::vector<S*> fields;
  for (std::size_t i = 0; i < std::size_t(kJoints); ++i) {
    JointInput<S>& j = input.joints[i];
    if (model.joints[i].type == JointType::revolute) {
      fields.push_back(&j.cos_theta);
      fields.push_back(&j.sin_theta);
    } else {
      fields.push_back(&j.d);
    }
  }
  return fields;
}

// The master's preprocessing, templated on the scalar so that its cost can be counted and its
// code recorded: q is the host's message, the result the message to the workers.
template <class S>
WorkerInput<S> make_worker_input(const RobotModel& model, const std::array<S, kJoints>& q) {
  WorkerInput<S> input;
  occam::declare_each(message_fields(model, input), "message");
  for (int i = 0; i < kJoints; ++i) {
    const Joint& joint = model.joints[static_cast<std::size_t>(i)];
    JointInput<S>& out = input.joints[static_cast<std::size_t>(i)];
    note_loads<S>(1);  // q_i from the host's message
    const Folded<S> qi = Folded<S>::variable(q[static_cast<std::size_t>(i)]);
    if (joint.type == JointType::revolute) {
      const S theta = (qi + Folded<S>::constant(joint.dh.theta)).value();
      out.cos_theta = cosine(theta);
      out.sin_theta = sine(theta);
      note_stores<S>(2);
    } else {
      out.d = (qi + Folded<S>::constant(joint.dh.d)).value();
      note_stores<S>(1);
    }
  }
  return input;
}

// q arrives from the host in the precision of S (rounded to float for REAL32).
template <class S>
WorkerInput<S> make_worker_input(const RobotModel& model, const JointVector& q) {
  std::array<S, kJoints> host;
  for (int i = 0; i < kJoints; ++i) host[static_cast<std::size_t>(i)] = as_scalar<S>(q(i));
  return make_worker_input(model, host);
}

// Op counts of make_worker_input (the master's work per evaluation; independent of q).
OpCounts count_input_ops(const RobotModel& model);
// Its code, recorded: the master's PROC from the host's q to the workers' message.
std::shared_ptr<const t800::codegen::Recording> record_input(const RobotModel& model, bool real64);

}  // namespace dynamics
