// The systolic cell's arithmetic: one block step C := C + A.B of b x b blocks, as occam would write
// it, templated on the scalar (float for the sequential reference, t800sim::Real32 or Real64 when
// recorded as a kernel). Each element's sum runs over the inner index in order, so block by block,
// in order of the blocks, it adds exactly the terms a plain triple loop adds, in the same order.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "workloads/occam/structure.hpp"

namespace systolic {

// SEQ r = 0 FOR b
//   SEQ s = 0 FOR b
//     SEQ l = 0 FOR b
//       c[(r*b)+s] := c[(r*b)+s] + (a[(r*b)+l] * bb[(l*b)+s])
template <class S>
void multiply_add(std::vector<S>& c, const std::vector<S>& a, const std::vector<S>& b,
                  std::size_t n) {
  for (std::size_t r : occam::seq<S>(n))
    for (std::size_t s : occam::seq<S>(n))
      for (std::size_t l : occam::seq<S>(n))
        c[r * n + s] = c[r * n + s] + a[r * n + l] * b[l * n + s];
}

// The matrices' elements: a fixed pseudo-random sequence in [-1, 1) (a 32-bit linear congruential
// generator, Numerical Recipes' constants), element (row, col) of an n x n matrix row-major.
inline std::vector<float> matrix(std::size_t n, std::uint32_t seed) {
  std::vector<float> m(n * n);
  std::uint32_t x = seed;
  for (float& v : m) {
    x = 1664525u * x + 1013904223u;
    v = float(x >> 8) / float(1u << 23) - 1.0f;
  }
  return m;
}

// Block (bi, bj) of an n x n row-major matrix cut into b x b blocks, row-major within the block.
inline std::vector<float> block(const std::vector<float>& m, std::size_t n, std::size_t b,
                                std::size_t bi, std::size_t bj) {
  std::vector<float> out(b * b);
  for (std::size_t r = 0; r < b; ++r)
    for (std::size_t s = 0; s < b; ++s) out[r * b + s] = m[(bi * b + r) * n + bj * b + s];
  return out;
}

}  // namespace systolic
