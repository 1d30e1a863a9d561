// What one piece of the elimination costs: its floating-point operations (counted by
// dynamics::Counted, op_counts.hpp) plus the integer work of the loops around them, which the
// dynamics kernels do not have (they are straight-line code) but Gaussian elimination does: a
// T800 `lend` costs 10 cycles, as much as a floating add, so loop control cannot be left out.
//
// The integer work is tallied by the kernels themselves as they run (occam::seq for loops,
// note_indexed, note_tests, ...) whenever the scalar is counted, the same way note_loads/note_stores
// count memory traffic. How each item maps onto T800 instructions is the op-count model's business
// (workloads/pipeline/costs.hpp); a recording compiles the kernel's own code instead.
#pragma once

#include <cmath>
#include <string>

#include "workloads/dynamics/counted.hpp"
#include "workloads/dynamics/op_counts.hpp"
#include "workloads/occam/structure.hpp"

namespace elimination {

// Integer and control work, in units of the code the occam compiler emits for it:
//   loops       occam replicated SEQ loops entered (set-up of the index and count)
//   iterations  loop iterations (one `lend` each)
//   indexed     element addressings a[i] or a[i][j] (base and index loaded, scaled, added)
//   tests       IF branches on a computed condition (a conditional jump each)
//   moves       integer assignments (a row index swapped on an interchange, a counter updated)
//   abs         fpuabs, the FPU's absolute value (no arithmetic; costed as its issue)
struct IntegerWork {
  long loops = 0;
  long iterations = 0;
  long indexed = 0;
  long tests = 0;
  long moves = 0;
  long abs = 0;

  IntegerWork& operator+=(const IntegerWork& o) {
    loops += o.loops;
    iterations += o.iterations;
    indexed += o.indexed;
    tests += o.tests;
    moves += o.moves;
    abs += o.abs;
    return *this;
  }
  bool operator==(const IntegerWork& o) const {
    return loops == o.loops && iterations == o.iterations && indexed == o.indexed &&
           tests == o.tests && moves == o.moves && abs == o.abs;
  }
  bool operator!=(const IntegerWork& o) const { return !(*this == o); }
};

// The cost of one piece: floating point and integer work together.
struct Work {
  dynamics::OpCounts fp;
  IntegerWork integer;

  Work& operator+=(const Work& o) {
    fp += o.fp;
    integer += o.integer;
    return *this;
  }
  bool operator==(const Work& o) const { return fp == o.fp && integer == o.integer; }
  bool operator!=(const Work& o) const { return !(*this == o); }
};

inline Work operator+(Work a, const Work& b) {
  return a += b;
}

// "fadd=.. fmul=.. | loops=.. iterations=.." (for reports and test messages).
std::string to_string(const Work& work);

// Collects the work of every counted kernel run while it is alive (per thread, nests like
// dynamics::OpTally, which it contains for the floating-point part).
class WorkTally {
 public:
  WorkTally() : outer_(active()) { active() = &integer_; }
  ~WorkTally() { active() = outer_; }
  WorkTally(const WorkTally&) = delete;
  WorkTally& operator=(const WorkTally&) = delete;

  Work work() const {
    IntegerWork integer = integer_;
    integer.loops += loops_.loops();
    integer.iterations += loops_.iterations();
    return {fp_.counts(), integer};
  }
  static IntegerWork* current() { return active(); }

 private:
  static IntegerWork*& active() {
    thread_local IntegerWork* work = nullptr;
    return work;
  }
  dynamics::OpTally fp_;
  occam::LoopTally loops_;  // the replicated SEQs (occam::seq) the kernels run
  IntegerWork integer_;
  IntegerWork* outer_;
};

namespace detail {
template <class S>
void tally(long IntegerWork::*field, long n) {
  if constexpr (dynamics::is_counted_v<S>) {
    if (IntegerWork* work = WorkTally::current()) work->*field += n;
  }
}
}  // namespace detail

template <class S>
void note_indexed(long n) {
  detail::tally<S>(&IntegerWork::indexed, n);
}
// IFs on integer conditions (a status word, a flag): counted, and recorded as integer tests.
template <class S>
void note_tests(long n) {
  detail::tally<S>(&IntegerWork::tests, n);
  occam::integer<S>(t800::codegen::IntegerStatement::test, n);
}
// IFs whose condition is a REAL comparison: counted here; the comparison records itself.
template <class S>
void note_compared(long n) {
  detail::tally<S>(&IntegerWork::tests, n);
}
// The FPU's error flag tested once (a status word for level 3, or q-dot's check).
template <class S>
void note_error_check() {
  detail::tally<S>(&IntegerWork::tests, 1);
  occam::integer<S>(t800::codegen::IntegerStatement::error_check, 1);
}
template <class S>
void note_moves(long n) {
  detail::tally<S>(&IntegerWork::moves, n);
  occam::integer<S>(t800::codegen::IntegerStatement::move, n);
}

// |x| for plain and counted scalars; counted as one fpuabs.
template <class S>
S magnitude(const S& x) {
  detail::tally<S>(&IntegerWork::abs, 1);
  if constexpr (dynamics::is_counted_v<S>) {
    return fabs(x);
  } else {
    return std::fabs(x);
  }
}

}  // namespace elimination
