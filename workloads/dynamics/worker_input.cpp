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

}  // namespace dynamics
