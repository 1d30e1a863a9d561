#include "workloads/dynamics/evaluate.hpp"

namespace dynamics {

OpCounts count_ops(const RobotModel& model, const Subtask& task, const JointVector& q) {
  const WorkerInput<Counted<double>> input = make_worker_input<Counted<double>>(model, q);
  OpTally tally;  // opened after the master's part
  evaluate_subtask(model, task, input);
  return tally.counts();
}

OpCounts count_ops(const RobotModel& model, const Subtask& task) {
  return count_ops(model, task, mid_configuration(model));
}

}  // namespace dynamics
