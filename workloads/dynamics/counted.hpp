// The instrumented scalar: Counted<T> computes exactly what T computes (same IEEE operations, same
// order), counts each operation into the OpCounts of the innermost active OpTally, and, while a
// t800::codegen::Recording is active on its thread, records the operation's dataflow, from which
// the code generator compiles the kernel to T800 code. Kernels templated on the scalar type run
// with it to learn their operation mix and their code (docs/architecture.md, "Compute costs").
#pragma once

#include <cmath>
#include <cstdint>
#include <type_traits>

#include "t800/codegen/recording.hpp"
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
  using NodeKind = t800::codegen::NodeKind;
  using Recording = t800::codegen::Recording;

 public:
  using value_type = T;

  // Made while a recording is active, a value is that recording's (a constant of its code until
  // computed); made with none, it belongs to none, and a recording that reads it is told so.
  Counted() : serial_(current_serial()) {}
  // Implicit from T: literals and constants enter expressions without cost (their loads are counted
  // explicitly by the kernels, see op_counts.hpp; a recording makes them constants of the code).
  Counted(T v) : v_(v), serial_(current_serial()) {}  // NOLINT(google-explicit-constructor)
  // A copy is a value: reading a declared array element, it is a load of that element.
  Counted(const Counted& o) : v_(o.v_), node_(o.value_node()), serial_(o.serial_) {}
  // Assigning to a declared array element is a store into it (recorded); otherwise a copy.
  Counted& operator=(const Counted& o) {
    const int node = o.value_node();
    v_ = o.v_;
    Recording* r = Recording::current();
    if (r && home_ >= 0 && serial_ == r->serial()) {
      if (o.foreign_to(*r)) [[unlikely]]
        r->foreign_value(o.serial_, type_name(), r->arrays()[r->accesses()[home_].array].name);
      r->store(home_, node >= 0 ? node : r->constant(double(v_)));
      node_ = -1;  // read again, it is loaded from the element
    } else {
      node_ = node;
      home_ = -1;
      serial_ = o.serial_;
    }
    return *this;
  }

  T value() const { return v_; }

  // Makes this the element of a declared array (occam/structure.hpp, occam::declare).
  void bind(int access) {
    home_ = access;
    node_ = -1;
    serial_ = current_serial();
  }

  friend Counted operator+(Counted a, Counted b) {
    return count(&OpCounts::fadd, a.v_ + b.v_, NodeKind::add, a, b);
  }
  friend Counted operator-(Counted a, Counted b) {
    return count(&OpCounts::fadd, a.v_ - b.v_, NodeKind::sub, a, b);
  }
  friend Counted operator*(Counted a, Counted b) {
    return count(&OpCounts::fmul, a.v_ * b.v_, NodeKind::mul, a, b);
  }
  friend Counted operator/(Counted a, Counted b) {
    return count(&OpCounts::fdiv, a.v_ / b.v_, NodeKind::div, a, b);
  }
  // A sign change is folded into the add or subtract that consumes it (occam writes a - b): not
  // counted, and the code generator folds it the same way.
  friend Counted operator-(Counted a) { return record(-a.v_, NodeKind::neg, a, a); }

  Counted& operator+=(Counted b) { return *this = *this + b; }
  Counted& operator-=(Counted b) { return *this = *this - b; }
  Counted& operator*=(Counted b) { return *this = *this * b; }
  Counted& operator/=(Counted b) { return *this = *this / b; }

  // The T800 compares with fpgt and fpeq: a < b is b > a, a <= b is NOT (a > b). A recording keeps
  // the comparison instruction's outcome (the IF's branch).
  friend bool operator<(Counted a, Counted b) {
    return compare(NodeKind::greater, b, a, b.v_ > a.v_, a.v_ < b.v_);
  }
  friend bool operator>(Counted a, Counted b) {
    return compare(NodeKind::greater, a, b, a.v_ > b.v_, a.v_ > b.v_);
  }
  friend bool operator<=(Counted a, Counted b) {
    return compare(NodeKind::greater, a, b, a.v_ > b.v_, a.v_ <= b.v_);
  }
  friend bool operator>=(Counted a, Counted b) {
    return compare(NodeKind::greater, b, a, b.v_ > a.v_, a.v_ >= b.v_);
  }
  friend bool operator==(Counted a, Counted b) {
    return compare(NodeKind::equal, a, b, a.v_ == b.v_, a.v_ == b.v_);
  }
  friend bool operator!=(Counted a, Counted b) {
    return compare(NodeKind::equal, a, b, a.v_ == b.v_, a.v_ != b.v_);
  }

  friend Counted sqrt(Counted a) {
    return count(&OpCounts::fsqrt, std::sqrt(a.v_), NodeKind::sqrt, a, a);
  }
  friend Counted sin(Counted a) {
    return count(&OpCounts::fsincos, std::sin(a.v_), NodeKind::sine, a, a);
  }
  friend Counted cos(Counted a) {
    return count(&OpCounts::fsincos, std::cos(a.v_), NodeKind::cosine, a, a);
  }
  // |a| (fpuabs): kernels count it themselves where they count integer work.
  friend Counted fabs(Counted a) { return record(std::fabs(a.v_), NodeKind::abs, a, a); }

 private:
  // The node holding this value in the active recording: its own, a load of its array element, or
  // -1 (a literal, or a value from outside the recording: a constant of the code).
  int value_node() const {
    Recording* r = Recording::current();
    if (!r || serial_ != r->serial()) return -1;
    if (node_ >= 0) return node_;
    return home_ >= 0 ? r->load(home_) : -1;
  }
  // Made outside this recording: in another, or before any (kOutside). A literal or a plain T
  // converted inside is this recording's constant.
  bool foreign_to(const Recording& r) const { return serial_ != r.serial(); }
  static std::uint32_t current_serial() {
    Recording* r = Recording::current();
    return r ? r->serial() : Recording::kOutside;
  }
  static const char* type_name() {
    return sizeof(T) == sizeof(double) ? "t800sim::Real64 (dynamics::Counted<double>)"
                                       : "t800sim::Real32 (dynamics::Counted<float>)";
  }
  static int operand(Recording& r, const Counted& x) {
    if (x.foreign_to(r)) [[unlikely]]
      r.foreign_value(x.serial_, type_name());
    return (x.node_ >= 0 && x.serial_ == r.serial()) ? x.node_ : r.constant(double(x.v_));
  }
  static Counted record(T result, NodeKind kind, const Counted& a, const Counted& b) {
    Counted c(result);
    if (Recording* r = Recording::current()) {
      const bool unary = &a == &b;
      c.node_ = r->operation(kind, operand(*r, a), unary ? -1 : operand(*r, b));
      c.serial_ = r->serial();
    }
    return c;
  }
  static Counted count(long OpCounts::*field, T result, NodeKind kind, const Counted& a,
                       const Counted& b) {
    detail::tally(field);
    return record(result, kind, a, b);
  }
  static bool compare(NodeKind kind, const Counted& a, const Counted& b, bool instruction_result,
                      bool result) {
    detail::tally(&OpCounts::fcompare);
    if (Recording* r = Recording::current())
      r->test(r->operation(kind, operand(*r, a), operand(*r, b)), instruction_result);
    return result;
  }

  T v_ = 0;
  int node_ = -1;                               // the recorded node holding the value
  int home_ = -1;                               // a declared array element (recorded access)
  std::uint32_t serial_ = Recording::kOutside;  // the recording node_, home_ and the value are of
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
