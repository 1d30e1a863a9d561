// Fixed-step integrators for q̈ = f(q, q̇), templated on the scalar (float = REAL32 state and
// arithmetic, double = REAL64): the classical fourth-order Runge-Kutta method (the paper's "e.g.
// Runge Kutta"; four evaluations of the dynamics per step) and semi-implicit (symplectic) Euler,
// four times cheaper: q̇ first, then q with the new q̇ (first order; for a separable Hamiltonian
// its energy error stays bounded instead of drifting).
#pragma once

#include <optional>
#include <string_view>

#include "workloads/dynamics/robot_model.hpp"

namespace integration {

template <class S>
struct State {
  dynamics::JointVectorT<S> q = dynamics::JointVectorT<S>::Zero();
  dynamics::JointVectorT<S> qd = dynamics::JointVectorT<S>::Zero();
};

enum class Method { rk4, semi_implicit_euler };
const char* to_string(Method method);
std::optional<Method> parse_method(std::string_view text);  // "rk4" | "semi-implicit-euler"
int evaluations_per_step(Method method);
// When each evaluation of a step happens, as a fraction of the step from its start, in the order
// the steps below call f: RK4 0, ½, ½, 1; semi-implicit Euler 0. A time-dependent input (a torque
// table) is read at these times.
inline const double* stage_offsets(Method method) {
  static constexpr double rk4[] = {0.0, 0.5, 0.5, 1.0};
  static constexpr double euler[] = {0.0};
  return method == Method::rk4 ? rk4 : euler;
}

// One RK4 step of (q, q̇)' = (q̇, f(q, q̇)).
template <class S, class Accel>
State<S> rk4_step(const State<S>& x, S h, Accel&& f) {
  using V = dynamics::JointVectorT<S>;
  const S half = h / S(2);
  const V a1 = f(x.q, x.qd);
  const V q2 = x.q + half * x.qd, v2 = x.qd + half * a1;
  const V a2 = f(q2, v2);
  const V q3 = x.q + half * v2, v3 = x.qd + half * a2;
  const V a3 = f(q3, v3);
  const V q4 = x.q + h * v3, v4 = x.qd + h * a3;
  const V a4 = f(q4, v4);
  const S sixth = h / S(6);
  State<S> next;
  next.q = x.q + sixth * (x.qd + S(2) * v2 + S(2) * v3 + v4);
  next.qd = x.qd + sixth * (a1 + S(2) * a2 + S(2) * a3 + a4);
  return next;
}

template <class S, class Accel>
State<S> semi_implicit_euler_step(const State<S>& x, S h, Accel&& f) {
  State<S> next;
  next.qd = x.qd + h * f(x.q, x.qd);
  next.q = x.q + h * next.qd;
  return next;
}

template <class S, class Accel>
State<S> step(Method method, const State<S>& x, S h, Accel&& f) {
  return method == Method::rk4 ? rk4_step(x, h, f) : semi_implicit_euler_step(x, h, f);
}

}  // namespace integration
