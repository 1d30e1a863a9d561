// Operation counts of a piece of numerical work, by kind. t800::CostModel turns them into T800
// cycles (REAL32 or REAL64 timings); this struct only counts and knows nothing of cycles.
#pragma once

#include <string>

namespace dynamics {

// What each field counts (one unit = one executed operation of the kind named):
//   fadd      additions and subtractions (a sign change is folded into them, not counted)
//   fmul      multiplications
//   fdiv      divisions
//   fsqrt     square roots
//   fsincos   calls of the software SIN or COS routine (occam has no sin/cos instruction; one call
//             each, the cost model prices the routine)
//   fcompare  comparisons
//   fload     REAL values loaded from memory: each value of the master's message a kernel uses,
//   once
//             per kernel; each model constant other than 0 and +-1 (those fold away), once per step
//             that uses it (a DH step, a link's contribution)
//   fstore    REAL results stored (one per subtask; the message values, for the master)
//   int_ops   integer and control operations a kernel counts explicitly (loop bookkeeping,
//             indexing), and t800sim::Int's one-cycle operations, comparisons and conversions;
//             the dynamics kernels are straight-line code per subtask and count none
//   int_mul   t800sim::Int products (mul)
//   int_div   t800sim::Int quotients and remainders (div, rem)
// Spills of intermediate values and the integer work of straight-line code are not counted; they
// belong to the compiled code's efficiency, which the cost model carries as one global factor.
struct OpCounts {
  long fadd = 0;
  long fmul = 0;
  long fdiv = 0;
  long fsqrt = 0;
  long fsincos = 0;
  long fcompare = 0;
  long fload = 0;
  long fstore = 0;
  long int_ops = 0;
  long int_mul = 0;
  long int_div = 0;

  OpCounts& operator+=(const OpCounts& other) {
    fadd += other.fadd;
    fmul += other.fmul;
    fdiv += other.fdiv;
    fsqrt += other.fsqrt;
    fsincos += other.fsincos;
    fcompare += other.fcompare;
    fload += other.fload;
    fstore += other.fstore;
    int_ops += other.int_ops;
    int_mul += other.int_mul;
    int_div += other.int_div;
    return *this;
  }

  // Floating-point arithmetic operations (add, mul, div, sqrt, compare), sin/cos calls excluded.
  long flops() const { return fadd + fmul + fdiv + fsqrt + fcompare; }
};

inline OpCounts operator+(OpCounts a, const OpCounts& b) {
  return a += b;
}

inline bool operator==(const OpCounts& a, const OpCounts& b) {
  return a.fadd == b.fadd && a.fmul == b.fmul && a.fdiv == b.fdiv && a.fsqrt == b.fsqrt &&
         a.fsincos == b.fsincos && a.fcompare == b.fcompare && a.fload == b.fload &&
         a.fstore == b.fstore && a.int_ops == b.int_ops && a.int_mul == b.int_mul &&
         a.int_div == b.int_div;
}
inline bool operator!=(const OpCounts& a, const OpCounts& b) {
  return !(a == b);
}

// "fadd=12 fmul=30 ..." listing the non-zero fields (for reports and test messages).
std::string to_string(const OpCounts& counts);

}  // namespace dynamics
