// A 3-vector of any scalar (here Folded<S>), with the few operations the kernels need. Not an Eigen
// type on purpose: every operation is spelt out, so the order of the arithmetic (and its count) is
// exactly what reads here, the same for every scalar type.
#pragma once

#include <array>

namespace dynamics {

template <class F>
struct Vec3 {
  std::array<F, 3> e{};

  F& operator[](int i) { return e[static_cast<std::size_t>(i)]; }
  const F& operator[](int i) const { return e[static_cast<std::size_t>(i)]; }
};

template <class F>
Vec3<F> operator+(const Vec3<F>& a, const Vec3<F>& b) {
  return {{a[0] + b[0], a[1] + b[1], a[2] + b[2]}};
}

template <class F>
Vec3<F> operator-(const Vec3<F>& a) {
  return {{-a[0], -a[1], -a[2]}};
}

template <class F>
Vec3<F> operator*(const F& s, const Vec3<F>& a) {
  return {{s * a[0], s * a[1], s * a[2]}};
}

template <class F>
F dot(const Vec3<F>& a, const Vec3<F>& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

template <class F>
Vec3<F> cross(const Vec3<F>& a, const Vec3<F>& b) {
  return {{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}};
}

}  // namespace dynamics
