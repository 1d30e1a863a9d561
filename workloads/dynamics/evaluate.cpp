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

std::shared_ptr<const t800::codegen::Recording> record_subtask(const RobotModel& model,
                                                               const Subtask& task, bool real64) {
  auto recording = std::make_shared<t800::codegen::Recording>(task.name, real64);
  auto run = [&](auto scalar) {
    using S = decltype(scalar);
    WorkerInput<S> input = make_worker_input<S>(model, mid_configuration(model));  // the master's
    const t800::codegen::RecordingScope scope(*recording);
    occam::declare_each(message_fields(model, input), "message");
    std::array<S, 1> result;
    occam::declare(result, "result");
    result[0] = evaluate_term(model, task, input).value();
  };
  if (real64)
    run(Counted<double>());
  else
    run(Counted<float>());
  return recording;
}

}  // namespace dynamics
