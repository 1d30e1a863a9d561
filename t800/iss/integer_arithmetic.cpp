#include "t800/iss/integer_arithmetic.hpp"

namespace t800::iss {

namespace {
using S64 = std::int64_t;
using U64 = std::uint64_t;
S64 s(Word w) {
  return std::int32_t(w);
}
}  // namespace

Checked divide(Word b, Word a) {
  if (a == 0 || (b == kMostNeg && a == 0xFFFFFFFFu)) return {b, true};
  return {Word(s(b) / s(a)), false};
}

Checked remainder(Word b, Word a) {
  if (a == 0) return {b, true};
  if (b == kMostNeg && a == 0xFFFFFFFFu) return {0, false};  // MinInt REM -1 = 0 (CWG)
  return {Word(s(b) % s(a)), false};
}

Checked long_add(Word b, Word a, Word carry) {
  return checked_exact(s(b) + s(a) + S64(carry & 1));
}

DoubleWord long_sum(Word b, Word a, Word carry) {
  const U64 sum = U64(b) + U64(a) + (carry & 1);
  return {Word(sum), Word(sum >> 32)};
}

Checked long_sub(Word b, Word a, Word borrow) {
  return checked_exact(s(b) - s(a) - S64(borrow & 1));
}

DoubleWord long_diff(Word b, Word a, Word borrow) {
  const U64 diff = U64(b) - U64(a) - (borrow & 1);
  return {Word(diff), Word((diff >> 32) & 1)};
}

DoubleWord long_multiply(Word b, Word a, Word carry) {
  const U64 product = U64(b) * U64(a) + carry;
  return {Word(product), Word(product >> 32)};
}

LongDivide long_divide(Word high, Word low, Word divisor) {
  if (high >= divisor) return {low, high, true};
  const U64 dividend = (U64(high) << 32) | low;
  return {Word(dividend / divisor), Word(dividend % divisor), false};
}

DoubleWord long_shift_left(Word high, Word low, Word places) {
  const U64 v = (U64(high) << 32) | low;
  const U64 r = places >= 64 ? 0 : v << places;
  return {Word(r), Word(r >> 32)};
}

DoubleWord long_shift_right(Word high, Word low, Word places) {
  const U64 v = (U64(high) << 32) | low;
  const U64 r = places >= 64 ? 0 : v >> places;
  return {Word(r), Word(r >> 32)};
}

Normalised normalise(Word high, Word low) {
  U64 v = (U64(high) << 32) | low;
  if (v == 0) return {0, 0, 64};
  Word places = 0;
  while (!(v >> 63)) {
    v <<= 1;
    ++places;
  }
  return {Word(v), Word(v >> 32), places};
}

Word shift_left(Word value, Word places) {
  return places >= 32 ? 0 : value << places;
}
Word shift_right(Word value, Word places) {
  return places >= 32 ? 0 : value >> places;
}

// Fractions with bit 31 the sign and 31 fraction bits: the product of two is the 62-bit product
// shifted right 31 places, rounded to nearest (CWG: fmul rounds; MinInt * MinInt overflows).
Checked fractional_multiply(Word b, Word a) {
  if (a == kMostNeg && b == kMostNeg) return {a, true};
  const S64 product = s(a) * s(b);
  const S64 rounded = (product + (S64(1) << 30)) >> 31;
  return {Word(U64(rounded)), false};
}

// CRC (T800 datasheet, crcword/crcbyte): the CRC is shifted left one bit per data bit, the data's
// top bit shifted in below it; when a bit falls out of the top, the generator is XORed in.
namespace {
Word crc_bits(Word crc, Word data, Word generator, int bits) {
  for (int k = 0; k < bits; ++k) {
    const bool out = crc >> 31;
    crc = (crc << 1) | (data >> 31);
    data <<= 1;
    if (out) crc ^= generator;
  }
  return crc;
}
}  // namespace

Word crc_word(Word crc, Word data, Word generator) {
  return crc_bits(crc, data, generator, 32);
}
Word crc_byte(Word crc, Word data, Word generator) {
  return crc_bits(crc, data, generator, 8);
}

Word bit_count(Word value) {
  Word n = 0;
  for (; value; value &= value - 1) ++n;
  return n;
}

Word bit_reverse(Word value) {
  Word r = 0;
  for (int k = 0; k < 32; ++k) r |= ((value >> k) & 1u) << (31 - k);
  return r;
}

Word bit_reverse_bits(Word value, Word bits) {
  if (bits == 0) return 0;
  if (bits >= 32) return bit_reverse(value);
  return bit_reverse(value) >> (32 - bits);
}

}  // namespace t800::iss
