// The linear systems the elimination solves: the arm's D q̈ = τ − (C + h) at a state, or a random
// system from a seed; in any scalar type.
#pragma once

#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "workloads/dynamics/assembly.hpp"
#include "workloads/elimination/gauss.hpp"

namespace elimination {

template <class S>
struct LinearSystem {
  Rows<S> a;
  Row<S> b;
  std::size_t size() const { return a.size(); }
};

// Rounds every value to S (through double: every system here starts life in double or lower).
template <class S, class T>
LinearSystem<S> convert(const LinearSystem<T>& in) {
  LinearSystem<S> out;
  for (const Row<T>& row : in.a) {
    Row<S> r;
    for (const T& v : row) r.push_back(S(static_cast<dynamics::plain_scalar_t<S>>(value_of(v))));
    out.a.push_back(std::move(r));
  }
  for (const T& v : in.b) out.b.push_back(S(static_cast<dynamics::plain_scalar_t<S>>(value_of(v))));
  return out;
}

template <class S, class Derived, class VDerived>
LinearSystem<S> from_eigen(const Eigen::MatrixBase<Derived>& a,
                           const Eigen::MatrixBase<VDerived>& b) {
  LinearSystem<S> out;
  out.a.reserve(std::size_t(a.rows()));
  out.b.reserve(std::size_t(a.rows()));
  for (Eigen::Index i = 0; i < a.rows(); ++i) {
    Row<S> r;
    r.reserve(std::size_t(a.cols()));
    for (Eigen::Index j = 0; j < a.cols(); ++j)
      r.push_back(S(static_cast<dynamics::plain_scalar_t<S>>(a(i, j))));
    out.a.push_back(std::move(r));
    out.b.push_back(S(static_cast<dynamics::plain_scalar_t<S>>(b(i))));
  }
  return out;
}

// D and τ − c − h computed in S (REAL32 dynamics for a REAL32 pipeline, as the farm's master
// would hand them over).
template <class S>
LinearSystem<S> dynamics_system(const dynamics::DynamicsData<S>& data,
                                const dynamics::JointVector& tau) {
  const dynamics::JointVectorT<S> rhs = tau.cast<S>() - data.c - data.h;
  return from_eigen<S>(data.D, rhs);
}

template <class S>
LinearSystem<S> dynamics_system(const dynamics::RobotModel& model,
                                const std::vector<dynamics::Subtask>& subtasks,
                                const dynamics::JointVector& q, const dynamics::JointVector& qd,
                                const dynamics::JointVector& tau) {
  dynamics::DynamicsData<S> data;
  dynamics::evaluate_all(model, data, subtasks, q, qd);
  return dynamics_system(data, tau);
}

// A random n x n system: entries uniform in [-1, 1] from the seed (mt19937_64).
LinearSystem<double> random_system(int n, std::uint64_t seed);

}  // namespace elimination
