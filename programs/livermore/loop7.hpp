// Livermore loop 7, the "equation of state fragment" of the Livermore Fortran kernels (F. H.
// McMahon, LLNL, 1986), as occam would write it: 16 floating-point operations (8 multiplies, 8
// additions) per element. INMOS published its speed on the T800 (Technical Note 6, "IMS T800
// architecture", 1988): 1.5 MFLOPS on a T800-20, 2.25 on a T800-30 (docs/t800-timing.md).
#pragma once

#include <cstddef>
#include <vector>

#include "workloads/occam/structure.hpp"

namespace livermore {

constexpr int kLoop7FlopsPerElement = 16;

// SEQ k = 0 FOR n
//   x[k] := u[k] + (r * (z[k] + (r * y[k]))) +
//           (t * ((u[k+3] + (r * (u[k+2] + (r * u[k+1])))) +
//                 (t * (u[k+6] + (q * (u[k+5] + (q * u[k+4])))))))
template <class S>
void loop7(std::vector<S>& x, const std::vector<S>& y, const std::vector<S>& z,
           const std::vector<S>& u, const S& r, const S& t, const S& q) {
  for (std::size_t k : occam::seq<S>(x.size()))
    x[k] = u[k] + r * (z[k] + r * y[k]) +
           t * (u[k + 3] + r * (u[k + 2] + r * u[k + 1]) +
                t * (u[k + 6] + q * (u[k + 5] + q * u[k + 4])));
}

// The kernel's inputs for n elements (u has n + 6), values from the benchmark's initialisation
// pattern (any finite values: the timing does not depend on them).
template <class S>
struct Loop7Data {
  std::vector<S> x, y, z, u;
  S r, t, q;
  explicit Loop7Data(std::size_t n)
      : x(n, S(0)), y(n), z(n), u(n + 6), r(S(0.1)), t(S(0.2)), q(S(0.3)) {
    for (std::size_t k = 0; k < n; ++k) {
      y[k] = S(0.001f * float(k + 1));
      z[k] = S(0.002f * float(k + 1));
    }
    for (std::size_t k = 0; k < u.size(); ++k) u[k] = S(0.0005f * float(k + 1));
  }
};

}  // namespace livermore
