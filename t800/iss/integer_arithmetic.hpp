// The integer unit's arithmetic as plain functions (CWG, "arithmetic" and "long arithmetic"; the
// T800's bit operations from TN26/the T800 datasheet): 32-bit words, two's complement, the
// overflow each checked operation reports to the Error flag.
#pragma once

#include <cstdint>

#include "t800/iss/machine_words.hpp"

namespace t800::iss {

struct Checked {
  Word value;
  bool overflow;
};
struct DoubleWord {
  Word low, high;
};

// Inline: adc and add are among the commonest instructions.
inline Checked checked_exact(std::int64_t exact) {
  return {Word(std::uint64_t(exact)), exact < INT32_MIN || exact > INT32_MAX};
}
inline Checked checked_add(Word b, Word a) {  // b + a
  return checked_exact(std::int64_t(std::int32_t(b)) + std::int32_t(a));
}
inline Checked checked_sub(Word b, Word a) {  // b - a
  return checked_exact(std::int64_t(std::int32_t(b)) - std::int32_t(a));
}
inline Checked checked_mul(Word b, Word a) {  // b * a
  return checked_exact(std::int64_t(std::int32_t(b)) * std::int32_t(a));
}
// div and rem: b / a, b rem a truncating toward zero; a = 0 (and MinInt / -1) is an error.
Checked divide(Word b, Word a);
Checked remainder(Word b, Word a);

// Long arithmetic (CWG): carries and borrows in bit 0 of a third operand.
Checked long_add(Word b, Word a, Word carry);          // ladd, overflow checked
DoubleWord long_sum(Word b, Word a, Word carry);       // lsum: low = sum, high = carry out
Checked long_sub(Word b, Word a, Word borrow);         // lsub
DoubleWord long_diff(Word b, Word a, Word borrow);     // ldiff: low = difference, high = borrow
DoubleWord long_multiply(Word b, Word a, Word carry);  // lmul: b * a + carry
// ldiv: (high:low) / divisor, quotient in low and remainder in high; overflow when high >= divisor.
struct LongDivide {
  Word quotient, remainder;
  bool overflow;
};
LongDivide long_divide(Word high, Word low, Word divisor);
DoubleWord long_shift_left(Word high, Word low, Word places);   // lshl
DoubleWord long_shift_right(Word high, Word low, Word places);  // lshr
// norm: shifts high:low left until bit 63 is set; `places` 64 for a zero value.
struct Normalised {
  Word low, high, places;
};
Normalised normalise(Word high, Word low);
Word shift_left(Word value, Word places);   // shl: 0 for 32 places or more
Word shift_right(Word value, Word places);  // shr, logical
// fmul: fractional multiply of two fixed-point fractions (bit 31 the sign), rounded.
Checked fractional_multiply(Word b, Word a);

// The T800's additions: CRC steps, bit counts, bit reversal (T800 datasheet).
Word crc_word(Word crc, Word data, Word generator);
Word crc_byte(Word crc, Word data, Word generator);  // data in the most significant byte
Word bit_count(Word value);
Word bit_reverse(Word value);
Word bit_reverse_bits(Word value, Word bits);  // the low `bits` bits reversed

// The bit number of the highest bit set (0 for 0 or 1): the datasheet's `b` in cycle figures.
inline int highest_bit(Word value) {
  return value ? 31 - __builtin_clz(value) : 0;
}

}  // namespace t800::iss
