// The T414's floating-point support operations (t414_float_support.hpp): IEEE single-length
// numbers taken apart and put together again on the integer stack.
#include "t800/iss/t414_float_support.hpp"

#include <cstdint>

namespace t800::iss {

using isa::Op;

namespace {

constexpr Word kSignBit = 0x80000000u;
constexpr Word kExponentField = 0x7F800000u;
constexpr Word kFractionField = 0x007FFFFFu;
constexpr Word kInfinity = 0x7F800000u;  // +Inf, exponent all ones and a zero fraction
constexpr int kFractionBits = 23;
constexpr std::int32_t kMaxExponent = 255;  // the exponent of infinities and NaNs
constexpr int kWordBits = 32;

// unpacksn's type codes (CWG): zero, a finite number (normal or denormal), infinity, NaN.
constexpr Word kZero = 0, kFinite = 1, kInfinite = 2, kNotANumber = 3;

// unpacksn. The fraction is left-justified (its field moved up 8 places, bit 31 free) so that the
// integer unit's long arithmetic and `norm` can work on it; a normal number gets its implied
// leading one at bit 31, a denormal none and the exponent 1 it is scaled by. The sign bit is
// dropped. C becomes 4 * B + type, so two unpacks in a row leave both operands' types in C.
void unpack(Word& a, Word& b, Word& c) {
  const Word packed = a;
  const Word exponent = (packed & kExponentField) >> kFractionBits;
  const Word fraction = packed & kFractionField;
  Word type = kFinite;
  Word unpacked_exponent = exponent;
  Word unpacked_fraction = fraction << 8;
  if (exponent == 0 && fraction == 0) {
    type = kZero;
  } else if (exponent == Word(kMaxExponent)) {
    type = fraction == 0 ? kInfinite : kNotANumber;
  } else if (exponent == 0) {
    unpacked_exponent = 1;  // denormal: 0.f * 2^(1 - 127)
  } else {
    unpacked_fraction |= kSignBit;  // normal: 1.f * 2^(e - 127)
  }
  c = 4 * b + type;
  b = unpacked_exponent;
  a = unpacked_fraction;
}

// postnormsn, after `norm` shifted B:A (fraction:guard) left by C places so that B's bit 31 is
// set: the exponent becomes workspace word 0 minus C, in the machine's 32-bit arithmetic.
// - 256 or more: too large; C := 255 and roundsn delivers infinity.
// - 1 ... 255: a normal number; C := the exponent.
// - 0 or below: a denormal. The fraction moves right by 1 - exponent places (a denormal is scaled
//   as exponent 1) and the exponent becomes 0; what leaves the guard word's bottom is kept as a
//   sticky bit by ORing the old guard word into the new one (only its being non-zero matters to
//   roundsn).
// - -32 or below: even the leading bit would fall below the guard word's top, so the number is
//   less than half the smallest denormal and rounds to zero: A, B and C := 0 (as the chip does,
//   pahihu/t4 p.c after M. Bruestle).
void post_normalise(Word& a, Word& b, Word& c, Word temp) {
  const std::int32_t exponent = std::int32_t(temp - c);
  if (exponent <= -kWordBits) {
    a = b = c = 0;
  } else if (exponent > kMaxExponent) {
    c = Word(kMaxExponent);
  } else if (exponent <= 0) {
    const int places = 1 - exponent;  // 1 ... 32
    const std::uint64_t wide = (std::uint64_t(b) << 32 | a) >> places;
    a = Word(wide) | a;
    b = Word(wide >> 32);
    c = 0;
  } else {
    c = Word(exponent);
  }
}

// roundsn. B's bits 30..8 are the fraction field (bit 31 is the implied one, dropped), bit 7 the
// round bit, bits 6..0 and the whole guard word A what lies below (sticky). The exponent from C
// goes above the fraction (C's bit 8 reaches the sign bit); the sum is rounded to nearest, ties
// to the even result, and a carry out of the fraction raises the exponent, which also rounds the
// largest finite magnitude up to infinity and the largest denormal up to the smallest normal.
// An exponent of 255 or more gives infinity. Afterwards B holds the result too and C what was
// above C's 9-bit field; on overflow C := B * 2 (pahihu/t4 p.c, after M. Bruestle).
void round_single(Word& a, Word& b, Word& c) {
  if (std::int32_t(c) >= kMaxExponent) {
    a = kInfinity;
    c = b << 1;
    return;
  }
  Word packed = ((c & 0x1FFu) << kFractionBits) | ((b & 0x7FFFFF00u) >> 8);
  const bool round_bit = (b & 0x80u) != 0;
  const bool sticky = (a | (b & 0x7Fu)) != 0;
  if (round_bit && (sticky || (packed & 1u))) packed += 1;
  a = packed;
  b = packed;
  c >>= 9;
}

}  // namespace

bool is_t414_float_support(Op op) {
  switch (op) {
    case Op::unpacksn:
    case Op::postnormsn:
    case Op::roundsn:
    case Op::ldinf:
    case Op::cflerr:
      return true;
    default:
      return false;
  }
}

bool t414_float_support(Op op, Word& a, Word& b, Word& c, Word temp) {
  switch (op) {
    case Op::unpacksn:
      unpack(a, b, c);
      return false;
    case Op::postnormsn:
      post_normalise(a, b, c, temp);
      return false;
    case Op::roundsn:
      round_single(a, b, c);
      return false;
    case Op::ldinf:
      c = b;
      b = a;
      a = kInfinity;
      return false;
    case Op::cflerr:
      // Error if A is an infinity or a NaN (its exponent all ones); the stack is unchanged.
      return (a & kExponentField) == kExponentField;
    default:
      return false;
  }
}

}  // namespace t800::iss
