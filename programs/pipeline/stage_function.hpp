// What the fixed-stages pipeline (fixed_stages.cpp) feeds in and what each stage computes, in
// REAL32: round r's item is r + e / n for e = 0..n-1, and stage s (0-based) halves every element
// and adds s + 1.
#pragma once

#include <cstddef>
#include <vector>

namespace fixed_stages {

inline std::vector<float> input(int round, std::size_t n) {
  std::vector<float> x(n);
  for (std::size_t e = 0; e < n; ++e) x[e] = float(round) + float(e) / float(n);
  return x;
}

inline std::vector<float> stage_function(int stage, const std::vector<float>& x) {
  std::vector<float> y(x.size());
  for (std::size_t e = 0; e < x.size(); ++e) y[e] = x[e] * 0.5f + float(stage + 1);
  return y;
}

}  // namespace fixed_stages
