// The master's side: from the workers' subtask values to D, C, c, h, and q̈ by solving D q̈ = τ − c −
// h. Algorithms are free functions over (model, data, ...), Pinocchio style: DynamicsData is the
// workspace and the results; the model is only read.
#pragma once

#include <Eigen/Cholesky>
#include <array>
#include <memory>
#include <vector>

#include "workloads/dynamics/evaluate.hpp"
#include "workloads/dynamics/subtask_set.hpp"

namespace dynamics {

template <class S>
struct DynamicsData {
  using Matrix = Eigen::Matrix<S, kJoints, kJoints>;
  std::vector<S> values;      // one per subtask, in the order of the subtask list
  Matrix D = Matrix::Zero();  // inertia, symmetric
  std::array<Matrix, kJoints> C =
      zeros();  // C[i](j, k) = C_ijk, symmetric in j, k; 0 where no subtask
  JointVectorT<S> c = JointVectorT<S>::Zero();    // Σ_jk C_ijk q̇_j q̇_k
  JointVectorT<S> h = JointVectorT<S>::Zero();    // gravity
  JointVectorT<S> qdd = JointVectorT<S>::Zero();  // the last forward_dynamics result

 private:
  static std::array<Matrix, kJoints> zeros() {
    std::array<Matrix, kJoints> matrices;
    for (Matrix& m : matrices) m.setZero();
    return matrices;
  }
};
using Dynamics = DynamicsData<double>;

// c_i = Σ_j Σ_k C_ijk q̇_j q̇_k from the stored C_ijk (j <= k): Σ_{j<=k} C_ijk w_jk with w_jj = q̇_j²
// and w_jk = 2 q̇_j q̇_k, each w formed once. Templated so that the master's cost can be counted.
template <class S>
std::array<S, kJoints> coriolis_vector(const std::vector<Subtask>& subtasks,
                                       const std::vector<S>& values,
                                       const std::array<S, kJoints>& qd) {
  std::array<Folded<S>, kJoints> rate;
  std::array<bool, kJoints> rate_loaded{};
  std::array<std::array<Folded<S>, kJoints>, kJoints> weight;
  std::array<std::array<bool, kJoints>, kJoints> weight_formed{};
  auto load_rate = [&](int j) {
    const auto sj = static_cast<std::size_t>(j);
    if (!rate_loaded[sj]) {
      note_loads<S>(1);
      rate[sj] = Folded<S>::variable(qd[sj]);
      rate_loaded[sj] = true;
    }
    return rate[sj];
  };
  std::array<Folded<S>, kJoints> c;
  for (std::size_t t = 0; t < subtasks.size(); ++t) {
    const Subtask& task = subtasks[t];
    if (task.kind != TermKind::coriolis) continue;
    const auto sj = static_cast<std::size_t>(task.j), sk = static_cast<std::size_t>(task.k);
    if (!weight_formed[sj][sk]) {
      const Folded<S> qj = load_rate(task.j);
      weight[sj][sk] = task.j == task.k ? qj * qj : (qj + qj) * load_rate(task.k);
      weight_formed[sj][sk] = true;
    }
    note_loads<S>(1);  // the worker's value of C_ijk
    c[static_cast<std::size_t>(task.i)] += Folded<S>::variable(values[t]) * weight[sj][sk];
  }
  std::array<S, kJoints> result;
  occam::declare(result, "c");
  for (std::size_t i = 0; i < result.size(); ++i) result[i] = c[i].value();
  note_stores<S>(kJoints);
  return result;
}

// The master's operations in coriolis_vector for this subtask list, and its code.
OpCounts count_assembly_ops(const std::vector<Subtask>& subtasks);
std::shared_ptr<const t800::codegen::Recording> record_assembly(
    const std::vector<Subtask>& subtasks, bool real64);

// data.values (one per subtask) -> data.D, data.C, data.c, data.h.
template <class S>
void assemble(const std::vector<Subtask>& subtasks, const JointVector& qd, DynamicsData<S>& data) {
  data.D.setZero();
  for (auto& matrix : data.C) matrix.setZero();
  data.h.setZero();
  for (std::size_t t = 0; t < subtasks.size(); ++t) {
    const Subtask& task = subtasks[t];
    const S value = data.values[t];
    switch (task.kind) {
      case TermKind::inertia:
        data.D(task.i, task.j) = data.D(task.j, task.i) = value;
        break;
      case TermKind::coriolis:
        data.C[static_cast<std::size_t>(task.i)](task.j, task.k) = value;
        data.C[static_cast<std::size_t>(task.i)](task.k, task.j) = value;
        break;
      case TermKind::gravity:
        data.h(task.i) = value;
        break;
    }
  }
  std::array<S, kJoints> rates;
  for (int j = 0; j < kJoints; ++j) rates[static_cast<std::size_t>(j)] = as_scalar<S>(qd(j));
  const std::array<S, kJoints> c = coriolis_vector(subtasks, data.values, rates);
  for (int i = 0; i < kJoints; ++i) data.c(i) = c[static_cast<std::size_t>(i)];
}

// Every subtask evaluated as the farm would (one master message, one kernel per subtask), then
// assembled.
template <class S>
void evaluate_all(const RobotModel& model, DynamicsData<S>& data,
                  const std::vector<Subtask>& subtasks, const JointVector& q,
                  const JointVector& qd) {
  const WorkerInput<S> input = make_worker_input<S>(model, q);
  data.values.clear();
  for (const Subtask& task : subtasks) data.values.push_back(evaluate_subtask(model, task, input));
  assemble(subtasks, qd, data);
}

Dynamics evaluate_all(const RobotModel& model, const std::vector<Subtask>& subtasks,
                      const JointVector& q, const JointVector& qd);

// q̈ = D⁻¹(τ − c − h) by LDLT (the sequential reference; the paper's Gaussian elimination is
// elsewhere).
template <class S>
const JointVectorT<S>& forward_dynamics(const RobotModel& model, DynamicsData<S>& data,
                                        const std::vector<Subtask>& subtasks, const JointVector& q,
                                        const JointVector& qd, const JointVector& tau) {
  evaluate_all(model, data, subtasks, q, qd);
  const JointVectorT<S> rhs = tau.cast<S>() - data.c - data.h;
  data.qdd = data.D.ldlt().solve(rhs);
  return data.qdd;
}

JointVector forward_dynamics(const RobotModel& model, const std::vector<Subtask>& subtasks,
                             const JointVector& q, const JointVector& qd, const JointVector& tau);

// Convenience: derives the variant's subtasks first (an analysis of ~10 ms; in a loop, derive once
// and use the overload above).
JointVector forward_dynamics(const RobotModel& model, ModelVariant variant, const JointVector& q,
                             const JointVector& qd, const JointVector& tau);

}  // namespace dynamics
