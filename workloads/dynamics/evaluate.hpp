// Evaluating one subtask: exactly the code one worker runs, on the master's message
// (worker_input.hpp).
#pragma once

#include <memory>

#include "workloads/dynamics/state.hpp"
#include "workloads/dynamics/subtask.hpp"
#include "workloads/dynamics/terms.hpp"

namespace dynamics {

// The term of a subtask with its structure: kind() == zero when the term is zero for the model's
// constants alone, whatever the configuration.
template <class S>
Folded<S> evaluate_term(const RobotModel& model, const Subtask& task, const WorkerInput<S>& input) {
  switch (task.kind) {
    case TermKind::inertia:
      return inertia_term(model, input, task.i, task.j);
    case TermKind::coriolis:
      return coriolis_term(model, input, task.i, task.j, task.k);
    case TermKind::gravity:
      return gravity_term(model, input, task.i);
  }
  return Folded<S>();
}

// The worker's code for one subtask; its single result is stored (counted as one fstore).
template <class S>
S evaluate_subtask(const RobotModel& model, const Subtask& task, const WorkerInput<S>& input) {
  const S value = evaluate_term(model, task, input).value();
  note_stores<S>(1);
  return value;
}

// One subtask at a configuration, the master's preprocessing included (uncounted unless S counts).
template <class S = double>
S evaluate(const RobotModel& model, const Subtask& task, const JointVector& q) {
  return evaluate_subtask(model, task, make_worker_input<S>(model, q));
}

template <class S = double>
S evaluate(const RobotModel& model, const Subtask& task, const State& state) {
  return evaluate<S>(model, task, state.q);
}

// The operations of evaluate_subtask for this subtask (the worker's cost; the master's
// preprocessing is count_input_ops). They do not depend on the configuration; the overload with q
// is there to show it.
OpCounts count_ops(const RobotModel& model, const Subtask& task);
OpCounts count_ops(const RobotModel& model, const Subtask& task, const JointVector& q);

// The worker's PROC for this subtask, recorded: it reads the master's message and stores its value.
std::shared_ptr<const t800::codegen::Recording> record_subtask(const RobotModel& model,
                                                               const Subtask& task, bool real64);

}  // namespace dynamics
