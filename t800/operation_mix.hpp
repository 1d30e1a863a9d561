// What a piece of code does, counted by kind: the input of the cost model. Workloads fill it from
// counted kernels (floating point) and from the shape of the code around them (integer work, loops,
// calls).
#pragma once

#include <cstdint>

namespace t800 {

struct OperationMix {
  // Integer unit. `int_simple` are one-cycle instructions (ldc, adc, add, sub, ldlp, ...); local
  // and non-local word loads/stores are counted apart because their cycles differ and they touch
  // memory.
  std::int64_t int_simple = 0;
  std::int64_t word_loads = 0;   // ldl / ldnl
  std::int64_t word_stores = 0;  // stl / stnl
  std::int64_t int_mul = 0;
  std::int64_t int_div = 0;
  std::int64_t branches = 0;   // cj taken / j
  std::int64_t loop_ends = 0;  // lend, one per loop iteration
  std::int64_t calls = 0;      // call + ret pairs
  std::int64_t prefixes = 0;   // pfix / nfix bytes
  // Floating point unit.
  std::int64_t fp_add = 0;  // add or subtract
  std::int64_t fp_mul = 0;
  std::int64_t fp_div = 0;
  std::int64_t fp_sqrt = 0;
  std::int64_t fp_compare = 0;
  std::int64_t fp_loads = 0;   // fpldnlsn / fpldnldb
  std::int64_t fp_stores = 0;  // fpstnlsn / fpstnldb
  std::int64_t sincos = 0;     // calls of the software SIN / COS routine (costed as its own mix)

  OperationMix& operator+=(const OperationMix& o);
  OperationMix operator*(std::int64_t n) const;  // the mix of n repetitions
  bool operator==(const OperationMix& o) const;
  std::int64_t fp_operations() const { return fp_add + fp_mul + fp_div + fp_sqrt; }
};

inline OperationMix operator+(OperationMix a, const OperationMix& b) {
  return a += b;
}

}  // namespace t800
