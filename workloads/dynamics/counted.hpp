// A counting scalar: Counted<T> computes exactly what T computes (same IEEE operations, same
// order) and counts each operation into the OpCounts of the innermost active OpTally. Kernels
// templated on the scalar type run once with it to learn their operation mix (docs/architecture.md, "Programs: processes and
// flows", step 4).
#pragma once

#include <cmath>
#include <type_traits>

#include "workloads/dynamics/op_counts.hpp"

namespace dynamics {

// Collects the operations of every Counted<T> evaluated while it is alive (per thread; nests: an
// inner tally hides the outer one until it ends). Operations with no tally alive are not counted.
class OpTally {
 public:
  OpTally() : outer_(active()) { active() = &counts_; }
  ~OpTally() { active() = outer_; }
  OpTally(const OpTally&) = delete;
  OpTally& operator=(const OpTally&) = delete;

  const OpCounts& counts() const { return counts_; }

  // The counts receiving operations now, or nullptr.
  static OpCounts* current() { return active(); }

 private:
  static OpCounts*& active() {
    thread_local OpCounts* counts = nullptr;
    return counts;
  }
  OpCounts counts_;
  OpCounts* outer_;
};

namespace detail {
template <class Field>
inline void tally(Field field, long n = 1) {
  if (OpCounts* counts = OpTally::current()) counts->*field += n;
}
}  // namespace detail

template <class T>
class Counted {
  static_assert(std::is_floating_point_v<T>, "Counted wraps float or double");

 public:
  using value_type = T;

  Counted() = default;
  // Implicit from T: literals and constants enter expressions without cost (their loads are counted
  // explicitly by the kernels, see op_counts.hpp).
  Counted(T v) : v_(v) {}  // NOLINT(google-explicit-constructor)

  T value() const { return v_; }

  friend Counted operator+(Counted a, Counted b) { return count(&OpCounts::fadd, a.v_ + b.v_); }
  friend Counted operator-(Counted a, Counted b) { return count(&OpCounts::fadd, a.v_ - b.v_); }
  friend Counted operator*(Counted a, Counted b) { return count(&OpCounts::fmul, a.v_ * b.v_); }
  friend Counted operator/(Counted a, Counted b) { return count(&OpCounts::fdiv, a.v_ / b.v_); }
  // A sign change is folded into the add or subtract that consumes it (occam writes a - b).
  friend Counted operator-(Counted a) { return Counted(-a.v_); }

  Counted& operator+=(Counted b) { return *this = *this + b; }
  Counted& operator-=(Counted b) { return *this = *this - b; }
  Counted& operator*=(Counted b) { return *this = *this * b; }
  Counted& operator/=(Counted b) { return *this = *this / b; }

  friend bool operator<(Counted a, Counted b) { return compare(a.v_ < b.v_); }
  friend bool operator>(Counted a, Counted b) { return compare(a.v_ > b.v_); }
  friend bool operator<=(Counted a, Counted b) { return compare(a.v_ <= b.v_); }
  friend bool operator>=(Counted a, Counted b) { return compare(a.v_ >= b.v_); }
  friend bool operator==(Counted a, Counted b) { return compare(a.v_ == b.v_); }
  friend bool operator!=(Counted a, Counted b) { return compare(a.v_ != b.v_); }

  friend Counted sqrt(Counted a) { return count(&OpCounts::fsqrt, std::sqrt(a.v_)); }
  friend Counted sin(Counted a) { return count(&OpCounts::fsincos, std::sin(a.v_)); }
  friend Counted cos(Counted a) { return count(&OpCounts::fsincos, std::cos(a.v_)); }

 private:
  static Counted count(long OpCounts::*field, T result) {
    detail::tally(field);
    return Counted(result);
  }
  static bool compare(bool result) {
    detail::tally(&OpCounts::fcompare);
    return result;
  }
  T v_ = 0;
};

template <class T>
struct is_counted : std::false_type {};
template <class T>
struct is_counted<Counted<T>> : std::true_type {};
template <class T>
inline constexpr bool is_counted_v = is_counted<T>::value;

// The plain floating-point type underneath a scalar (T for Counted<T>, the type itself otherwise).
template <class S>
struct plain_scalar {
  using type = S;
};
template <class T>
struct plain_scalar<Counted<T>> {
  using type = T;
};
template <class S>
using plain_scalar_t = typename plain_scalar<S>::type;

// A double as a scalar of type S (rounded to float for float and Counted<float>).
template <class S>
S as_scalar(double x) {
  return S(static_cast<plain_scalar_t<S>>(x));
}

// The value of a scalar as double, whatever the scalar type.
template <class S>
double to_double(const S& x) {
  if constexpr (is_counted_v<S>) {
    return static_cast<double>(x.value());
  } else {
    return static_cast<double>(x);
  }
}

// Explicit memory traffic of REAL values (the convention in op_counts.hpp): no-ops for plain
// scalars.
template <class S>
void note_loads(long n) {
  if constexpr (is_counted_v<S>) detail::tally(&OpCounts::fload, n);
}
template <class S>
void note_stores(long n) {
  if constexpr (is_counted_v<S>) detail::tally(&OpCounts::fstore, n);
}

// sin and cos for plain and counted scalars alike (std:: for float/double, the friends above for
// Counted).
template <class S>
S sine(const S& x) {
  using std::sin;
  return sin(x);
}
template <class S>
S cosine(const S& x) {
  using std::cos;
  return cos(x);
}

}  // namespace dynamics
