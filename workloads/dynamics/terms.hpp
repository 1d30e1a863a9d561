// The three kinds of dynamics terms as kernels templated on the scalar type, in Paul's
// differential-transformation form: every term is a sum over links p of products of the
// differentials (δ, d) of frame p (frames.hpp) with the link's constants (link_constants.hpp).
//
// With Δ_i = [[δ_i×], d_i; 0 0] (U_pi = T_p Δ_i) and the pseudo-inertia J_p = ∫ x xᵀ dm of link p:
//   D_ij  = Σ_p Tr(Δ_j J_p Δ_iᵀ) = Σ_p ∫ (δ_j×r + d_j)·(δ_i×r + d_i) dm
//         = Σ_p m d_i·d_j + m r̄·(d_i×δ_j + d_j×δ_i) + δ_iᵀ I_o δ_j                      (Paul)
//   C_ijk = Σ_p Tr(U_pjk J_p U_piᵀ), p >= max(i, j, k), with U_pjk = T_p Δ_j Δ_k for j <= k (the
//           mixed second derivative, so C_ijk = C_ikj); expanding Δ_j Δ_k x = δ_j×(δ_k×r + d_k):
//         = Σ_p δ_jᵀ P_o (δ_k×δ_i) + (δ_j·m r̄)(δ_k·d_i) − (δ_j·δ_k)(m r̄·d_i)
//               + (δ_j×d_k)·(δ_i×m r̄ + m d_i)
//           Exact, and equal to the Christoffel symbol ½(∂D_ij/∂q_k + ∂D_ik/∂q_j − ∂D_jk/∂q_i)
//           (checked in the tests). It uses the same differentials as D_ij: a C subtask is a D
//           subtask with one more chain, and no derivative of D is ever formed.
//   h_i   = −Σ_p m_p gᵀ U_pi r̄_p = −Σ_p g_p·(δ_i×m r̄ + m d_i), g_p = gravity in frame p,
//           carried from frame 0 with the transposed rotations of the A's.
// Joint indices are 0-based here; i <= j for D and j <= k for C.
#pragma once

#include "workloads/dynamics/frames.hpp"
#include "workloads/dynamics/link_constants.hpp"

