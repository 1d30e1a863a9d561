// The instrumented scalar: Counted<T> computes exactly what T computes (same IEEE operations, same
// order), counts each operation into the OpCounts of the innermost active OpTally, and, while a
// t800::codegen::Recording is active on its thread, records the operation's dataflow, from which
// the code generator compiles the kernel to T800 code. Kernels templated on the scalar type run
// with it to learn their operation mix and their code (docs/architecture.md, "Compute costs").
//
// T is float (REAL32), double (REAL64) or std::int32_t (occam's INT on the T800). An INT's
// arithmetic is occam's: + - * / \ are checked (an overflow, a division by zero, is an error: a
// std::overflow_error here, the Error flag on the chip), / truncates towards zero and \ takes the
// dividend's sign (as C++'s / and %), << and >> shift by 0 to 32 places (>> is logical, as shr);
// its values convert to REAL and back only where the kernel says so (to_real, int_round,
// int_trunc), as occam's REAL64 ROUND n, INT ROUND x, INT TRUNC x.
#pragma once

#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
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
  static constexpr bool kInt = std::is_same_v<T, std::int32_t>;
  static_assert(std::is_floating_point_v<T> || kInt, "Counted wraps float, double or std::int32_t");
  using NodeKind = t800::codegen::NodeKind;
  using Recording = t800::codegen::Recording;
  template <class>
  friend class Counted;  // the conversions between INT and REAL

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
      r->store(home_, node >= 0 ? node : constant(*r, v_));
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

  // For subscripts the kernel computes (occam/subscript.hpp). The access of the declared element
  // this is, or -1; whether it is an element of recording r's.
  int home() const { return home_; }
  bool belongs_to(const Recording& r) const { return serial_ == r.serial(); }
  // The node holding x in recording r: x's own, a load when x is a declared element (x is taken by
  // value: the copy loads it), a constant for a literal; a KernelError for another recording's.
  static int node_of(Recording& r, Counted x) { return operand(r, x); }
  // The value the active recording holds at INT node `node` (a loop's index, occam/structure.hpp).
  static Counted recorded(T v, int node) {
    Counted c(v);
    c.node_ = node;
    return c;
  }
  // Sets the value alone, recording nothing: it was stored through a view of this element whose
  // subscript the kernel computed, and that store was recorded.
  void set_value_unrecorded(T v) { v_ = v; }

  friend Counted operator+(Counted a, Counted b) {
    if constexpr (kInt) return integer(NodeKind::add, a, b);
    return count(&OpCounts::fadd, a.v_ + b.v_, NodeKind::add, a, b);
  }
  friend Counted operator-(Counted a, Counted b) {
    if constexpr (kInt) return integer(NodeKind::sub, a, b);
    return count(&OpCounts::fadd, a.v_ - b.v_, NodeKind::sub, a, b);
  }
  friend Counted operator*(Counted a, Counted b) {
    if constexpr (kInt) return integer(NodeKind::mul, a, b);
    return count(&OpCounts::fmul, a.v_ * b.v_, NodeKind::mul, a, b);
  }
  friend Counted operator/(Counted a, Counted b) {
    if constexpr (kInt) return integer(NodeKind::div, a, b);
    return count(&OpCounts::fdiv, a.v_ / b.v_, NodeKind::div, a, b);
  }
  // A REAL's sign change is folded into the add or subtract that consumes it (occam writes a - b):
  // not counted, and the code generator folds it the same way. An INT's is 0 - a (checked).
  friend Counted operator-(Counted a) {
    if constexpr (kInt) return integer(NodeKind::sub, Counted(0), a);
    return record(-a.v_, NodeKind::neg, a, a);
  }

  // INT only: occam's \, /\, \/, ><, ~, << and >>.
  friend Counted operator%(Counted a, Counted b) { return integer(NodeKind::rem, a, b); }
  friend Counted operator&(Counted a, Counted b) { return integer(NodeKind::bit_and, a, b); }
  friend Counted operator|(Counted a, Counted b) { return integer(NodeKind::bit_or, a, b); }
  friend Counted operator^(Counted a, Counted b) { return integer(NodeKind::bit_xor, a, b); }
  friend Counted operator~(Counted a) { return integer(NodeKind::bit_not, a, a); }
  friend Counted operator<<(Counted a, Counted b) { return integer(NodeKind::shift_left, a, b); }
  friend Counted operator>>(Counted a, Counted b) { return integer(NodeKind::shift_right, a, b); }

  Counted& operator+=(Counted b) { return *this = *this + b; }
  Counted& operator-=(Counted b) { return *this = *this - b; }
  Counted& operator*=(Counted b) { return *this = *this * b; }
  Counted& operator/=(Counted b) { return *this = *this / b; }
  Counted& operator%=(Counted b) { return *this = *this % b; }

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
    static_assert(!kInt, "SQRT is a REAL operation");
    return count(&OpCounts::fsqrt, std::sqrt(a.v_), NodeKind::sqrt, a, a);
  }
  friend Counted sin(Counted a) {
    static_assert(!kInt, "SIN is a REAL routine");
    return count(&OpCounts::fsincos, std::sin(a.v_), NodeKind::sine, a, a);
  }
  friend Counted cos(Counted a) {
    static_assert(!kInt, "COS is a REAL routine");
    return count(&OpCounts::fsincos, std::cos(a.v_), NodeKind::cosine, a, a);
  }
  // |a| (fpuabs): kernels count it themselves where they count integer work.
  friend Counted fabs(Counted a) {
    static_assert(!kInt, "fabs is a REAL operation");
    return record(std::fabs(a.v_), NodeKind::abs, a, a);
  }

  // The result of a conversion from `from` (another Counted type), recorded as `kind`: the
  // conversions below are its only callers.
  // `from` by value: an element of a declared array is loaded by the copy.
  template <class From>
  static Counted converted(NodeKind kind, T result, Counted<From> from) {
    detail::tally(&OpCounts::int_ops);
    Counted c(result);
    if (Recording* r = Recording::current()) {
      c.node_ =
          r->operation(kind, Counted<From>::operand(*r, from), -1, kInt ? double(result) : 0.0);
      c.serial_ = r->serial();
    }
    return c;
  }

 private:
  // The node holding this value in the active recording: its own, a load of its array element, or
  // -1 (a literal, or a value from outside the recording: a constant of the code).
  int value_node() const {
    Recording* r = Recording::current();
    if (!r || serial_ != r->serial()) return -1;
    if (node_ >= 0) return node_;
    return home_ >= 0 ? r->load(home_, double(v_)) : -1;
  }
  // Made outside this recording: in another, or before any (kOutside). A literal or a plain T
  // converted inside is this recording's constant.
  bool foreign_to(const Recording& r) const { return serial_ != r.serial(); }
  static std::uint32_t current_serial() {
    Recording* r = Recording::current();
    return r ? r->serial() : Recording::kOutside;
  }
  static const char* type_name() {
    if constexpr (kInt) return "t800sim::Int (dynamics::Counted<std::int32_t>)";
    return sizeof(T) == sizeof(double) ? "t800sim::Real64 (dynamics::Counted<double>)"
                                       : "t800sim::Real32 (dynamics::Counted<float>)";
  }
  static int constant(Recording& r, T v) {
    if constexpr (kInt) return r.integer_constant(v);
    return r.constant(double(v));
  }
  static int operand(Recording& r, const Counted& x) {
    if (x.foreign_to(r)) [[unlikely]]
      r.foreign_value(x.serial_, type_name());
    return (x.node_ >= 0 && x.serial_ == r.serial()) ? x.node_ : constant(r, x.v_);
  }
  // occam's INT arithmetic, checked as the T800's add, sub, mul, div and rem check it.
  static T integer_result(NodeKind kind, std::int64_t a, std::int64_t b) {
    static_assert(kInt, "an INT operation");
    const auto fail = [&](const char* what) -> T {
      throw std::overflow_error(std::string("INT ") + what + " (" + std::to_string(a) + ", " +
                                std::to_string(b) + "): occam's INT arithmetic is checked");
    };
    std::int64_t v = 0;
    switch (kind) {
      case NodeKind::add:
        v = a + b;
        break;
      case NodeKind::sub:
        v = a - b;
        break;
      case NodeKind::mul:
        v = a * b;
        break;
      case NodeKind::div:
      case NodeKind::rem:
        if (b == 0) return fail("division by zero");
        v = kind == NodeKind::div ? a / b : a % b;
        break;
      case NodeKind::bit_and:
        return T(a & b);
      case NodeKind::bit_or:
        return T(a | b);
      case NodeKind::bit_xor:
        return T(a ^ b);
      case NodeKind::bit_not:
        return T(~a);
      case NodeKind::shift_left:
      case NodeKind::shift_right: {
        if (b < 0 || b > 32) return fail("shift by other than 0 to 32 places");
        if (b == 32) return 0;
        const std::uint32_t u = std::uint32_t(std::int32_t(a));
        return T(std::int32_t(kind == NodeKind::shift_left ? u << b : u >> b));
      }
      default:
        break;
    }
    if (v < std::numeric_limits<T>::min() || v > std::numeric_limits<T>::max())
      return fail("overflow");
    return T(v);
  }
  static Counted integer(NodeKind kind, const Counted& a, const Counted& b) {
    detail::tally(kind == NodeKind::mul                            ? &OpCounts::int_mul
                  : kind == NodeKind::div || kind == NodeKind::rem ? &OpCounts::int_div
                                                                   : &OpCounts::int_ops);
    return record(integer_result(kind, a.v_, b.v_), kind, a, b);
  }
  static Counted record(T result, NodeKind kind, const Counted& a, const Counted& b) {
    Counted c(result);
    if (Recording* r = Recording::current()) {
      const bool unary = &a == &b;
      c.node_ = r->operation(kind, operand(*r, a), unary ? -1 : operand(*r, b),
                             kInt ? double(result) : 0.0);
      c.serial_ = r->serial();
    }
    return c;
  }
  static Counted count(long OpCounts::*field, T result, NodeKind kind, const Counted& a,
                       const Counted& b) {
    detail::tally(field);
    return record(result, kind, a, b);
  }
  // A REAL comparison's test keeps the instruction's outcome (the IF's branches are arranged
  // around it); an INT one keeps the condition's, its node saying whether the condition is the
  // instruction's result negated (occam's >=, <= and <> on INTs: gt or diff, then eqc 0).
  static bool compare(NodeKind kind, const Counted& a, const Counted& b, bool instruction_result,
                      bool result) {
    detail::tally(kInt ? &OpCounts::int_ops : &OpCounts::fcompare);
    if (Recording* r = Recording::current()) {
      if constexpr (kInt) {
        const bool inverted = instruction_result != result;
        r->test(r->comparison(kind, operand(*r, a), operand(*r, b), inverted), result);
      } else {
        r->test(r->operation(kind, operand(*r, a), operand(*r, b)), instruction_result);
      }
    }
    return result;
  }

  T v_ = 0;
  int node_ = -1;                               // the recorded node holding the value
  int home_ = -1;                               // a declared array element (recorded access)
  std::uint32_t serial_ = Recording::kOutside;  // the recording node_, home_ and the value are of
};

