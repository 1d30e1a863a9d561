// Folded<S>: a scalar that knows when it is a structural 0, +1 or -1, so that a kernel written once
// for any robot executes only the operations a programmer simplifying the equations for *this*
// robot would write (Paul's hand-simplified Stanford-arm equations drop every product with a zero
// DH or inertia constant). Structure comes only from model constants (alpha = +-90 deg, a = 0, zero
// centre-of-mass components, a prismatic joint's delta = 0), never from the state, so the
// operations executed, and therefore the op counts, do not depend on the state. Folding is exact:
// 0*x = 0, 1*x = x, x + 0 = x.
#pragma once

#include "workloads/dynamics/counted.hpp"

namespace dynamics {

template <class S>
class Folded {
 public:
  enum class Kind { zero, plus_one, minus_one, general };

  Folded() = default;  // a structural zero

  // A computed quantity (an input, or the result of arithmetic). Never folded by its value, even
  // when it happens to be 0 or 1: that would make the operations depend on the state.
  static Folded variable(S value) { return Folded(Kind::general, value); }

  // A model constant: exact 0 and +-1 fold away; any other value is a REAL the kernel loads from
  // memory.
  static Folded constant(double k) {
    if (k == 0.0) return Folded();
    if (k == 1.0) return Folded(Kind::plus_one, S(1));
    if (k == -1.0) return Folded(Kind::minus_one, S(-1));
    note_loads<S>(1);
    return Folded(Kind::general, S(static_cast<plain_scalar_t<S>>(k)));
  }

  Kind kind() const { return kind_; }
  bool is_zero() const { return kind_ == Kind::zero; }
  const S& value() const { return value_; }

  friend Folded operator-(const Folded& a) {
    switch (a.kind_) {
      case Kind::zero:
        return a;
      case Kind::plus_one:
        return Folded(Kind::minus_one, S(-1));
      case Kind::minus_one:
        return Folded(Kind::plus_one, S(1));
      case Kind::general:
        break;
    }
    return Folded(Kind::general, -a.value_);
  }

  friend Folded operator+(const Folded& a, const Folded& b) {
    if (a.is_zero()) return b;
    if (b.is_zero()) return a;
    return Folded(Kind::general, a.value_ + b.value_);
  }

  friend Folded operator-(const Folded& a, const Folded& b) {
    if (b.is_zero()) return a;
    if (a.is_zero()) return -b;
    return Folded(Kind::general, a.value_ - b.value_);
  }

  friend Folded operator*(const Folded& a, const Folded& b) {
    if (a.is_zero() || b.is_zero()) return Folded();
    if (a.kind_ == Kind::plus_one) return b;
    if (a.kind_ == Kind::minus_one) return -b;
    if (b.kind_ == Kind::plus_one) return a;
    if (b.kind_ == Kind::minus_one) return -a;
    return Folded(Kind::general, a.value_ * b.value_);
  }

  Folded& operator+=(const Folded& b) { return *this = *this + b; }
  Folded& operator-=(const Folded& b) { return *this = *this - b; }

 private:
  Folded(Kind kind, S value) : kind_(kind), value_(value) {}

  Kind kind_ = Kind::zero;
  S value_ = S(0);
};

}  // namespace dynamics