namespace dynamics {

namespace detail {

template <class S>
Vec3<Folded<S>> constant_vector(const Eigen::Vector3d& v) {
  return {{Folded<S>::constant(v.x()), Folded<S>::constant(v.y()), Folded<S>::constant(v.z())}};
}

// xᵀ M y for a symmetric constant M, from its six distinct entries.
template <class S>
Folded<S> bilinear(const Eigen::Matrix3d& m, const Vec3<Folded<S>>& x, const Vec3<Folded<S>>& y) {
  auto k = [&m](int r, int c) { return Folded<S>::constant(m(r, c)); };
  return k(0, 0) * (x[0] * y[0]) + k(1, 1) * (x[1] * y[1]) + k(2, 2) * (x[2] * y[2]) +
         k(0, 1) * (x[0] * y[1] + x[1] * y[0]) + k(0, 2) * (x[0] * y[2] + x[2] * y[0]) +
         k(1, 2) * (x[1] * y[2] + x[2] * y[1]);
}

// xᵀ M x for a symmetric constant M (off-diagonal entries doubled in the constants).
template <class S>
Folded<S> quadratic(const Eigen::Matrix3d& m, const Vec3<Folded<S>>& x) {
  auto k = [&m](int r, int c) { return Folded<S>::constant(r == c ? m(r, c) : 2 * m(r, c)); };
  return k(0, 0) * (x[0] * x[0]) + k(1, 1) * (x[1] * x[1]) + k(2, 2) * (x[2] * x[2]) +
         k(0, 1) * (x[0] * x[1]) + k(0, 2) * (x[0] * x[2]) + k(1, 2) * (x[1] * x[2]);
}

// Rᵀ g for the rotation of A_p = Rz(theta) Rx(alpha): gravity in frame p+1 from gravity in frame p.
template <class S>
Vec3<Folded<S>> rotate_back(const Vec3<Folded<S>>& g, const DhEntries<S>& e) {
  const Folded<S> c = e.cos_theta(), s = e.sin_theta(), ca = e.cos_alpha(), sa = e.sin_alpha();
  const Folded<S> x = c * g[0] + s * g[1];
  const Folded<S> y = c * g[1] - s * g[0];
  return {{x, ca * y + sa * g[2], ca * g[2] - sa * y}};
}

// Link p's contribution to D_ij.
template <class S>
Folded<S> inertia_link_term(const LinkConstants& k, const Differential<S>& di,
                            const Differential<S>& dj, bool same_joint) {
  const Folded<S> m = Folded<S>::constant(k.mass);
  if (same_joint) {
    return m * dot(di.d, di.d) +
           dot(constant_vector<S>(2 * k.first_moment), cross(di.d, di.delta)) +
           quadratic(k.inertia, di.delta);
  }
  const Vec3<Folded<S>> mr = constant_vector<S>(k.first_moment);
  return m * dot(di.d, dj.d) + dot(mr, cross(di.d, dj.delta) + cross(dj.d, di.delta)) +
         bilinear(k.inertia, di.delta, dj.delta);
}

// Link p's contribution to C_ijk (j <= k).
template <class S>
Folded<S> coriolis_link_term(const LinkConstants& k, const Differential<S>& di,
                             const Differential<S>& dj, const Differential<S>& dk) {
  const Folded<S> m = Folded<S>::constant(k.mass);
  const Vec3<Folded<S>> mr = constant_vector<S>(k.first_moment);
  const Folded<S> rotation = bilinear(k.second_moment, dj.delta, cross(dk.delta, di.delta));
  const Folded<S> first_moment =
      dot(dj.delta, mr) * dot(dk.delta, di.d) - dot(dj.delta, dk.delta) * dot(mr, di.d);
  const Folded<S> translation = dot(cross(dj.delta, dk.d), cross(di.delta, mr) + m * di.d);
  return rotation + first_moment + translation;
}

}  // namespace detail

template <class S>
Folded<S> inertia_term(const RobotModel& model, const WorkerInput<S>& input, int i, int j) {
  const auto dh = load_dh_entries(model, input, std::min(i, j));
  const JointSet set = JointSet::of({i, j});
  Folded<S> sum;
  for_each_link<S>(dh, set, [&](int p, const Differentials<S>& diffs) {
    sum += detail::inertia_link_term(link_constants(model, p), diffs[set.index_of(i)],
                                     diffs[set.index_of(j)], i == j);
  });
  return sum;
}

template <class S>
Folded<S> coriolis_term(const RobotModel& model, const WorkerInput<S>& input, int i, int j, int k) {
  const auto dh = load_dh_entries(model, input, std::min({i, j, k}));
  const JointSet set = JointSet::of({i, j, k});
  Folded<S> sum;
  for_each_link<S>(dh, set, [&](int p, const Differentials<S>& diffs) {
    sum += detail::coriolis_link_term(link_constants(model, p), diffs[set.index_of(i)],
                                      diffs[set.index_of(j)], diffs[set.index_of(k)]);
  });
  return sum;
}

template <class S>
Folded<S> gravity_term(const RobotModel& model, const WorkerInput<S>& input, int i) {
  const auto dh = load_dh_entries(model, input, 0);  // gravity is carried from frame 0
  Vec3<Folded<S>> g = detail::constant_vector<S>(model.gravity);
  for (int p = 0; p < i; ++p) g = detail::rotate_back(g, dh[static_cast<std::size_t>(p)]);
  Folded<S> sum;
  for_each_link<S>(dh, JointSet::of({i}), [&](int p, const Differentials<S>& diffs) {
    g = detail::rotate_back(g, dh[static_cast<std::size_t>(p)]);  // now in frame p
    const LinkConstants k = link_constants(model, p);
    const Differential<S>& di = diffs[0];
    sum += dot(g, cross(di.delta, detail::constant_vector<S>(k.first_moment)) +
                      Folded<S>::constant(k.mass) * di.d);
  });
  return -sum;
}

}  // namespace dynamics