using CountedInt = Counted<std::int32_t>;

// REALn ROUND n: an INT as a REAL of R's precision (exact in REAL64, rounded to nearest in REAL32;
// fpi32tor64, fpi32tor32).
template <class R>
R to_real(const CountedInt& n) {
  static_assert(std::is_floating_point_v<typename R::value_type>, "to_real<Real32 or Real64>");
  using Real = typename R::value_type;
  return R::converted(t800::codegen::NodeKind::to_real, Real(n.value()), n);
}

namespace detail {
// x rounded (to nearest, ties to even, as the FPU's default mode) or truncated to an INT; an
// error when that is not an INT (the chip's fpuchki32 sets the Error flag).
template <class Real>
std::int32_t int_of(Real x, bool truncate) {
  const double v = truncate ? std::trunc(double(x)) : std::nearbyint(double(x));
  if (!(v >= -2147483648.0 && v <= 2147483647.0))
    throw std::overflow_error("INT " + std::string(truncate ? "TRUNC" : "ROUND") + " " +
                              std::to_string(double(x)) + ": not an INT");
  return std::int32_t(v);
}
}  // namespace detail

// INT ROUND x and INT TRUNC x.
template <class R>
CountedInt int_round(const R& x) {
  return CountedInt::converted(t800::codegen::NodeKind::int_round, detail::int_of(x.value(), false),
                               x);
}
template <class R>
CountedInt int_trunc(const R& x) {
  return CountedInt::converted(t800::codegen::NodeKind::int_trunc, detail::int_of(x.value(), true),
                               x);
}

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
