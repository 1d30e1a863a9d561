#include "workloads/dynamics/worker_input.hpp"

namespace dynamics {

int worker_input_reals(const RobotModel& model) {
  int reals = 0;
  for (const Joint& joint : model.joints) reals += joint.type == JointType::revolute ? 2 : 1;
  return reals;
}

OpCounts count_input_ops(const RobotModel& model) {
  const JointVector q = JointVector::Constant(0.25);
  OpTally tally;
  make_worker_input<Counted<double>>(model, q);
  return tally.counts();
}

// The host's q is an array of the master's; sin and cos of each joint angle go into the message.
std::shared_ptr<const t800::codegen::Recording> record_input(const RobotModel& model, bool real64) {
  auto recording = std::make_shared<t800::codegen::Recording>("MASTER.INPUT", real64);
  const t800::codegen::RecordingScope scope(*recording);
  auto run = [&](auto scalar) {
    using S = decltype(scalar);
    std::array<S, kJoints> q;
    q.fill(S(0.25));
    occam::declare(q, "q");
    make_worker_input(model, q);
  };
  if (real64)
    run(Counted<double>());
  else
    run(Counted<float>());
  return recording;
}

}  // namespace dynamics
