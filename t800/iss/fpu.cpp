// The T800 FPU (fpu.hpp). Sources, cited below by these names:
//   CWG    "Transputer instruction set: a compiler writer's guide", INMOS 1988; read through
//          pahihu/t4's citations ("ACWG pp.106 B.2.7", "pp.158") and the Transterpreter's
//          (concurrency/kroc tvm ins_float.c, quoting "the gray book").
//   t4     pahihu/t4 (github), a T800 emulator whose FPU was checked against INMOS's TVS1F test
//          vectors: fparithmetic.c (NaN values, special cases), p.c (stack effects, the rounding
//          reset), Notebook.txt (T800 datasheet excerpts on the error flag and the rounding mode).
//   occ21  the INMOS occam compiler as kept in concurrency/kroc tools/occ21/be: the code it emits
//          for REAL REM (gen12.c), SQRT (gen8.c), REAL->INT (gen11.c, gen5.c), INT64->REAL32
//          (code1k.c geni64tor).
// IEEE 754 arithmetic is exact software rounding of exact intermediate results (round_pack), with
// the host's own IEEE arithmetic as a fast path for round-to-nearest.
#include "t800/iss/fpu.hpp"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstring>
#include <limits>
#include <utility>

namespace t800::iss {

// The fast path needs one IEEE rounding per host operation, in the operand's own format.
static_assert(std::numeric_limits<float>::is_iec559 && std::numeric_limits<double>::is_iec559);
static_assert(FLT_EVAL_METHOD == 0, "float and double operations must round to their own format");

namespace {

using u64 = std::uint64_t;
__extension__ typedef unsigned __int128 u128;
using Length = Fpu::Length;
using Rounding = Fpu::Rounding;
using Register = Fpu::Register;

enum class Arith : std::uint8_t { add, sub, mul, div };

constexpr u64 kSign64 = u64(1) << 63;
constexpr u64 kExp64 = u64(0x7FF) << 52;
constexpr u64 kFrac64 = (u64(1) << 52) - 1;

// The NaNs the T800 produces (t4 fparithmetic.c, NAN64_* and NAN32_*). Each REAL32 value is the
// REAL64 one with its fraction shifted right 29 places (checked in the tests against t4's REAL32
// constants). RemInvalidQuot (the quotient left by an invalid remainder) has only a REAL64 value
// in t4; its REAL32 value 0x7F801000 follows the same pattern.
constexpr u64 kNanDivZeroByZero = 0x7FF8000000000000;
constexpr u64 kNanDivInfByInf = 0x7FF4000000000000;
constexpr u64 kNanMulZeroByInf = 0x7FF2000000000000;
constexpr u64 kNanAddOppositeInf = 0x7FF1000000000000;  // also FB - FA with same-signed infinities
constexpr u64 kNanNegativeSqrt = 0x7FF0800000000000;
constexpr u64 kNanConversion = 0x7FF0400000000000;  // fpur64tor32 of a NaN
constexpr u64 kNanRemFromInf = 0x7FF0080000000000;
constexpr u64 kNanRemByZero = 0x7FF0040000000000;
constexpr u64 kNanRemInvalidQuot = 0x7FF0020000000000;

struct Format {
  int precision, emin, emax, frac_bits, bias, sign_shift;
  u64 sign() const { return u64(1) << sign_shift; }
  u64 inf() const { return u64(2 * bias + 1) << frac_bits; }
};
constexpr Format kSingle{24, -126, 127, 23, 127, 31};
constexpr Format kDouble{53, -1022, 1023, 52, 1023, 63};
const Format& format(Length l) {
  return l == Length::real32 ? kSingle : kDouble;
}

int clz64(u64 x) {
  return __builtin_clzll(x);
}  // x != 0

double to_double(u64 b) {
  double d;
  std::memcpy(&d, &b, sizeof d);
  return d;
}
u64 from_double(double d) {
  u64 b;
  std::memcpy(&b, &d, sizeof b);
  return b;
}
float to_float(u64 b) {
  const auto w = std::uint32_t(b);
  float f;
  std::memcpy(&f, &w, sizeof f);
  return f;
}
u64 from_float(float f) {
  std::uint32_t w;
  std::memcpy(&w, &f, sizeof w);
  return w;
}

bool is_nan64(u64 b) {
  return (b & kExp64) == kExp64 && (b & kFrac64) != 0;
}
bool not_finite64(u64 b) {
  return (b & kExp64) == kExp64;
}

// A binary64 pattern taken apart: finite values are sig * 2^exp, sig != 0.
enum class Kind : std::uint8_t { zero, finite, inf, nan };
struct Unpacked {
  Kind kind;
  bool sign;
  int exp;
  u64 sig;
};

Unpacked unpack(u64 b) {
  const bool s = b >> 63;
  const int e = int((b >> 52) & 0x7FF);
  const u64 f = b & kFrac64;
  if (e == 0x7FF) return {f ? Kind::nan : Kind::inf, s, 0, 0};
  if (e == 0) return f ? Unpacked{Kind::finite, s, -1074, f} : Unpacked{Kind::zero, s, 0, 0};
  return {Kind::finite, s, e - 1075, f | (u64(1) << 52)};
}

// IEEE rounding (754-1985 section 4): whether the kept part moves away from zero by one unit, given
// its lowest bit, the first dropped bit and whether anything below that is nonzero.
bool round_up(Rounding m, bool sign, bool odd, bool half, bool rest) {
  switch (m) {
    case Rounding::nearest:
      return half && (rest || odd);  // ties to even
    case Rounding::zero:
      return false;
    case Rounding::plus:
      return !sign && (half || rest);
    case Rounding::minus:
      return sign && (half || rest);
  }
  return false;
}

struct Packed {
  u64 bits;  // in the format (a REAL32 pattern in the low 32 bits for kSingle)
  bool overflow;
};

u64 overflowed(bool sign, const Format& f, Rounding m) {
  // IEEE 754 section 7.3: nearest gives Inf; the directed modes give the largest finite value
  // unless they round away from zero.
  const bool to_inf =
      m == Rounding::nearest || (m == Rounding::plus && !sign) || (m == Rounding::minus && sign);
  return (sign ? f.sign() : 0) | (to_inf ? f.inf() : f.inf() - 1);
}

// Round (sig + d) * 2^exp, 0 <= d < 1 and d > 0 exactly when sticky, to the format: the one
// rounding every result goes through (denormals and overflow included). sig != 0.
Packed round_pack(bool sign, int exp, u64 sig, bool sticky, const Format& f, Rounding m) {
  const int lz = clz64(sig);
  sig <<= lz;
  exp -= lz;                                             // the leading bit is now bit 63
  const int lead = exp + 63;                             // its weight
  int lsb = std::max(lead, f.emin) - (f.precision - 1);  // the result's last place
  const int drop = lsb - exp;                            // >= 64 - precision >= 11
  u64 keep = drop >= 64 ? 0 : sig >> drop;
  bool half = false, rest = true;
  if (drop <= 64) {
    half = (sig >> (drop - 1)) & 1;
    rest = (sig & ((u64(1) << (drop - 1)) - 1)) != 0;
  }
  keep += round_up(m, sign, keep & 1, half, rest || sticky);
  if (keep >> f.precision) {  // rounded up to the next power of two
    keep >>= 1;
    ++lsb;
  }
  const u64 s = sign ? f.sign() : 0;
  const u64 hidden = u64(1) << (f.precision - 1);
  if (keep < hidden) return {s | keep, false};  // denormal or zero (lsb is the format's minimum)
  const int e = lsb + f.precision - 1;
  if (e > f.emax) return {overflowed(sign, f, m), true};
  return {s | u64(e + f.bias) << f.frac_bits | (keep - hidden), false};
}

// An exact intermediate result: (sig + d) * 2^exp as in round_pack; zero when sig == 0.
struct Exact {
  bool sign;
  int exp;
  u64 sig;
  bool sticky;
};

// Shift a nonzero sig left until its leading bit is bit `to`.
void normalize(u64& sig, int& exp, int to) {
  const int n = clz64(sig) - (63 - to);
  sig <<= n;
  exp -= n;
}

// Exact sum of two finite nonzero values. Each is first placed with its leading bit at bit 62 (so
// at least 9 zero bits below a 53-bit significand); the smaller is shifted into place with a
// sticky bit for what falls off. A sticky subtrahend takes one unit more from the difference and
// leaves the sticky bit set: the exact difference then lies strictly inside that last unit.
Exact exact_sum(Unpacked a, Unpacked b) {
  normalize(a.sig, a.exp, 62);
  normalize(b.sig, b.exp, 62);
  if (a.exp < b.exp || (a.exp == b.exp && a.sig < b.sig)) std::swap(a, b);
  const int d = a.exp - b.exp;
  const u64 small = d >= 64 ? 0 : b.sig >> d;
  const bool sticky = d >= 64 || (b.sig & ((u64(1) << d) - 1)) != 0;
  if (a.sign == b.sign) return {a.sign, a.exp, a.sig + small, sticky};
  return {a.sign, a.exp, a.sig - small - (sticky ? 1 : 0), sticky};
}

Exact exact_product(const Unpacked& a, const Unpacked& b) {
  const u128 p = u128(a.sig) * b.sig;
  const u64 hi = u64(p >> 64);
  if (hi == 0) return {a.sign != b.sign, a.exp + b.exp, u64(p), false};
  const int s = 64 - clz64(hi);
  const bool sticky = (p & ((u128(1) << s) - 1)) != 0;
  return {a.sign != b.sign, a.exp + b.exp + s, u64(p >> s), sticky};
}

// With both significands in [2^52, 2^53), (a << 64) / b lies in (2^63, 2^65): 64 or 65 bits.
Exact exact_quotient(Unpacked a, Unpacked b) {
  normalize(a.sig, a.exp, 52);
  normalize(b.sig, b.exp, 52);
  const u128 n = u128(a.sig) << 64;
  u128 q = n / b.sig;
  bool sticky = n % b.sig != 0;
  int exp = a.exp - b.exp - 64;
  if (q >> 64) {
    sticky = sticky || (q & 1);
    q >>= 1;
    ++exp;
  }
  return {a.sign != b.sign, exp, u64(q), sticky};
}

// Square root of a positive finite value: floor(sqrt(M)) of a 113- or 114-bit M = sig << k with an
// even exponent left, by the bit-by-bit method; a nonzero remainder is the sticky bit.
Exact exact_sqrt(Unpacked a) {
  normalize(a.sig, a.exp, 52);
  const int k = ((a.exp - 60) & 1) ? 61 : 60;
  u128 op = u128(a.sig) << k, root = 0, one = u128(1) << 126;
  while (one > op) one >>= 2;
  while (one != 0) {
    if (op >= root + one) {
      op -= root + one;
      root = (root >> 1) + one;
    } else {
      root >>= 1;
    }
    one >>= 2;
  }
  return {false, (a.exp - k) / 2, u64(root), op != 0};
}

// IEEE remainder x - n*y, n = x/y rounded to nearest even (occam's REAL REM, and what t4 computes
// with remainder()), of finite nonzero values; it is exact. q: the low 64 bits of |n|.
Exact exact_remainder(Unpacked x, Unpacked y, u64& q) {
  normalize(x.sig, x.exp, 52);
  normalize(y.sig, y.exp, 52);
  q = 0;
  if (x.exp < y.exp) {  // |x| < |y|: n is 0, or 1 when |x| > |y|/2
    if (x.exp + 1 == y.exp && x.sig > y.sig) {
      q = 1;
      return {!x.sign, x.exp, 2 * y.sig - x.sig, false};
    }
    return {x.sign, x.exp, x.sig, false};
  }
  u64 r = x.sig;  // long division, one quotient bit per place of exponent difference
  for (int i = x.exp - y.exp; i >= 0; --i) {
    if (r >= y.sig) {
      r -= y.sig;
      q |= 1;
    }
    if (i > 0) {
      r <<= 1;
      q <<= 1;
    }
  }
  bool sign = x.sign;
  if (2 * r > y.sig || (2 * r == y.sig && (q & 1))) {
    r = y.sig - r;
    sign = !sign;
    ++q;
  }
  return {sign, y.exp, r, false};
}

// The exact REAL64 pattern of a register's value (a REAL32 value widens exactly; NaN fractions
// move up 29 places, as t4's fp_r32tor64 keeps them).
u64 as_real64(const Register& r) {
  if (r.length == Length::real64 || r.unrounded) return r.bits;
  const auto w = std::uint32_t(r.bits);
  const u64 s = u64(w >> 31) << 63;
  const int e = int((w >> 23) & 0xFF);
  const u64 f = w & 0x7FFFFF;
  if (e == 0xFF) return s | kExp64 | f << 29;
  if (e == 0) return f ? round_pack(s != 0, -149, f, false, kDouble, Rounding::nearest).bits : s;
  return s | u64(e - 127 + 1023) << 52 | f << 29;
}

Register make(Length l, u64 bits) {
  return {bits, l, false};
}
Register canonical(const Register& r);
// A REAL64 pattern as a register of length l (truncated if it does not fit a REAL32).
Register in_length(Length l, u64 bits) {
  return l == Length::real64 ? make(l, bits) : canonical({bits, Length::real32, true});
}

// A REAL64 NaN in a register of length l. A REAL32 NaN keeps the top 23 fraction bits; should
// they all be zero (a REAL64 NaN in a REAL32 operation, undefined by the CWG) it takes the
// conversion NaN's fraction, so that it stays a NaN.
Register nan_in(Length l, u64 nan) {
  if (l == Length::real64) return make(l, nan);
  u64 f = (nan & kFrac64) >> 29;
  if (f == 0) f = (kNanConversion & kFrac64) >> 29;
  return make(l, (nan >> 63) << 31 | 0x7F800000 | f);
}

Register inf_in(Length l, bool sign) {
  const Format& f = format(l);
  return make(l, (sign ? f.sign() : 0) | f.inf());
}
Register zero_in(Length l, bool sign) {
  return make(l, sign ? format(l).sign() : 0);
}

Register rounded(const Exact& e, Length l, Rounding m, bool& error) {
  const Packed p = round_pack(e.sign, e.exp, e.sig, e.sticky, format(l), m);
  error = error || p.overflow;
  return make(l, p.bits);
}

// What a store writes for a register: an unrounded REAL32 is truncated (toward zero; for values
// in REAL32 range this is t4's fp_norounddb bit for bit); other registers are their own value.
// Every operation but the four arithmetic ones sees a register through this.
Register canonical(const Register& r) {
  if (!r.unrounded) return r;
  const Unpacked u = unpack(r.bits);
  switch (u.kind) {
    case Kind::nan:
      return nan_in(Length::real32, r.bits);
    case Kind::inf:
      return inf_in(Length::real32, u.sign);
    case Kind::zero:
      return zero_in(Length::real32, u.sign);
    case Kind::finite:
      break;
  }
  return make(Length::real32,
              round_pack(u.sign, u.exp, u.sig, false, kSingle, Rounding::zero).bits);
}

// The NaN an operation with a NaN operand returns (t4 fparithmetic.c db_add .. sn_div, the rule of
// Notebook.txt "Not-a-Number Arithmetic"): the NaN operand, or of two the one with the larger
// fraction (FB on a tie). FB - FA returns FA's NaN negated; FB * FA and FB / FA give the NaN the
// sign of the product. The NaN is returned as it is (a signalling NaN is not quietened).
u64 propagate_nan(Arith op, u64 fb, u64 fa) {
  if (op == Arith::sub) fa ^= kSign64;
  const bool nb = is_nan64(fb), na = is_nan64(fa);
  u64 r = nb && (!na || (fb & kFrac64) >= (fa & kFrac64)) ? fb : fa;
  if (op == Arith::mul || op == Arith::div) r = (r & ~kSign64) | ((fb ^ fa) & kSign64);
  return r;
}

template <typename T>
T host_op(Arith op, T x, T y) {
  switch (op) {
    case Arith::add:
      return x + y;
    case Arith::sub:
      return x - y;
    case Arith::mul:
      return x * y;
    case Arith::div:
      return x / y;
  }
  return x;
}

// FB op FA, finite nonzero operands, round-to-nearest on the host: one IEEE operation in the
// result's format. Only where both operands are exactly values of that format.
Register host_arith(Arith op, const Register& rb, const Register& ra, bool& error) {
  u64 bits;
  if (ra.length == Length::real64) {
    bits = from_double(host_op(op, to_double(as_real64(rb)), to_double(as_real64(ra))));
  } else {
    bits = from_float(host_op(op, to_float(rb.bits), to_float(ra.bits)));
  }
  const u64 inf = format(ra.length).inf();
  error = error || (bits & inf) == inf;  // overflow: finite operands gave Inf
  return make(ra.length, bits);
}

// Results fixed by the IEEE special cases (an infinite or zero operand) and the T800's invalid
// operations, or nothing for two finite nonzero operands. b is FB, a is FA (negated for sub).
bool special_sum(const Unpacked& b, const Unpacked& a, Length l, Rounding m, bool& error,
                 Register& r) {
  if (b.kind == Kind::inf && a.kind == Kind::inf && b.sign != a.sign) {
    error = true;  // t4 db_add, db_sub: opposite infinities added
    r = nan_in(l, kNanAddOppositeInf);
  } else if (b.kind == Kind::inf || a.kind == Kind::inf) {
    r = inf_in(l, b.kind == Kind::inf ? b.sign : a.sign);
  } else if (b.kind == Kind::zero && a.kind == Kind::zero) {
    // IEEE 754 section 6.3: +0 for x + (-x) except -0 when rounding toward minus.
    r = zero_in(l, b.sign == a.sign ? b.sign : m == Rounding::minus);
  } else if (b.kind == Kind::zero || a.kind == Kind::zero) {
    const Unpacked& x = b.kind == Kind::zero ? a : b;  // rounds an unrounded REAL32 operand
    r = rounded({x.sign, x.exp, x.sig, false}, l, m, error);
  } else {
    return false;
  }
  return true;
}

bool special_product(const Unpacked& b, const Unpacked& a, Length l, bool& error, Register& r) {
  const bool sign = b.sign != a.sign;
  const bool inf = b.kind == Kind::inf || a.kind == Kind::inf;
  const bool zero = b.kind == Kind::zero || a.kind == Kind::zero;
  if (inf && zero) {
    error = true;  // t4 db_mul: zero times infinity
    r = nan_in(l, kNanMulZeroByInf);
  } else if (inf) {
    r = inf_in(l, sign);
  } else if (zero) {
    r = zero_in(l, sign);
  } else {
    return false;
  }
  return true;
}

bool special_quotient(const Unpacked& b, const Unpacked& a, Length l, bool& error, Register& r) {
  const bool sign = b.sign != a.sign;
  if (b.kind == Kind::zero && a.kind == Kind::zero) {
    error = true;  // t4 db_div
    r = nan_in(l, kNanDivZeroByZero);
  } else if (b.kind == Kind::inf && a.kind == Kind::inf) {
    error = true;
    r = nan_in(l, kNanDivInfByInf);
  } else if (b.kind == Kind::inf) {
    r = inf_in(l, sign);
  } else if (a.kind == Kind::inf || b.kind == Kind::zero) {
    r = zero_in(l, sign);
  } else if (a.kind == Kind::zero) {
    error = true;  // division by zero: a correctly signed infinity (Notebook.txt)
    r = inf_in(l, sign);
  } else {
    return false;
  }
  return true;
}

// FB op FA in FA's length (the CWG requires both lengths equal; mixed lengths compute with both
// values and round to FA's). Unrounded REAL32 operands (fpunoround) take part with all their bits.
Register arith(Arith op, const Register& rb, const Register& ra, Rounding m, bool& error) {
  const Length l = ra.length;
  const u64 fb = as_real64(rb), fa = as_real64(ra);
  if (is_nan64(fb) || is_nan64(fa)) {
    error = true;  // t4: a NaN operand sets the FP error flag
    return nan_in(l, propagate_nan(op, fb, fa));
  }
  const Unpacked b = unpack(fb);
  Unpacked a = unpack(fa);
  // Notebook.txt (T800 datasheet): "the flag is set if an input to a fp operation is infinite".
  if (b.kind == Kind::inf || a.kind == Kind::inf) error = true;
  if (op == Arith::sub) a.sign = !a.sign;
  Register r;
  if (op == Arith::add || op == Arith::sub) {
    if (special_sum(b, a, l, m, error, r)) return r;
  } else if (op == Arith::mul) {
    if (special_product(b, a, l, error, r)) return r;
  } else if (special_quotient(b, a, l, error, r)) {
    return r;
  }
  const bool exact_operands =
      l == Length::real64 || (rb.length == Length::real32 && !rb.unrounded && !ra.unrounded);
  if (m == Rounding::nearest && exact_operands) return host_arith(op, rb, ra, error);
  Exact e;
  if (op == Arith::mul) {
    e = exact_product(b, a);
  } else if (op == Arith::div) {
    e = exact_quotient(b, a);
  } else {
    e = exact_sum(b, a);
    if (e.sig == 0) return zero_in(l, m == Rounding::minus);  // exact cancellation (IEEE 6.3)
  }
  return rounded(e, l, m, error);
}

// FA * 2^k, rounded (denormal results) (t4 fp_mulby2db .. fp_expdec32db via ldexp).
Register scaled(const Register& ra, int k, Rounding m, bool& error) {
  const Register x = canonical(ra);
  const Unpacked u = unpack(as_real64(x));
  if (u.kind == Kind::nan || u.kind == Kind::inf) error = true;  // t4 db_unary
  if (u.kind != Kind::finite) return x;
  return rounded({u.sign, u.exp + k, u.sig, false}, x.length, m, error);
}

// fpint: the integral value nearest in the rounding mode, sign kept (IEEE roundToIntegral: -0.3
// gives -0 and, rounding toward minus, +0.3 gives +0; t4's T4_CRTHACKS work around a C library
// that returned -0 there). NaN and Inf are left alone and set the FP error flag (t4 fp_intdb).
Register integral(const Register& ra, Rounding m, bool& error) {
  const Register x = canonical(ra);
  const Unpacked u = unpack(as_real64(x));
  if (u.kind == Kind::nan || u.kind == Kind::inf) error = true;
  if (u.kind != Kind::finite || u.exp >= 0) return x;
  const int drop = -u.exp;
  u64 keep = drop >= 64 ? 0 : u.sig >> drop;
  const bool half = drop <= 64 && ((u.sig >> (drop - 1)) & 1);
  const bool rest = drop > 64 || (u.sig & ((u64(1) << (drop - 1)) - 1)) != 0;
  keep += round_up(m, u.sign, keep & 1, half, rest);
  if (keep == 0) return zero_in(x.length, u.sign);
  return rounded({u.sign, 0, keep, false}, x.length, Rounding::nearest, error);  // exact
}

// Total order of the CWG (t4 fp_gtdb, "ACWG pp.106 B.2.7: binary comparison on total ordering"):
// sign and magnitude of the bit patterns, so NaNs order beyond the infinities; +0 = -0.
bool greater(u64 b, u64 a) {
  const u64 mb = b & ~kSign64, ma = a & ~kSign64;
  if (mb == 0 && ma == 0) return false;
  if ((b ^ a) & kSign64) return !(b & kSign64);
  return (b & kSign64) ? mb < ma : mb > ma;
}
bool equal(u64 b, u64 a) {
  return b == a || ((b | a) & ~kSign64) == 0;
}

// A finite value inside [lo, hi) (t4 fp_chki32db/fp_chki64db: the guards are -2^31 and the
// largest REAL64 below 2^31, -2^63 and the largest below 2^63). Host comparisons are exact.
bool in_range(const Register& r, double lo, double hi) {
  const u64 b = as_real64(canonical(r));
  if (not_finite64(b)) return false;
  const double v = to_double(b);
  return v >= lo && v < hi;
}

}  // namespace

void Fpu::push(const Register& r) {
  fc_ = fb_;
  fb_ = fa_;
  fa_ = r;
}

// Loads. The T800 tracks each register's length (CWG; t4 p.c keeps FAReg.length). Conversions
// from integers round in the mode (only fpi32tor32 can be inexact).
void Fpu::load_single(std::uint32_t bits) {
  push(make(Length::real32, bits));
  done();
}
void Fpu::load_double(std::uint64_t bits) {
  push(make(Length::real64, bits));
  done();
}
void Fpu::load_zero_single() {
  push(zero_in(Length::real32, false));
  done();
}
void Fpu::load_zero_double() {
  push(zero_in(Length::real64, false));
  done();
}

namespace {
Register from_integer(bool negative, u64 magnitude, Length l, Rounding m) {
  if (magnitude == 0) return zero_in(l, false);  // an integer zero is +0 in every mode
  bool unused = false;
  return rounded({negative, 0, magnitude, false}, l, m, unused);
}
u64 magnitude(std::int32_t v) {
  return v < 0 ? u64(0) - u64(std::int64_t(v)) : u64(v);
}
}  // namespace

void Fpu::load_int32_as_real32(std::int32_t v) {
  push(from_integer(v < 0, magnitude(v), Length::real32, rounding_));
  done();
}
void Fpu::load_int32_as_real64(std::int32_t v) {
  push(from_integer(v < 0, magnitude(v), Length::real64, rounding_));
  done();
}
void Fpu::load_bit32_as_real64(std::uint32_t v) {
  push(from_integer(false, v, Length::real64, rounding_));
  done();
}

// fpldnladdsn etc.: FA := FA op memory, FB unchanged (CWG as quoted in tvm ins_float.c). It is one
// instruction, so the rounding mode set before it applies to the operation.
void Fpu::load_add_single(std::uint32_t bits) {
  push(make(Length::real32, bits));
  replace_fa_fb(arith(Arith::add, fb_, fa_, rounding_, error_));
  done();
}
void Fpu::load_add_double(std::uint64_t bits) {
  push(make(Length::real64, bits));
  replace_fa_fb(arith(Arith::add, fb_, fa_, rounding_, error_));
  done();
}
void Fpu::load_mul_single(std::uint32_t bits) {
  push(make(Length::real32, bits));
  replace_fa_fb(arith(Arith::mul, fb_, fa_, rounding_, error_));
  done();
}
void Fpu::load_mul_double(std::uint64_t bits) {
  push(make(Length::real64, bits));
  replace_fa_fb(arith(Arith::mul, fb_, fa_, rounding_, error_));
  done();
}

// Stores pop: FA := FB, FB := FC; FC is undefined (CWG) and keeps its value (as t4 fp_drop).
// A store of the other length (undefined by the CWG) writes the value: exactly when widening,
// truncated when narrowing.
std::uint32_t Fpu::store_single() {
  const bool plain = fa_.length == Length::real32 && !fa_.unrounded;
  const auto bits =
      std::uint32_t(plain ? fa_.bits : in_length(Length::real32, as_real64(fa_)).bits);
  fa_ = fb_;
  fb_ = fc_;
  done();
  return bits;
}
std::uint64_t Fpu::store_double() {
  const u64 bits = as_real64(fa_);
  fa_ = fb_;
  fb_ = fc_;
  done();
  return bits;
}

// fpstnli32: the low 32 bits of the integer floor(FA), two's complement (t4 fp_stnli32db, after
// M. Bruestle, which passes TVS1F; 0 for zero, Inf and NaN). Floor, not truncation: the compiler
// stores INT64 values as fpstnli32 of FA and then of FA / 2^32 (occ21 gen5.c ROUND/TRUNC).
std::uint32_t Fpu::store_int32() {
  const Unpacked u = unpack(as_real64(canonical(fa_)));
  u64 n = 0;
  if (u.kind == Kind::finite && u.exp >= 0) {
    n = u.exp >= 64 ? 0 : u.sig << u.exp;
  } else if (u.kind == Kind::finite) {
    const int drop = -u.exp;
    n = drop >= 64 ? 0 : u.sig >> drop;
    const bool fraction = drop >= 64 || (u.sig & ((u64(1) << drop) - 1)) != 0;
    if (u.sign && fraction) ++n;  // floor of a negative value with a fraction
  }
  if (u.sign) n = u64(0) - n;
  fa_ = fb_;
  fb_ = fc_;
  done();
  return std::uint32_t(n);
}

void Fpu::add() {
  replace_fa_fb(arith(Arith::add, fb_, fa_, rounding_, error_));
  done();
}
void Fpu::sub() {
  replace_fa_fb(arith(Arith::sub, fb_, fa_, rounding_, error_));
  done();
}
void Fpu::mul() {
  replace_fa_fb(arith(Arith::mul, fb_, fa_, rounding_, error_));
  done();
}
void Fpu::div() {
  replace_fa_fb(arith(Arith::div, fb_, fa_, rounding_, error_));
  done();
}

// The remainder. occ21 gen12.c emits "fpremfirst; eqc 0; cj next; loop: fpremstep; cj loop;
// next:", so Areg TRUE from either instruction ends the loop. Like t4 (p.c, fp_remfirstdb) the
// whole remainder is done by fpremfirst, which returns TRUE; fpremstep is never reached then and,
// should a program run it, changes nothing and returns TRUE too (t4 returns FALSE there, which in
// the compiler's loop would never end). FB := the quotient n, as the CWG gives it (tvm
// ins_float.c: defined when the exponents differ by at most 20 (REAL32) or 30 (REAL64); here its
// low 64 bits always), signed as FB / FA; FC keeps its value (t4).
std::uint32_t Fpu::rem_first() {
  const Length l = fa_.length;
  const Register xr = canonical(fb_), yr = canonical(fa_);
  const Unpacked x = unpack(as_real64(xr)), y = unpack(as_real64(yr));
  Register rem, quot = nan_in(l, kNanRemInvalidQuot);
  if (x.kind == Kind::inf || y.kind == Kind::inf) error_ = true;  // t4 fp_remfirstdb
  if (x.kind == Kind::nan || y.kind == Kind::nan) {
    error_ = true;
    rem = nan_in(l, propagate_nan(Arith::add, as_real64(xr), as_real64(yr)));
  } else if (x.kind == Kind::inf) {
    rem = nan_in(l, kNanRemFromInf);
  } else if (y.kind == Kind::zero) {
    error_ = true;
    rem = nan_in(l, kNanRemByZero);
  } else if (x.kind == Kind::zero || y.kind == Kind::inf) {
    rem = in_length(l, as_real64(xr));  // x REM Inf is x
    quot = zero_in(l, x.sign != y.sign);
  } else {
    u64 q = 0;
    const Exact e = exact_remainder(x, y, q);
    bool unused = false;
    rem = e.sig == 0 ? zero_in(l, x.sign) : rounded(e, l, Rounding::nearest, unused);  // exact
    quot = q == 0 ? zero_in(l, x.sign != y.sign)
                  : from_integer(x.sign != y.sign, q, l, Rounding::nearest);
  }
  fa_ = rem;
  fb_ = quot;
  done();
  return 1;
}
std::uint32_t Fpu::rem_step() {
  done();
  return 1;
}

// The square root. occ21 gen8.c emits fpusqrtfirst, 2 (REAL32) or 5 (REAL64) fpusqrtstep and
// fpusqrtlast; as in t4 (p.c, fp_sqrtfirstdb, fp_sqrtlastdb) fpusqrtfirst deals with the invalid
// operands and fpusqrtlast computes the correctly rounded root, rounded in the mode set before it
// (each instruction of the sequence resets the mode). FB and FC, which the chip uses for the
// iteration and leaves undefined (CWG), keep their values.
void Fpu::sqrt_first() {
  fa_ = canonical(fa_);
  const Unpacked u = unpack(as_real64(fa_));
  if (u.kind == Kind::nan) {
    error_ = true;
  } else if (u.kind != Kind::zero && u.sign) {  // sqrt(-0) is -0
    error_ = true;
    fa_ = nan_in(fa_.length, kNanNegativeSqrt);
  }
  done();
}
void Fpu::sqrt_step() {
  done();
}
void Fpu::sqrt_last() {
  const Register x = canonical(fa_);
  const Unpacked u = unpack(as_real64(x));
  if (u.kind == Kind::nan || u.kind == Kind::inf) error_ = true;  // t4 db_unary
  if (u.kind == Kind::finite && u.sign) {
    error_ = true;  // not through sqrt_first: still invalid
    fa_ = nan_in(x.length, kNanNegativeSqrt);
  } else if (u.kind != Kind::finite) {
    fa_ = x;
  } else if (rounding_ == Rounding::nearest && x.length == Length::real64) {
    fa_ = make(x.length, from_double(std::sqrt(to_double(x.bits))));
  } else if (rounding_ == Rounding::nearest) {
    fa_ = make(x.length, from_float(std::sqrt(to_float(x.bits))));
  } else {
    fa_ = rounded(exact_sqrt(u), x.length, rounding_, error_);
  }
  done();
}

// fpuabs: the sign cleared, NaNs included; NaN and Inf set the FP error flag (t4 fp_absdb).
void Fpu::abs() {
  fa_ = canonical(fa_);
  if (not_finite64(as_real64(fa_))) error_ = true;
  fa_.bits &= ~format(fa_.length).sign();
  done();
}
void Fpu::mul_by_2() {
  fa_ = scaled(fa_, 1, rounding_, error_);
  done();
}
void Fpu::div_by_2() {
  fa_ = scaled(fa_, -1, rounding_, error_);
  done();
}
void Fpu::exp_inc32() {
  fa_ = scaled(fa_, 32, rounding_, error_);
  done();
}
void Fpu::exp_dec32() {
  fa_ = scaled(fa_, -32, rounding_, error_);
  done();
}

void Fpu::to_integral() {
  fa_ = integral(fa_, rounding_, error_);
  done();
}

// fprtoi32 leaves the integral value in FA, in FA's length (fpstnli32 then stores it: occ21
// gen11.c); the FP error flag is set when that rounded value is outside INT32. t4 checks the
// operand before rounding and then corrects four boundary cases to the TVS1F results (fp_rtoi32db,
// T4_CRTHACKS): -(2^31 + 2^-21) is an error only rounding toward minus, 2^31 - 2^-22 only rounding
// to nearest or plus. Checking the rounded value gives exactly those results.
void Fpu::real_to_int32() {
  fa_ = integral(fa_, rounding_, error_);
  if (!not_finite64(as_real64(fa_)) && !in_range(fa_, -2147483648.0, 2147483648.0)) {
    error_ = true;
  }
  done();
}
void Fpu::check_int32() {
  if (!in_range(fa_, -2147483648.0, 2147483648.0)) error_ = true;
  done();
}
void Fpu::check_int64() {
  if (!in_range(fa_, -9223372036854775808.0, 9223372036854775808.0)) error_ = true;
  done();
}

// fpur32tor64 is exact; NaN (fraction kept) and Inf set the FP error flag (t4 fp_r32tor64).
void Fpu::real32_to_real64() {
  const u64 v = as_real64(fa_);
  if (not_finite64(v)) error_ = true;
  fa_ = make(Length::real64, v);
  done();
}
// fpur64tor32 rounds in the mode; a NaN becomes the conversion NaN (t4 fp_r64tor32); NaN, Inf and
// overflow set the FP error flag.
void Fpu::real64_to_real32() {
  const Unpacked u = unpack(as_real64(fa_));
  if (u.kind == Kind::nan || u.kind == Kind::inf) error_ = true;
  if (u.kind == Kind::nan) {
    fa_ = nan_in(Length::real32, kNanConversion);
  } else if (u.kind == Kind::inf) {
    fa_ = inf_in(Length::real32, u.sign);
  } else if (u.kind == Kind::zero) {
    fa_ = zero_in(Length::real32, u.sign);
  } else {
    fa_ = rounded({u.sign, u.exp, u.sig, false}, Length::real32, rounding_, error_);
  }
  done();
}
// fpunoround: REAL32 length without rounding. The compiler converts INT64 to REAL32 as
// "fpb32tor64 (low word); fpunoround; fpi32tor64 (high word); fpuexpinc32; fpunoround; [fpurz];
// fpadd" (occ21 code1k.c geni64tor), which is one correct rounding of the 64-bit integer only if
// fpadd sees the unrounded values; a truncating fpunoround (as in t4) would round twice. So the
// register keeps the REAL64 value for arithmetic; stores and the other operations see it
// truncated, which for values in REAL32 range is t4's fp_norounddb. (An inference from the
// compiler's code: the CWG text was not at hand.)
void Fpu::no_round() {
  fa_ = {as_real64(fa_), Length::real32, true};
  done();
}

void Fpu::rev() {
  std::swap(fa_, fb_);
  done();
}
void Fpu::dup() {
  push(fa_);
  done();
}

// The error flag (t4 p.c fpuseterr, fpuclrerr, fptesterr, fpchkerr; CWG as quoted in tvm
// ins_float.c: fpchkerr is "error_flag' = error_flag OR fp_error_flag" and leaves the FP flag).
void Fpu::set_error() {
  error_ = true;
  done();
}
void Fpu::clear_error() {
  error_ = false;
  done();
}
std::uint32_t Fpu::test_error() {
  const std::uint32_t r = error_ ? 0 : 1;
  error_ = false;
  done();
  return r;
}
bool Fpu::check_error() {
  done();
  return error_;
}
// Notebook.txt (T800 datasheet): "At the end of all FP operations the rounding mode is reset to
// Round-To-Nearest, except the rounding mode setting operations" (t4 p.c ResetRounding).
void Fpu::set_rounding(Rounding m) {
  rounding_ = m;
}

// Comparisons set the FP error flag when either operand is Inf or NaN ("ACWG pp.158: checks (Inf U
// NaN) membership", t4 fp_gtdb). fpgt and fpeq pop both (FA := FC, t4 fp_pop2db); fpordered,
// fpnan and fpnotfinite pop nothing (occ21 gen8.c pops after them only for non-transputer targets).
std::uint32_t Fpu::gt() {
  const u64 b = as_real64(canonical(fb_)), a = as_real64(canonical(fa_));
  if (not_finite64(b) || not_finite64(a)) error_ = true;
  fa_ = fc_;
  fb_ = fc_;
  done();
  return greater(b, a) ? 1 : 0;
}
std::uint32_t Fpu::eq() {
  const u64 b = as_real64(canonical(fb_)), a = as_real64(canonical(fa_));
  if (not_finite64(b) || not_finite64(a)) error_ = true;
  fa_ = fc_;
  fb_ = fc_;
  done();
  return equal(b, a) ? 1 : 0;
}
std::uint32_t Fpu::ordered() {
  const bool nan = is_nan64(as_real64(canonical(fb_))) || is_nan64(as_real64(canonical(fa_)));
  done();
  return nan ? 0 : 1;
}
std::uint32_t Fpu::is_nan() {
  const bool nan = is_nan64(as_real64(canonical(fa_)));
  done();
  return nan ? 1 : 0;
}
std::uint32_t Fpu::not_finite() {
  const bool r = not_finite64(as_real64(canonical(fa_)));
  done();
  return r ? 1 : 0;
}

}  // namespace t800::iss
