#include "workloads/dynamics/assembly.hpp"

namespace dynamics {

OpCounts count_assembly_ops(const std::vector<Subtask>& subtasks) {
  const std::vector<Counted<double>> values(subtasks.size(), Counted<double>(0.5));
  std::array<Counted<double>, kJoints> qd;
  qd.fill(Counted<double>(0.25));
  OpTally tally;
  coriolis_vector(subtasks, values, qd);
  return tally.counts();
}

// The workers' values arrive in one array, q-dot in another; c is the master's.
std::shared_ptr<const t800::codegen::Recording> record_assembly(
    const std::vector<Subtask>& subtasks, bool real64) {
  auto recording = std::make_shared<t800::codegen::Recording>("MASTER.ASSEMBLE", real64);
  const t800::codegen::RecordingScope scope(*recording);
  auto run = [&](auto scalar) {
    using S = decltype(scalar);
    std::vector<S> values(subtasks.size(), S(0.5));
    std::array<S, kJoints> qd;
    qd.fill(S(0.25));
    occam::declare(values, "values");
    occam::declare(qd, "qdot");
    coriolis_vector(subtasks, values, qd);
  };
  if (real64)
    run(Counted<double>());
  else
    run(Counted<float>());
  return recording;
}

Dynamics evaluate_all(const RobotModel& model, const std::vector<Subtask>& subtasks,
                      const JointVector& q, const JointVector& qd) {
  Dynamics data;
  evaluate_all(model, data, subtasks, q, qd);
  return data;
}

JointVector forward_dynamics(const RobotModel& model, const std::vector<Subtask>& subtasks,
                             const JointVector& q, const JointVector& qd, const JointVector& tau) {
  Dynamics data;
  return forward_dynamics(model, data, subtasks, q, qd, tau);
}

JointVector forward_dynamics(const RobotModel& model, ModelVariant variant, const JointVector& q,
                             const JointVector& qd, const JointVector& tau) {
  return forward_dynamics(model, derive_subtasks(model, variant), q, qd, tau);
}

}  // namespace dynamics
