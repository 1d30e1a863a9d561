// Subtasks' arithmetic traced once and replayed: the host's fast path for what the simulated
// workers compute, for plain float and double (a trajectory's farm evaluates every subtask at every
// state, and the kernels' folding, frame chains and constant look-ups cost far more than their
// arithmetic).
//
// Why a replay gives the kernel's bits: the operations evaluate_subtask<T> performs on T depend
// only on the model's constants, never on the message (Folded folds by structure, not by value, and
// no kernel compares scalars; folded.hpp). Running it once on a tracing scalar records that
// sequence as a graph of additions, subtractions, products and sign changes whose operands are
// message values, model constants rounded to T, or earlier results. Replaying the graph performs
// the same IEEE operations on the same operands, each in the same operand order (so even a NaN from
// a corrupted message propagates as it would), hence the same bits. Three rewrites keep that: an
// operation on two constants is done while tracing (the same T arithmetic, once), an operation
// repeated on the same operands -- within a subtask, or across the subtasks, which build the same
// frame chains -- is done once, and operations no result uses are left out.
//
// Counted and recording scalars never come here: they run the kernels themselves, so operation
// counts, recordings and generated code are untouched.
#pragma once

#include <cstdint>
#include <vector>

#include "workloads/dynamics/robot_model.hpp"
#include "workloads/dynamics/subtask.hpp"

namespace dynamics {

template <class T>
class SubtaskReplay {
 public:
  SubtaskReplay() = default;
  // Traces evaluate_subtask<T>(model, task, .) for each of `tasks`.
  SubtaskReplay(const RobotModel& model, const std::vector<Subtask>& tasks);

  // evaluate_subtask<T>(model, tasks[t], input) for every t, for the input whose message_fields
  // hold `message` (the fields past its end keep WorkerInput's defaults). The values are kept
  // until a message with other bits comes (every worker of a farm gets the same message), so a
  // replay is not to be shared between threads.
  const std::vector<T>& operator()(const std::vector<T>& message) const;

  // Operations replayed per message (after the rewrites).
  std::size_t operations() const { return steps_.size(); }

 private:
  enum class Op : std::uint8_t { add, sub, mul, neg };
  struct Step {
    Op op;
    std::uint32_t a, b;  // registers of the operands (b unused by neg)
  };
  static T apply(const Step& step, const T* registers);
  void run(const std::vector<T>& message) const;

  // Registers: the message's REALs (their defaults here), then the constants, then one per step.
  std::vector<T> image_;
  std::size_t message_reals_ = 0;
  std::vector<Step> steps_;
  std::vector<std::int64_t> results_;  // per task: its value's register; -1: a constant, in values_

  mutable std::vector<T> registers_;
  mutable std::vector<T> message_;  // the message values_ are for
  mutable bool valid_ = false;
  mutable std::vector<T> values_;
};

extern template class SubtaskReplay<float>;
extern template class SubtaskReplay<double>;

}  // namespace dynamics
