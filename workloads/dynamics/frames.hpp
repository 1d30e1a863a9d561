// DH frames as a worker builds them: the transforms ^{i-1}T_p = A_i A_{i+1} ... A_p from the
// master's message, and Paul's differential rotation δ and translation d of frame p caused by
// joint i, read off ^{i-1}T_p (R. P. Paul, Robot Manipulators, 1981, ch. 4; the paper's eqs. 2-9).
#pragma once

#include <algorithm>
#include <array>
#include <initializer_list>

#include "workloads/dynamics/folded.hpp"
#include "workloads/dynamics/robot_model.hpp"
#include "workloads/dynamics/vec3.hpp"
#include "workloads/dynamics/worker_input.hpp"

namespace dynamics {

// The entries of A_p a kernel works with: the joint-dependent ones from the master's message
// (loaded once per kernel), the others model constants (a load each time a step uses one, unless 0
// or +-1).
template <class S>
class DhEntries {
 public:
  DhEntries() = default;
  DhEntries(const Joint& joint, const JointInput<S>& in) : joint_(&joint) {
    if (revolute()) {
      note_loads<S>(2);
      cos_theta_ = Folded<S>::variable(in.cos_theta);
      sin_theta_ = Folded<S>::variable(in.sin_theta);
    } else {
      note_loads<S>(1);
      d_ = Folded<S>::variable(in.d);
    }
  }

  JointType type() const { return joint_->type; }
  bool revolute() const { return joint_->type == JointType::revolute; }

  Folded<S> cos_theta() const {
    return revolute() ? cos_theta_ : Folded<S>::constant(exact_cos_sin(joint_->dh.theta).cos);
  }
  Folded<S> sin_theta() const {
    return revolute() ? sin_theta_ : Folded<S>::constant(exact_cos_sin(joint_->dh.theta).sin);
  }
  Folded<S> d() const { return revolute() ? Folded<S>::constant(joint_->dh.d) : d_; }
  Folded<S> a() const { return Folded<S>::constant(joint_->dh.a); }
  Folded<S> cos_alpha() const { return Folded<S>::constant(exact_cos_sin(joint_->dh.alpha).cos); }
  Folded<S> sin_alpha() const { return Folded<S>::constant(exact_cos_sin(joint_->dh.alpha).sin); }

 private:
  const Joint* joint_ = nullptr;
  Folded<S> cos_theta_, sin_theta_, d_;
};

template <class S>
using DhTable = std::array<DhEntries<S>, kJoints>;

// The DH entries of joints first..kJoints-1 (the loads of their message values are counted here).
template <class S>
DhTable<S> load_dh_entries(const RobotModel& model, const WorkerInput<S>& input, int first) {
  DhTable<S> table;
  for (int p = first; p < kJoints; ++p) {
    const auto sp = static_cast<std::size_t>(p);
    table[sp] = DhEntries<S>(model.joints[sp], input.joints[sp]);
  }
  return table;
}

// A homogeneous transform [n o a p] (the columns of the rotation, and the translation).
template <class S>
struct Frame {
  Vec3<Folded<S>> n, o, a, p;
};

template <class S>
Frame<S> identity_frame() {
  const Folded<S> one = Folded<S>::constant(1.0);
  Frame<S> f;
  f.n[0] = one;
  f.o[1] = one;
  f.a[2] = one;
  return f;
}

// T A_p with A_p = Rz(theta) Tz(d) Tx(a) Rx(alpha), applied factor by factor: the way to multiply
// by a DH matrix without touching its structural zeros.
template <class S>
Frame<S> append(const Frame<S>& t, const DhEntries<S>& e) {
  const Folded<S> c = e.cos_theta(), s = e.sin_theta(), d = e.d(), a = e.a();
  const Folded<S> ca = e.cos_alpha(), sa = e.sin_alpha();
  Frame<S> r;
  r.n = c * t.n + s * t.o;  // Rz(theta)
  const Vec3<Folded<S>> o = c * t.o + -(s * t.n);
  r.p = t.p + d * t.a + a * r.n;  // Tz(d), then Tx(a) along the new x axis
  r.o = ca * o + sa * t.a;        // Rx(alpha)
  r.a = ca * t.a + -(sa * o);
  return r;
}

// Differential motion of frame p for a unit rate of joint i, in frame p's axes, from ^{i-1}T_p.
template <class S>
struct Differential {
  Vec3<Folded<S>> delta;  // rotation δ
  Vec3<Folded<S>> d;      // translation of the origin
};

template <class S>
Differential<S> differential(const Frame<S>& t, JointType type) {
  const Vec3<Folded<S>> z_axis{{t.n[2], t.o[2], t.a[2]}};  // z_{i-1} in frame p
  if (type == JointType::prismatic) return {Vec3<Folded<S>>{}, z_axis};
  // Revolute: the origin moves by z_{i-1} x p, i.e. (-n_x p_y + n_y p_x, ...) in frame p.
  auto moment = [&t](const Vec3<Folded<S>>& axis) { return axis[1] * t.p[0] - axis[0] * t.p[1]; };
  return {z_axis, {{moment(t.n), moment(t.o), moment(t.a)}}};
}

// The distinct joints a subtask differentiates by (D_ii needs one chain, not two).
struct JointSet {
  std::array<int, 3> joints{};
  int count = 0;

  static JointSet of(std::initializer_list<int> list) {
    JointSet set;
    for (int joint : list) {
      if (set.index_of(joint) < 0) set.joints[static_cast<std::size_t>(set.count++)] = joint;
    }
    return set;
  }
  int index_of(int joint) const {
    for (int c = 0; c < count; ++c) {
      if (joints[static_cast<std::size_t>(c)] == joint) return c;
    }
    return -1;
  }
};

template <class S>
using Differentials = std::array<Differential<S>, 3>;

// Walks the chains ^{i-1}T_p of the set's joints link by link (each chain starts at its own joint)
// and, for every link p >= the largest joint, calls visit(p, differentials) with the differentials
// of frame p, indexed like the set.
template <class S, class Visit>
void for_each_link(const DhTable<S>& dh, const JointSet& set, Visit visit) {
  const auto begin = set.joints.begin();
  const auto end = begin + set.count;
  const int first = *std::min_element(begin, end);
  const int last = *std::max_element(begin, end);
  std::array<Frame<S>, 3> chain;
  for (auto& frame : chain) frame = identity_frame<S>();
  for (int p = first; p < kJoints; ++p) {
    for (int c = 0; c < set.count; ++c) {
      const auto sc = static_cast<std::size_t>(c);
      if (p >= set.joints[sc]) chain[sc] = append(chain[sc], dh[static_cast<std::size_t>(p)]);
    }
    if (p < last) continue;  // links below the largest joint do not enter the subtask
    Differentials<S> diffs;
    for (int c = 0; c < set.count; ++c) {
      const auto sc = static_cast<std::size_t>(c);
      diffs[sc] = differential(chain[sc], dh[static_cast<std::size_t>(set.joints[sc])].type());
    }
    visit(p, diffs);
  }
}

}  // namespace dynamics
