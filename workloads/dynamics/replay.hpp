// A subtask's arithmetic traced once and replayed: the host's fast path for what a simulated worker
// computes, for plain float and double (a trajectory's farm evaluates every subtask at every state,
// and the kernel's folding, frame chains and constant look-ups cost far more than its arithmetic).
//
// Why a replay gives the kernel's bits: the operations evaluate_subtask<T> performs on T depend
// only on the model's constants, never on the message (Folded folds by structure, not by value, and
// no kernel compares scalars; folded.hpp). Running it once on Traced<T> records that sequence as a
// graph of additions, subtractions, products and sign changes whose operands are message values,
// model constants rounded to T, or earlier results. Replaying the graph performs the same IEEE
// operations on the same operands, each in the same operand order (so even a NaN from a corrupted
// message propagates as it would), hence the same bits. Three rewrites keep that: an operation on
// two constants is done while tracing (the same T arithmetic, once), an operation repeated on the
// same operands is done once, and operations the result does not use are left out.
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
  // Traces evaluate_subtask<T>(model, task, .).
  SubtaskReplay(const RobotModel& model, const Subtask& task);

  // evaluate_subtask<T>(model, task, input) for the input whose message_fields hold `message` (the
  // fields past its end keep WorkerInput's defaults).
  T operator()(const std::vector<T>& message) const;

  // Operations replayed per evaluation (after the rewrites).
  std::size_t operations() const { return steps_.size(); }

 private:
  enum class Op : std::uint8_t { add, sub, mul, neg };
  struct Step {
    Op op;
    std::uint32_t a, b;  // registers of the operands (b unused by neg)
  };

  static T apply(const Step& step, const T* registers);

  // Registers: the message's REALs (their defaults here), then the constants, then one per step.
  std::vector<T> image_;
  std::size_t message_reals_ = 0;
  std::vector<Step> steps_;
  std::int64_t result_ = -1;  // the result's register; -1: the constant literal_
  T literal_ = T(0);
};

extern template class SubtaskReplay<float>;
extern template class SubtaskReplay<double>;

}  // namespace dynamics
