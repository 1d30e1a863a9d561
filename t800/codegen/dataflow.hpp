// What the emitters need to know of a recording's values before emitting any code: which nodes
// are live (reach a store or a test), how often and from which blocks each is used, hence which
// are local variables (workspace temporaries), the last statement that reads each of those, and,
// while emitting, the workspace word each temporary has. REAL and INT nodes are analysed alike;
// the REAL and INT expression emitters (expression.hpp, integer_expression.hpp) share one.
#pragma once

#include <array>
#include <map>
#include <vector>

#include "t800/codegen/frame.hpp"
#include "t800/codegen/recording.hpp"

namespace t800::codegen {

// The depth of the evaluation stacks, integer (A, B, C) and floating point (FA, FB, FC) alike.
constexpr int kStackDepth = 3;

class Dataflow {
 public:
  explicit Dataflow(const Recording& recording);

  bool live(int n) const { return live_[std::size_t(n)]; }
  bool temporary(int n) const { return temporary_[std::size_t(n)]; }
  int uses(int n) const { return uses_[std::size_t(n)]; }
  // n without the sign changes around it (a REAL's -x is folded into its consumer).
  int through(int n) const;
  // The INT node an access's subscript is computed from (t800sim::at), or -1.
  int subscript(int access) const;
  // A SEQ's first index and count, where the kernel computes them (INT nodes, else -1).
  std::array<int, 2> loop_bounds(const Event& e) const;
  // Whether REAL constants other than 0.0 are read (the PROC then points at its constant table).
  bool uses_real_constants() const { return uses_real_constants_; }

  // The workspace word of temporary n, while it lives (assign when it is defined).
  int slot(int n) const { return slot_[std::size_t(n)]; }
  void assign(int n, Frame& frame);
  void adopt(int n, int slot) { slot_[std::size_t(n)] = slot; }  // a word already allocated
  // The temporaries whose last use is `event` give their words back.
  void release_after(int event, Frame& frame);

 private:
  int words(int n) const;  // of n's value: an INT's one, a REAL's one or two
  const Recording& r_;
  std::vector<bool> live_, temporary_;
  std::vector<int> uses_, last_use_, slot_;
  std::multimap<int, int> release_at_;  // event -> temporaries whose last use it is
  bool uses_real_constants_ = false;
};

}  // namespace t800::codegen
