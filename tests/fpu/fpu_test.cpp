// The T800 FPU (t800/iss/fpu.hpp). Every expected value is worked out by hand from the binary
// expansion and the IEEE 754 rules (the working is in the comments), or is a T800 constant quoted
// from pahihu/t4 fparithmetic.c, or follows from the code the INMOS occam compiler emits
// (concurrency/kroc tools/occ21); none was taken from running this code.
#include <gtest/gtest.h>

#include <cstdint>
#include <limits>

#include "t800/iss/fpu.hpp"

namespace {

using t800::iss::Fpu;
using R = Fpu::Rounding;
using L = Fpu::Length;
using Op = void (Fpu::*)();

// FB op FA on REAL32 (sn) or REAL64 (db) operands, in rounding mode m; the result in FA.
std::uint32_t sn(Op op, std::uint32_t fb, std::uint32_t fa, R m = R::nearest,
                 bool* error = nullptr) {
  Fpu f;
  f.load_single(fb);
  f.load_single(fa);
  f.set_rounding(m);
  (f.*op)();
  if (error) *error = f.error();
  EXPECT_EQ(f.fa().length, L::real32);
  return f.store_single();
}
std::uint64_t db(Op op, std::uint64_t fb, std::uint64_t fa, R m = R::nearest,
                 bool* error = nullptr) {
  Fpu f;
  f.load_double(fb);
  f.load_double(fa);
  f.set_rounding(m);
  (f.*op)();
  if (error) *error = f.error();
  EXPECT_EQ(f.fa().length, L::real64);
  return f.store_double();
}
// op on FA alone.
std::uint32_t sn1(Op op, std::uint32_t x, R m = R::nearest, bool* error = nullptr) {
  Fpu f;
  f.load_single(x);
  f.set_rounding(m);
  (f.*op)();
  if (error) *error = f.error();
  return f.store_single();
}
std::uint64_t db1(Op op, std::uint64_t x, R m = R::nearest, bool* error = nullptr) {
  Fpu f;
  f.load_double(x);
  f.set_rounding(m);
  (f.*op)();
  if (error) *error = f.error();
  return f.store_double();
}
bool error_of_sn(Op op, std::uint32_t fb, std::uint32_t fa, R m = R::nearest) {
  bool e = false;
  sn(op, fb, fa, m, &e);
  return e;
}

// REAL32 and REAL64 constants, each from its fields (sign, biased exponent, fraction).
constexpr std::uint32_t kOneF = 0x3F800000, kTwoF = 0x40000000, kThreeF = 0x40400000;
constexpr std::uint32_t kInfF = 0x7F800000, kMaxF = 0x7F7FFFFF;  // exponent 254, fraction all ones
constexpr std::uint64_t kOne = 0x3FF0000000000000, kTwo = 0x4000000000000000;
constexpr std::uint64_t kThree = 0x4008000000000000, kInf = 0x7FF0000000000000;
constexpr std::uint64_t kMax = 0x7FEFFFFFFFFFFFFF;

// 1/3 = 0.010101...b = 1.0101...b * 2^-2 (biased exponent 125 = 0x7D for REAL32, 1021 = 0x3FD for
// REAL64). REAL32: the 23 fraction bits are 0101...010 (0x2AAAAA), then 1 and more: above half, so
// nearest and plus round up to 0x2AAAAB; zero and minus keep 0x2AAAAA. For -1/3 plus and minus
// swap. REAL64: the 52 fraction bits 0101...0101 (0x5555555555555) are followed by 0 then 1s:
// below half, so only plus rounds up.
TEST(FpuRounding, OneThirdInEveryMode) {
  EXPECT_EQ(sn(&Fpu::div, kOneF, kThreeF, R::nearest), 0x3EAAAAABu);
  EXPECT_EQ(sn(&Fpu::div, kOneF, kThreeF, R::zero), 0x3EAAAAAAu);
  EXPECT_EQ(sn(&Fpu::div, kOneF, kThreeF, R::plus), 0x3EAAAAABu);
  EXPECT_EQ(sn(&Fpu::div, kOneF, kThreeF, R::minus), 0x3EAAAAAAu);
  const std::uint32_t minus_one = 0xBF800000;
  EXPECT_EQ(sn(&Fpu::div, minus_one, kThreeF, R::nearest), 0xBEAAAAABu);
  EXPECT_EQ(sn(&Fpu::div, minus_one, kThreeF, R::zero), 0xBEAAAAAAu);
  EXPECT_EQ(sn(&Fpu::div, minus_one, kThreeF, R::plus), 0xBEAAAAAAu);
  EXPECT_EQ(sn(&Fpu::div, minus_one, kThreeF, R::minus), 0xBEAAAAABu);

  EXPECT_EQ(db(&Fpu::div, kOne, kThree, R::nearest), 0x3FD5555555555555u);
  EXPECT_EQ(db(&Fpu::div, kOne, kThree, R::zero), 0x3FD5555555555555u);
  EXPECT_EQ(db(&Fpu::div, kOne, kThree, R::plus), 0x3FD5555555555556u);
  EXPECT_EQ(db(&Fpu::div, kOne, kThree, R::minus), 0x3FD5555555555555u);
  EXPECT_EQ(db(&Fpu::div, kOne | (1ull << 63), kThree, R::minus), 0xBFD5555555555556u);
}

// 0.1f = 0x3DCCCCCD = 13421773 * 2^-27, 0.2f = 0x3E4CCCCD = 13421773 * 2^-26. The sum is
// (13421773 + 26843546) * 2^-27 = 40265319 * 2^-27, 26 bits; dropping two bits leaves
// 10066329 (0x999999) and 3/4 of a unit: nearest rounds up to 0x99999A * 2^-25 = 1.2 * 2^-2,
// that is 0x3E800000 | 0x19999A; zero truncates to 0x3E999999.
// 0.1 = 0x3FB999999999999A = 0x1999999999999A * 2^-56, 0.2 twice that: the sum is
// 3 * 0x1999999999999A * 2^-56 = 0x4CCCCCCCCCCCCE * 2^-56, 55 bits ending in binary 10: an exact
// tie on the odd 0x13333333333333, so nearest goes to the even 0x13333333333334 * 2^-54.
TEST(FpuRounding, PointOnePlusPointTwo) {
  EXPECT_EQ(sn(&Fpu::add, 0x3DCCCCCD, 0x3E4CCCCD), 0x3E99999Au);
  EXPECT_EQ(sn(&Fpu::add, 0x3DCCCCCD, 0x3E4CCCCD, R::zero), 0x3E999999u);
  EXPECT_EQ(db(&Fpu::add, 0x3FB999999999999A, 0x3FC999999999999A), 0x3FD3333333333334u);
  EXPECT_EQ(db(&Fpu::add, 0x3FB999999999999A, 0x3FC999999999999A, R::zero), 0x3FD3333333333333u);
}

// Ties: 1 + 2^-24 (2^-24 = 0x33800000) is half a unit above 1.0f: nearest keeps the even 1.0,
// plus goes to 1 + 2^-23. (1 + 2^-23) + 2^-24 is a tie on an odd significand: nearest goes up.
TEST(FpuRounding, TiesToEven) {
  EXPECT_EQ(sn(&Fpu::add, kOneF, 0x33800000), kOneF);
  EXPECT_EQ(sn(&Fpu::add, kOneF, 0x33800000, R::plus), 0x3F800001u);
  EXPECT_EQ(sn(&Fpu::add, 0x3F800001, 0x33800000), 0x3F800002u);
  EXPECT_EQ(sn(&Fpu::add, 0x3F800001, 0x33800000, R::zero), 0x3F800001u);
}

// 2 * max = 2^128 - 2^104 overflows: nearest gives Inf, zero the largest finite value, plus and
// minus Inf on their own side and the largest finite value on the other. Overflow sets the FP
// error flag in every mode.
TEST(FpuRounding, OverflowToInfOrLargestFinite) {
  const R modes[] = {R::nearest, R::zero, R::plus, R::minus};
  const std::uint32_t pos[] = {kInfF, kMaxF, kInfF, kMaxF};
  const std::uint32_t neg[] = {0xFF800000, 0xFF7FFFFF, 0xFF7FFFFF, 0xFF800000};
  for (int i = 0; i < 4; ++i) {
    bool e = false;
    EXPECT_EQ(sn(&Fpu::mul, kMaxF, kTwoF, modes[i], &e), pos[i]) << i;
    EXPECT_TRUE(e);
    e = false;
    EXPECT_EQ(sn(&Fpu::mul, kMaxF | 0x80000000, kTwoF, modes[i], &e), neg[i]) << i;
    EXPECT_TRUE(e);
  }
  bool e = false;
  EXPECT_EQ(db(&Fpu::mul, kMax, kTwo, R::nearest, &e), kInf);
  EXPECT_TRUE(e);
  EXPECT_EQ(db(&Fpu::mul, kMax, kTwo, R::zero, &e), kMax);
}

// max + 2^103 (0x73000000, exponent 230) is (2^24 - 1/2) * 2^104: a tie on the odd 2^24 - 1, so
// nearest rounds to 2^128 and overflows; toward zero it is max exactly as rounded, which is no
// overflow (IEEE: overflow is judged on the rounded result), so no FP error.
TEST(FpuRounding, OverflowIsJudgedAfterRounding) {
  bool e = false;
  EXPECT_EQ(sn(&Fpu::add, kMaxF, 0x73000000, R::nearest, &e), kInfF);
  EXPECT_TRUE(e);
  EXPECT_EQ(sn(&Fpu::add, kMaxF, 0x73000000, R::zero, &e), kMaxF);
  EXPECT_FALSE(e);
}

// IEEE 754 section 6.3: x + (-x) and (+0) + (-0) are +0, except -0 rounding toward minus;
// (-0) + (-0) is -0; products and quotients take the exclusive or of the signs.
TEST(FpuSignedZero, SumsAndProducts) {
  const std::uint32_t pz = 0, nz = 0x80000000;
  EXPECT_EQ(sn(&Fpu::add, nz, pz, R::nearest), pz);
  EXPECT_EQ(sn(&Fpu::add, nz, pz, R::minus), nz);
  EXPECT_EQ(sn(&Fpu::add, nz, pz, R::plus), pz);
  EXPECT_EQ(sn(&Fpu::add, nz, nz, R::nearest), nz);
  EXPECT_EQ(sn(&Fpu::sub, pz, pz, R::minus), nz);    // 0 - 0
  EXPECT_EQ(sn(&Fpu::sub, nz, pz, R::nearest), nz);  // -0 - 0 = -0 + -0
  EXPECT_EQ(sn(&Fpu::sub, kThreeF, kThreeF, R::nearest), pz);
  EXPECT_EQ(sn(&Fpu::sub, kThreeF, kThreeF, R::minus), nz);
  EXPECT_EQ(db(&Fpu::sub, kThree, kThree, R::minus), 1ull << 63);
  EXPECT_EQ(sn(&Fpu::mul, nz, kThreeF), nz);
  EXPECT_EQ(sn(&Fpu::div, pz, 0xC0400000), nz);  // 0 / -3
  EXPECT_EQ(sn(&Fpu::add, nz, kThreeF), kThreeF);
}

// Denormals as IEEE. FLT_MIN / 2 = 2^-127 = 0x00400000 exactly. 3 * 2^-149 / 2 is 1.5 units of
// 2^-149: a tie between 1 and the even 2, so nearest gives 2; zero and minus 1, plus 2.
// 2^-149 / 2 is a tie between 0 (even) and 1: nearest gives +0, plus the smallest denormal.
// Underflow does not set the FP error flag (Notebook.txt: not implemented in the T800).
TEST(FpuDenormal, RoundedAsIeee) {
  bool e = true;
  EXPECT_EQ(sn1(&Fpu::div_by_2, 0x00800000, R::nearest, &e), 0x00400000u);
  EXPECT_FALSE(e);
  EXPECT_EQ(sn1(&Fpu::div_by_2, 0x00000003, R::nearest), 0x00000002u);
  EXPECT_EQ(sn1(&Fpu::div_by_2, 0x00000003, R::zero), 0x00000001u);
  EXPECT_EQ(sn1(&Fpu::div_by_2, 0x00000003, R::plus), 0x00000002u);
  EXPECT_EQ(sn1(&Fpu::div_by_2, 0x00000003, R::minus), 0x00000001u);
  EXPECT_EQ(sn1(&Fpu::div_by_2, 0x80000003, R::plus), 0x80000001u);
  EXPECT_EQ(sn1(&Fpu::div_by_2, 0x00000001, R::nearest, &e), 0x00000000u);
  EXPECT_FALSE(e);
  EXPECT_EQ(sn1(&Fpu::div_by_2, 0x00000001, R::plus), 0x00000001u);
  // The largest denormal plus the smallest is FLT_MIN; FLT_MIN less the smallest is denormal.
  EXPECT_EQ(sn(&Fpu::add, 0x007FFFFF, 0x00000001), 0x00800000u);
  EXPECT_EQ(sn(&Fpu::sub, 0x00800000, 0x00000001), 0x007FFFFFu);
  // 2^-75 = 0x1A000000 (exponent 52): its square 2^-150 is half the smallest denormal, a tie on
  // 0; (1.5 * 2^-75)^2 = 1.125 * 2^-149 rounds to the smallest.
  EXPECT_EQ(sn(&Fpu::mul, 0x1A000000, 0x1A000000, R::nearest), 0u);
  EXPECT_EQ(sn(&Fpu::mul, 0x1A000000, 0x1A000000, R::plus), 1u);
  EXPECT_EQ(sn(&Fpu::mul, 0x1A400000, 0x1A400000, R::nearest), 1u);
  EXPECT_EQ(sn(&Fpu::mul, 0x1A400000, 0x1A400000, R::zero), 1u);
  // REAL64: DBL_MIN * 0.5 = 2^-1023 = 0x0008000000000000.
  EXPECT_EQ(db(&Fpu::mul, 0x0010000000000000, 0x3FE0000000000000), 0x0008000000000000u);
  EXPECT_EQ(db(&Fpu::div, 0x0000000000000003, kTwo, R::nearest), 0x0000000000000002u);
  EXPECT_EQ(db(&Fpu::div, 0x0000000000000003, kTwo, R::minus), 0x0000000000000001u);
}

// The T800's NaNs (t4 fparithmetic.c NAN32_* and NAN64_*), positive, where x86 gives its default
// negative quiet NaN 0xFFC00000 for all of them. Each invalid operation sets the FP error flag.
TEST(FpuNan, InvalidOperationsGiveTheT800Nans) {
  bool e = false;
  EXPECT_EQ(sn(&Fpu::div, 0, 0, R::nearest, &e), 0x7FC00000u);  // NAN32_DivZeroByZero
  EXPECT_TRUE(e);
  EXPECT_EQ(sn(&Fpu::div, kInfF, 0xFF800000), 0x7FA00000u);  // DivInfByInf
  EXPECT_EQ(sn(&Fpu::mul, 0x80000000, kInfF), 0x7F900000u);  // MulZeroByInf
  EXPECT_EQ(sn(&Fpu::mul, kInfF, 0), 0x7F900000u);
  EXPECT_EQ(sn(&Fpu::add, kInfF, 0xFF800000), 0x7F880000u);  // AddOppositeInf
  EXPECT_EQ(sn(&Fpu::sub, kInfF, kInfF), 0x7F880000u);       // SubSameInf
  EXPECT_EQ(db(&Fpu::div, 0, 0, R::nearest, &e), 0x7FF8000000000000u);
  EXPECT_TRUE(e);
  EXPECT_EQ(db(&Fpu::div, kInf, kInf), 0x7FF4000000000000u);
  EXPECT_EQ(db(&Fpu::mul, kInf, 0), 0x7FF2000000000000u);
  EXPECT_EQ(db(&Fpu::add, kInf | (1ull << 63), kInf), 0x7FF1000000000000u);
  EXPECT_EQ(db(&Fpu::sub, kInf, kInf), 0x7FF1000000000000u);
  // Same-signed infinities add, opposite ones subtract, without a NaN (but the error flag is set).
  EXPECT_EQ(sn(&Fpu::add, kInfF, kInfF, R::nearest, &e), kInfF);
  EXPECT_TRUE(e);
  EXPECT_EQ(sn(&Fpu::sub, kInfF, 0xFF800000), kInfF);
}

// Notebook.txt (from the datasheet): one NaN operand is returned, of two the one with the larger
// fraction; t4 (db_sub, db_mul) negates FA's NaN in FB - FA and gives the NaN of a product or
// quotient the sign of the product. A signalling NaN (0x7F800001) is returned as it is.
TEST(FpuNan, Propagation) {
  bool e = false;
  EXPECT_EQ(sn(&Fpu::add, 0x7F800001, kOneF, R::nearest, &e), 0x7F800001u);
  EXPECT_TRUE(e);
  EXPECT_EQ(sn(&Fpu::add, 0x7FC00001, 0x7FC00002), 0x7FC00002u);
  EXPECT_EQ(sn(&Fpu::add, 0x7FC00002, 0x7FC00001), 0x7FC00002u);
  EXPECT_EQ(sn(&Fpu::add, 0xFFC00001, 0x7FC00001), 0xFFC00001u);  // equal fractions: FB's
  EXPECT_EQ(sn(&Fpu::sub, kOneF, 0x7FC00001), 0xFFC00001u);
  EXPECT_EQ(sn(&Fpu::sub, 0x7FC00001, kOneF), 0x7FC00001u);
  EXPECT_EQ(sn(&Fpu::mul, 0x7FC00001, 0xBF800000), 0xFFC00001u);
  EXPECT_EQ(sn(&Fpu::div, 0xBF800000, 0xFFC00001), 0x7FC00001u);
  EXPECT_EQ(db(&Fpu::add, kOne, 0x7FF0000000000001), 0x7FF0000000000001u);
  // A NaN divided by zero is still the NaN (NaN rules come before division by zero).
  EXPECT_EQ(sn(&Fpu::div, 0x7FC00005, 0), 0x7FC00005u);
}

// sqrt(2) = 1.6A09E667F3BCC908B2FB...h. REAL32 keeps 23 fraction bits, 0x3504F3 (binary
// 011 0101 0000 0100 1111 0011 of 6A09E6|67F3...); the next bit is 0, so nearest, zero and minus
// give 0x3FB504F3 and plus 0x3FB504F4. REAL64 keeps 13 hex digits 6A09E667F3BCC; the next digit 9
// is 1001b, above half: nearest and plus round up to ...BCD, zero and minus keep ...BCC. The
// compiler's sequence is fpusqrtfirst, 2 (REAL32) or 5 (REAL64) fpusqrtstep, fpusqrtlast (occ21
// gen8.c); the mode that counts is the one set just before fpusqrtlast.
std::uint32_t sqrt_sn(std::uint32_t x, R m) {
  Fpu f;
  f.load_single(x);
  f.sqrt_first();
  f.sqrt_step();
  f.sqrt_step();
  f.set_rounding(m);
  f.sqrt_last();
  return f.store_single();
}
std::uint64_t sqrt_db(std::uint64_t x, R m, bool* error = nullptr) {
  Fpu f;
  f.load_double(x);
  f.sqrt_first();
  for (int i = 0; i < 5; ++i) f.sqrt_step();
  f.set_rounding(m);
  f.sqrt_last();
  if (error) *error = f.error();
  return f.store_double();
}

TEST(FpuSqrt, SquareRootOfTwo) {
  EXPECT_EQ(sqrt_sn(kTwoF, R::nearest), 0x3FB504F3u);
  EXPECT_EQ(sqrt_sn(kTwoF, R::zero), 0x3FB504F3u);
  EXPECT_EQ(sqrt_sn(kTwoF, R::minus), 0x3FB504F3u);
  EXPECT_EQ(sqrt_sn(kTwoF, R::plus), 0x3FB504F4u);
  EXPECT_EQ(sqrt_db(kTwo, R::nearest), 0x3FF6A09E667F3BCDu);
  EXPECT_EQ(sqrt_db(kTwo, R::plus), 0x3FF6A09E667F3BCDu);
  EXPECT_EQ(sqrt_db(kTwo, R::zero), 0x3FF6A09E667F3BCCu);
  EXPECT_EQ(sqrt_db(kTwo, R::minus), 0x3FF6A09E667F3BCCu);
}

TEST(FpuSqrt, ExactRootsAndSpecialOperands) {
  const std::uint64_t four = 0x4010000000000000;
  EXPECT_EQ(sqrt_db(four, R::nearest), kTwo);
  EXPECT_EQ(sqrt_db(four, R::plus), kTwo);
  EXPECT_EQ(sqrt_sn(0x40800000, R::minus), kTwoF);
  // Denormal operands: sqrt(2^-1074) = 2^-537 (exponent 486 = 0x1E6), sqrt(2^-148) = 2^-74
  // (REAL32 exponent 53 = 0x35).
  EXPECT_EQ(sqrt_db(1, R::nearest), 0x1E60000000000000u);
  EXPECT_EQ(sqrt_db(1, R::zero), 0x1E60000000000000u);
  EXPECT_EQ(sqrt_sn(0x00000002, R::plus), 0x1A800000u);
  bool e = true;
  EXPECT_EQ(sqrt_db(1ull << 63, R::nearest, &e), 1ull << 63);  // sqrt(-0) = -0
  EXPECT_FALSE(e);
  EXPECT_EQ(sqrt_db(0xBFF0000000000000, R::nearest, &e), 0x7FF0800000000000u);  // NegativeSqrt
  EXPECT_TRUE(e);
  EXPECT_EQ(sqrt_sn(0xBF800000, R::nearest), 0x7F840000u);
  EXPECT_EQ(sqrt_db(kInf, R::nearest, &e), kInf);  // an infinite operand sets the flag
  EXPECT_TRUE(e);
}

TEST(FpuSqrt, ModeBeforeTheFirstStepDoesNotReachTheLast) {
  Fpu f;
  f.load_double(kTwo);
  f.set_rounding(R::zero);
  f.sqrt_first();  // takes the mode and resets it (t4 p.c: ResetRounding after fpusqrtfirst)
  for (int i = 0; i < 5; ++i) f.sqrt_step();
  f.sqrt_last();
  EXPECT_EQ(f.store_double(), 0x3FF6A09E667F3BCDu);
}

// The compiler's REAL REM: "fpremfirst; eqc 0; cj next; loop: fpremstep; cj loop; next:" (occ21
// gen12.c). Runs it as the integer processor would and returns FA; the quotient is left in FB.
struct RemResult {
  std::uint64_t rem, quot;
  int steps;
  bool error;
};
RemResult occam_rem(Fpu& f) {
  RemResult r{0, 0, 0, false};
  const std::uint32_t a = f.rem_first();
  const std::uint32_t eqc = a == 0 ? 1 : 0;
  if (eqc != 0) {  // cj jumps to next when Areg is 0, else falls into the loop
    while (true) {
      ++r.steps;
      if (f.rem_step() != 0 || r.steps > 100) break;  // cj loop: again while Areg is 0
    }
  }
  r.error = f.error();
  r.quot = f.fb().bits;
  r.rem = f.fa().length == L::real32 ? f.store_single() : f.store_double();
  return r;
}
RemResult rem_sn(std::uint32_t x, std::uint32_t y) {
  Fpu f;
  f.load_single(x);
  f.load_single(y);
  return occam_rem(f);
}
RemResult rem_db(std::uint64_t x, std::uint64_t y) {
  Fpu f;
  f.load_double(x);
  f.load_double(y);
  return occam_rem(f);
}

// x REM y = x - n*y with n = x/y rounded to nearest, ties to even (IEEE remainder).
TEST(FpuRemainder, IeeeRemainderAndQuotient) {
  RemResult r = rem_sn(0x40A00000, kThreeF);  // 5/3 = 1.67: n = 2, 5 - 6 = -1
  EXPECT_EQ(r.rem, 0xBF800000u);
  EXPECT_EQ(r.quot, kTwoF);
  EXPECT_EQ(r.steps, 0);  // fpremfirst's TRUE skips the loop
  EXPECT_FALSE(r.error);
  r = rem_sn(0x40E00000, kTwoF);  // 7/2 = 3.5: n = 4 (even), 7 - 8 = -1
  EXPECT_EQ(r.rem, 0xBF800000u);
  EXPECT_EQ(r.quot, 0x40800000u);
  r = rem_sn(0x40A00000, kTwoF);  // 5/2 = 2.5: n = 2, 5 - 4 = 1
  EXPECT_EQ(r.rem, kOneF);
  r = rem_sn(0xC0A00000, kThreeF);  // -5/3: n = -2, -5 + 6 = 1
  EXPECT_EQ(r.rem, kOneF);
  EXPECT_EQ(r.quot, 0xC0000000u);
  // 2^100 = (2^2)^50 = 1 mod 3, and 1 < 3/2: the remainder is 1 (2^100 = 0x4630000000000000).
  EXPECT_EQ(rem_db(0x4630000000000000, kThree).rem, kOne);
  // Denormals: 5 units REM 2 units: n = 2 (2.5 to even), 1 unit.
  EXPECT_EQ(rem_db(5, 2).rem, 1u);
  r = rem_db(0x8000000000000000, kOne);  // -0 REM 1 = -0
  EXPECT_EQ(r.rem, 0x8000000000000000u);
  EXPECT_FALSE(r.error);
  r = rem_db(kOne, kInf);  // 1 REM Inf = 1, the infinite operand sets the flag
  EXPECT_EQ(r.rem, kOne);
  EXPECT_TRUE(r.error);
}

TEST(FpuRemainder, InvalidGivesTheT800Nans) {
  RemResult r = rem_sn(kInfF, kOneF);
  EXPECT_EQ(r.rem, 0x7F804000u);  // NAN32_RemFromInf
  EXPECT_TRUE(r.error);
  r = rem_sn(kOneF, 0);
  EXPECT_EQ(r.rem, 0x7F802000u);  // NAN32_RemByZero
  EXPECT_TRUE(r.error);
  r = rem_db(kInf, kOne);
  EXPECT_EQ(r.rem, 0x7FF0080000000000u);
  EXPECT_EQ(r.quot, 0x7FF0020000000000u);  // NAN64_RemInvalidQuot, pushed by t4 fp_remfirstdb
  EXPECT_EQ(rem_db(kOne, 0).rem, 0x7FF0040000000000u);
}

// fpint rounds to an integral value in the mode, keeping the sign: 2.5 -> 2 (nearest, even),
// 3.5 -> 4; toward plus 2.5 -> 3, toward minus -2.5 -> -3; -0.3 -> -0 to nearest and +0.3 -> +0
// toward minus (IEEE roundToIntegral keeps the sign of zero).
TEST(FpuInt, RoundToIntegral) {
  const std::uint32_t two_half = 0x40200000, m_two_half = 0xC0200000;
  EXPECT_EQ(sn1(&Fpu::to_integral, two_half, R::nearest), kTwoF);
  EXPECT_EQ(sn1(&Fpu::to_integral, 0x40600000, R::nearest), 0x40800000u);
  EXPECT_EQ(sn1(&Fpu::to_integral, two_half, R::zero), kTwoF);
  EXPECT_EQ(sn1(&Fpu::to_integral, two_half, R::plus), 0x40400000u);
  EXPECT_EQ(sn1(&Fpu::to_integral, two_half, R::minus), kTwoF);
  EXPECT_EQ(sn1(&Fpu::to_integral, m_two_half, R::nearest), 0xC0000000u);
  EXPECT_EQ(sn1(&Fpu::to_integral, m_two_half, R::plus), 0xC0000000u);
  EXPECT_EQ(sn1(&Fpu::to_integral, m_two_half, R::minus), 0xC0400000u);
  EXPECT_EQ(sn1(&Fpu::to_integral, 0xBE99999A, R::nearest), 0x80000000u);  // -0.3
  EXPECT_EQ(sn1(&Fpu::to_integral, 0x3E99999A, R::minus), 0x00000000u);    // +0.3
  EXPECT_EQ(sn1(&Fpu::to_integral, 0xBE99999A, R::plus), 0x80000000u);
  EXPECT_EQ(sn1(&Fpu::to_integral, 0x3E99999A, R::plus), kOneF);
  // 2^23 + 0.5 does not exist in REAL32; 2^52 + 1 (0x4330000000000001) is already integral.
  EXPECT_EQ(db1(&Fpu::to_integral, 0x4330000000000001, R::plus), 0x4330000000000001u);
  bool e = false;
  EXPECT_EQ(sn1(&Fpu::to_integral, kInfF, R::nearest, &e), kInfF);  // t4 fp_intdb
  EXPECT_TRUE(e);
}

// fprtoi32 then fpstnli32, as the compiler converts REAL to INT (occ21 gen11.c).
std::uint32_t to_int32(std::uint64_t x, R m, bool* error) {
  Fpu f;
  f.load_double(x);
  f.set_rounding(m);
  f.real_to_int32();
  *error = f.error();
  EXPECT_EQ(f.fa().length, L::real64);  // fprtoi32 keeps the length
  return f.store_int32();
}

// t4 fp_rtoi32db corrects its range check to the TVS1F results at the two boundaries:
// -(2^31 + 2^-21) (0xC1E0000000000001) is an error only rounding toward minus (it rounds to
// -2^31 - 1), 2^31 - 2^-22 (0x41DFFFFFFFFFFFFF) only rounding to nearest or plus (to 2^31).
TEST(FpuInt, RealToInt32Boundaries) {
  bool e = false;
  EXPECT_EQ(to_int32(0xC1E0000000000001, R::nearest, &e), 0x80000000u);
  EXPECT_FALSE(e);
  EXPECT_EQ(to_int32(0xC1E0000000000001, R::zero, &e), 0x80000000u);
  EXPECT_FALSE(e);
  EXPECT_EQ(to_int32(0xC1E0000000000001, R::plus, &e), 0x80000000u);
  EXPECT_FALSE(e);
  to_int32(0xC1E0000000000001, R::minus, &e);
  EXPECT_TRUE(e);
  to_int32(0x41DFFFFFFFFFFFFF, R::nearest, &e);
  EXPECT_TRUE(e);
  to_int32(0x41DFFFFFFFFFFFFF, R::plus, &e);
  EXPECT_TRUE(e);
  EXPECT_EQ(to_int32(0x41DFFFFFFFFFFFFF, R::zero, &e), 0x7FFFFFFFu);
  EXPECT_FALSE(e);
  EXPECT_EQ(to_int32(0x41DFFFFFFFFFFFFF, R::minus, &e), 0x7FFFFFFFu);
  EXPECT_FALSE(e);
  EXPECT_EQ(to_int32(0xC1E0000000000000, R::nearest, &e), 0x80000000u);  // MinInt exactly
  EXPECT_FALSE(e);
  EXPECT_EQ(to_int32(0xC004000000000000, R::minus, &e), 0xFFFFFFFDu);  // -2.5 -> -3
  to_int32(kInf, R::nearest, &e);
  EXPECT_TRUE(e);
}

// fpstnli32 stores floor(FA) mod 2^32 (t4 fp_stnli32db, which passes TVS1F): -0.5 -> -1,
// 2^32 + 5 (0x41F0000000500000) -> 5, a negative denormal -> -1; 0 for Inf and NaN.
TEST(FpuInt, StoreInt32IsFloorModulo2To32) {
  auto st = [](std::uint64_t x) {
    Fpu f;
    f.load_double(x);
    return f.store_int32();
  };
  EXPECT_EQ(st(0xBFE0000000000000), 0xFFFFFFFFu);
  EXPECT_EQ(st(0x4004000000000000), 2u);           // 2.5
  EXPECT_EQ(st(0xC004000000000000), 0xFFFFFFFDu);  // -2.5 -> -3
  EXPECT_EQ(st(0x41F0000000500000), 5u);
  EXPECT_EQ(st(0x8000000000000001), 0xFFFFFFFFu);
  EXPECT_EQ(st(0x8000000000000000), 0u);
  EXPECT_EQ(st(kInf), 0u);
  EXPECT_EQ(st(0x7FF8000000000000), 0u);
  Fpu f;
  f.load_single(0xCF000000);  // -2^31
  EXPECT_EQ(f.store_int32(), 0x80000000u);
}

// INT64 ROUND x: "fpint; fpuchki64; fpdup; fpstnli32 (low); fpuexpdec32; fpstnli32 (high)"
// (occ21 gen5.c). -(2^40 + 3) = 0xC270000000003000 (exponent 1063 = 0x427, fraction 3 * 2^12):
// the low word is -3 mod 2^32 = 0xFFFFFFFD, the high floor(-(2^40 + 3) / 2^32) = -257.
TEST(FpuInt, Int64RoundSequence) {
  Fpu f;
  f.load_double(0xC270000000003000);
  f.to_integral();
  f.check_int64();
  f.dup();
  EXPECT_EQ(f.store_int32(), 0xFFFFFFFDu);
  f.exp_dec32();
  EXPECT_EQ(f.store_int32(), 0xFFFFFEFFu);
  EXPECT_FALSE(f.error());
}

// Range checks (t4 fp_chki32db/fp_chki64db guards): -2^31 <= x < 2^31, -2^63 <= x < 2^63.
TEST(FpuInt, RangeChecks) {
  auto chk = [](Op op, std::uint64_t x) {
    Fpu f;
    f.load_double(x);
    (f.*op)();
    return f.error();
  };
  EXPECT_FALSE(chk(&Fpu::check_int32, 0xC1E0000000000000));  // -2^31
  EXPECT_TRUE(chk(&Fpu::check_int32, 0xC1E0000000000001));
  EXPECT_TRUE(chk(&Fpu::check_int32, 0x41E0000000000000));   // 2^31
  EXPECT_FALSE(chk(&Fpu::check_int32, 0x41DFFFFFFFE00000));  // 2^31 - 0.5
  EXPECT_TRUE(chk(&Fpu::check_int32, 0x7FF8000000000000));
  EXPECT_TRUE(chk(&Fpu::check_int32, kInf));
  EXPECT_FALSE(chk(&Fpu::check_int64, 0xC3E0000000000000));  // -2^63
  EXPECT_TRUE(chk(&Fpu::check_int64, 0x43E0000000000000));   // 2^63
  EXPECT_FALSE(chk(&Fpu::check_int64, 0x43DFFFFFFFFFFFFF));
  Fpu f;
  f.load_single(0x4F000000);  // 2^31 as REAL32
  f.check_int32();
  EXPECT_TRUE(f.error());
}

// Loads from integers. INT32 MinInt -2^31: REAL32 0xCF000000, REAL64 0xC1E0000000000000.
// MaxInt 2^31 - 1 has 31 one bits; to 24 bits the dropped 7 ones are above half: nearest and plus
// give 2^31 (0x4F000000), zero and minus 2^31 - 2^7 (0x4EFFFFFF). 2^24 + 1 is a tie on the even
// 2^24 (0x4B800000); plus gives 2^24 + 2 (0x4B800001). fpb32tor64 is unsigned: #FFFFFFFF is
// 2^32 - 1 = 0x41EFFFFFFFE00000 (exponent 31, 31 one bits of fraction).
TEST(FpuConvert, FromInt32) {
  auto i32 = [](std::int32_t v, R m) {
    Fpu f;
    f.set_rounding(m);
    f.load_int32_as_real32(v);
    EXPECT_EQ(f.fa().length, L::real32);
    return f.store_single();
  };
  EXPECT_EQ(i32(-2147483647 - 1, R::nearest), 0xCF000000u);
  EXPECT_EQ(i32(2147483647, R::nearest), 0x4F000000u);
  EXPECT_EQ(i32(2147483647, R::plus), 0x4F000000u);
  EXPECT_EQ(i32(2147483647, R::zero), 0x4EFFFFFFu);
  EXPECT_EQ(i32(2147483647, R::minus), 0x4EFFFFFFu);
  EXPECT_EQ(i32(16777217, R::nearest), 0x4B800000u);
  EXPECT_EQ(i32(16777217, R::plus), 0x4B800001u);
  EXPECT_EQ(i32(-16777217, R::minus), 0xCB800001u);
  EXPECT_EQ(i32(0, R::minus), 0u);  // an integer zero is +0 in every mode
  Fpu f;
  f.load_int32_as_real64(-2147483647 - 1);
  EXPECT_EQ(f.fa().length, L::real64);
  EXPECT_EQ(f.store_double(), 0xC1E0000000000000u);
  f.load_int32_as_real64(-1);
  EXPECT_EQ(f.store_double(), 0xBFF0000000000000u);
  f.load_bit32_as_real64(0xFFFFFFFF);
  EXPECT_EQ(f.store_double(), 0x41EFFFFFFFE00000u);
  f.load_bit32_as_real64(0x80000000);
  EXPECT_EQ(f.store_double(), 0x41E0000000000000u);
}

// fpur64tor32 rounds: 1/3 as above; DBL_MAX overflows (Inf to nearest, FLT_MAX toward zero, the
// error flag in both); 2^-150 (0x3690000000000000) is a tie on 0, 1.5 * 2^-150
// (0x3698000000000000) is 3/4 of the smallest denormal; a NaN becomes t4's conversion NaN.
TEST(FpuConvert, Real64ToReal32) {
  auto cv = [](std::uint64_t x, R m, bool* e = nullptr) {
    Fpu f;
    f.load_double(x);
    f.set_rounding(m);
    f.real64_to_real32();
    EXPECT_EQ(f.fa().length, L::real32);
    if (e) *e = f.error();
    return f.store_single();
  };
  EXPECT_EQ(cv(0x3FD5555555555555, R::nearest), 0x3EAAAAABu);
  EXPECT_EQ(cv(0x3FD5555555555555, R::zero), 0x3EAAAAAAu);
  bool e = false;
  EXPECT_EQ(cv(kMax, R::nearest, &e), kInfF);
  EXPECT_TRUE(e);
  EXPECT_EQ(cv(kMax, R::zero, &e), kMaxF);
  EXPECT_TRUE(e);
  EXPECT_EQ(cv(0x3690000000000000, R::nearest), 0u);
  EXPECT_EQ(cv(0x3690000000000000, R::plus), 1u);
  EXPECT_EQ(cv(0x3698000000000000, R::nearest), 1u);
  EXPECT_EQ(cv(0x3698000000000000, R::zero), 0u);
  EXPECT_EQ(cv(0xFFF8000000000001, R::nearest, &e), 0x7F820000u);  // NAN32_ConversionNaN
  EXPECT_TRUE(e);
  EXPECT_EQ(cv(kInf | (1ull << 63), R::nearest, &e), 0xFF800000u);
  EXPECT_TRUE(e);
}

// fpur32tor64 is exact: 0x3EAAAAAB widens to fraction 0x2AAAAB << 29 = 0x5555560000000. A NaN
// keeps its sign and fraction (t4 fp_r32tor64) and sets the flag.
TEST(FpuConvert, Real32ToReal64) {
  Fpu f;
  f.load_single(0x3EAAAAAB);
  f.real32_to_real64();
  EXPECT_EQ(f.fa().length, L::real64);
  EXPECT_FALSE(f.error());
  EXPECT_EQ(f.store_double(), 0x3FD5555560000000u);
  f.load_single(0x00000001);  // 2^-149: exponent 874 = 0x36A
  f.real32_to_real64();
  EXPECT_EQ(f.store_double(), 0x36A0000000000000u);
  f.load_single(0xFF800001);
  f.real32_to_real64();
  EXPECT_TRUE(f.error());
  EXPECT_EQ(f.store_double(), 0xFFF0000020000000u);
}

// fpunoround stores truncated: 1/3 = 0x3FD5555555555555 gives sign 0, exponent 1021 - 1023 + 127
// = 125, fraction 0x5555555555555 >> 29 = 0x2AAAAA: 0x3EAAAAAA (t4 fp_norounddb's formula).
TEST(FpuConvert, NoRoundTruncates) {
  Fpu f;
  f.load_double(0x3FD5555555555555);
  f.no_round();
  EXPECT_EQ(f.fa().length, L::real32);
  EXPECT_EQ(f.store_single(), 0x3EAAAAAAu);
  f.load_double(0xBFF8000000000000);  // -1.5 is exact
  f.no_round();
  EXPECT_EQ(f.store_single(), 0xBFC00000u);
}

// INT64 to REAL32 as the compiler emits it (occ21 code1k.c geni64tor): "fpb32tor64 (low word);
// fpunoround; fpi32tor64 (high word); fpuexpinc32; fpunoround; [fpurz for TRUNC]; fpadd".
std::uint32_t int64_to_real32(std::int64_t v, bool trunc) {
  Fpu f;
  f.load_bit32_as_real64(std::uint32_t(v));
  f.no_round();
  f.load_int32_as_real64(std::int32_t(v >> 32));
  f.exp_inc32();
  f.no_round();
  if (trunc) f.set_rounding(R::zero);
  f.add();
  EXPECT_EQ(f.fa().length, L::real32);
  return f.store_single();
}

// 2^62 + 2^38 + 1: REAL32's unit at 2^62 is 2^39, so 2^38 + 1 is just above half a unit and the
// correctly rounded value is 2^62 + 2^39 = 0x5E800001 (exponent 189). Rounded first to REAL64 (unit
// 2^10) it would become the tie 2^62 + 2^38 and then the even 2^62 (0x5E800000): fpadd must see
// the unrounded operands. 2^62 + 2^39 - 1 is 1 below 2^62 + 2^39: nearest 0x5E800001, TRUNC
// 0x5E800000. -1 is #FFFFFFFF (low, unsigned) + -1 * 2^32.
TEST(FpuConvert, Int64ToReal32RoundsOnce) {
  const std::int64_t v = (std::int64_t(1) << 62) + (std::int64_t(1) << 38) + 1;
  EXPECT_EQ(int64_to_real32(v, false), 0x5E800001u);
  const std::int64_t w = (std::int64_t(1) << 62) + (std::int64_t(1) << 39) - 1;
  EXPECT_EQ(int64_to_real32(w, false), 0x5E800001u);
  EXPECT_EQ(int64_to_real32(w, true), 0x5E800000u);
  EXPECT_EQ(int64_to_real32(-1, false), 0xBF800000u);
  EXPECT_EQ(int64_to_real32(0, false), 0u);
  EXPECT_EQ(int64_to_real32(16777217, false), 0x4B800000u);  // the tie of FromInt32
  EXPECT_EQ(int64_to_real32(std::numeric_limits<std::int64_t>::min(), false),
            0xDF000000u);  // -2^63
}

// Scaling: 1.0f * 2^32 = 0x4F800000 (exponent 159); 1.0 / 2^32 = 0x3DF0000000000000 (exponent
// 991); 2^-120 (0x03800000) / 2^32 = 2^-152, a quarter of the smallest denormal.
TEST(FpuScale, ByPowersOfTwo) {
  EXPECT_EQ(sn1(&Fpu::exp_inc32, kOneF), 0x4F800000u);
  EXPECT_EQ(db1(&Fpu::exp_dec32, kOne), 0x3DF0000000000000u);
  EXPECT_EQ(sn1(&Fpu::exp_dec32, 0x03800000, R::nearest), 0u);
  EXPECT_EQ(sn1(&Fpu::exp_dec32, 0x03800000, R::plus), 1u);
  EXPECT_EQ(sn1(&Fpu::mul_by_2, 0x3FC00000), 0x40400000u);  // 1.5 * 2 = 3
  EXPECT_EQ(sn1(&Fpu::div_by_2, 0x80000000), 0x80000000u);
  bool e = false;
  EXPECT_EQ(sn1(&Fpu::mul_by_2, kMaxF, R::nearest, &e), kInfF);
  EXPECT_TRUE(e);
  EXPECT_EQ(sn1(&Fpu::mul_by_2, kMaxF, R::zero, &e), kMaxF);
  EXPECT_TRUE(e);
  EXPECT_EQ(db1(&Fpu::mul_by_2, 0x7FF8000000000001, R::nearest, &e), 0x7FF8000000000001u);
  EXPECT_TRUE(e);
}

TEST(FpuScale, Abs) {
  bool e = true;
  EXPECT_EQ(sn1(&Fpu::abs, 0x80000000, R::nearest, &e), 0u);
  EXPECT_FALSE(e);
  EXPECT_EQ(db1(&Fpu::abs, 0xBFF0000000000000), kOne);
  EXPECT_EQ(sn1(&Fpu::abs, 0xFFC00001, R::nearest, &e), 0x7FC00001u);  // t4 fp_absdb
  EXPECT_TRUE(e);
  EXPECT_EQ(sn1(&Fpu::abs, 0xFF800000, R::nearest, &e), kInfF);
  EXPECT_TRUE(e);
}

// The FP error flag: overflow, invalid, division by zero, an Inf or NaN operand; not inexact, not
// underflow (Notebook.txt). fptesterr answers TRUE (1) when clear and clears it; fpchkerr reports
// it without clearing.
TEST(FpuError, ConditionsAndTesting) {
  EXPECT_FALSE(error_of_sn(&Fpu::div, kOneF, kThreeF));          // inexact
  EXPECT_FALSE(error_of_sn(&Fpu::mul, 0x1A000000, 0x1A400000));  // underflow
  EXPECT_TRUE(error_of_sn(&Fpu::mul, kMaxF, kMaxF));             // overflow
  EXPECT_TRUE(error_of_sn(&Fpu::add, kInfF, kOneF));             // infinite operand
  EXPECT_TRUE(error_of_sn(&Fpu::mul, 0, kInfF));                 // invalid
  EXPECT_TRUE(error_of_sn(&Fpu::add, 0x7FC00000, kOneF));        // NaN operand
  EXPECT_TRUE(error_of_sn(&Fpu::div, kOneF, 0));                 // division by zero
  EXPECT_EQ(sn(&Fpu::div, kOneF, 0), kInfF);
  EXPECT_EQ(sn(&Fpu::div, 0xBF800000, 0), 0xFF800000u);
  EXPECT_EQ(sn(&Fpu::div, kOneF, 0x80000000), 0xFF800000u);
  EXPECT_EQ(sn(&Fpu::div, kOneF, kInfF), 0u);

  Fpu f;
  EXPECT_EQ(f.test_error(), 1u);
  f.load_single(kOneF);
  f.load_single(0);
  f.div();
  EXPECT_TRUE(f.check_error());
  EXPECT_TRUE(f.error());  // fpchkerr leaves it
  EXPECT_EQ(f.test_error(), 0u);
  EXPECT_FALSE(f.error());
  EXPECT_EQ(f.test_error(), 1u);
  EXPECT_FALSE(f.check_error());
  f.set_error();
  EXPECT_TRUE(f.error());
  f.clear_error();
  EXPECT_FALSE(f.error());
  // The error flag is sticky: a later clean operation leaves it set.
  f.load_single(kOneF);
  f.load_single(0);
  f.div();
  f.load_single(kOneF);
  f.add();
  EXPECT_TRUE(f.error());
}

// fpurz etc. apply to the next FPU instruction only, after which the mode is round-to-nearest
// again (Notebook.txt, from the datasheet; t4 p.c ResetRounding). A load is an FPU instruction;
// fpldnladdsn is one instruction, so the mode reaches its add.
TEST(FpuRoundingMode, RevertsAfterOneInstruction) {
  Fpu f;
  f.load_single(kOneF);
  f.load_single(kThreeF);
  f.set_rounding(R::zero);
  EXPECT_EQ(f.rounding(), R::zero);
  f.div();
  EXPECT_EQ(f.rounding(), R::nearest);
  EXPECT_EQ(f.store_single(), 0x3EAAAAAAu);
  f.load_single(kOneF);
  f.load_single(kThreeF);
  f.div();  // no fpurz before it
  EXPECT_EQ(f.store_single(), 0x3EAAAAABu);

  f.set_rounding(R::zero);
  f.load_single(kOneF);  // takes the mode
  f.load_single(kThreeF);
  f.div();
  EXPECT_EQ(f.store_single(), 0x3EAAAAABu);

  f.load_single(kOneF);
  f.set_rounding(R::plus);
  f.load_add_single(0x33800000);  // 1 + 2^-24 toward plus
  EXPECT_EQ(f.store_single(), 0x3F800001u);
  f.load_single(kOneF);
  f.set_rounding(R::plus);
  f.load_single(0x33800000);
  f.add();
  EXPECT_EQ(f.store_single(), kOneF);

  f.set_rounding(R::minus);
  f.set_rounding(R::plus);  // the last setting counts
  f.load_double(kOne);      // and is used up here
  EXPECT_EQ(f.rounding(), R::nearest);
  f.set_rounding(R::zero);
  EXPECT_EQ(f.test_error(), 1u);
  EXPECT_EQ(f.rounding(), R::nearest);
}

TEST(FpuStack, LoadsStoresRevDup) {
  Fpu f;
  EXPECT_EQ(f.fa(), (Fpu::Register{0, L::real64, false}));
  f.load_single(0x11111111);
  f.load_double(0x2222222222222222);
  f.load_single(0x33333333);
  f.load_zero_double();  // FC := FB, FB := FA, FA := 0; 0x11111111 is lost
  EXPECT_EQ(f.fa(), (Fpu::Register{0, L::real64, false}));
  EXPECT_EQ(f.fb(), (Fpu::Register{0x33333333, L::real32, false}));
  EXPECT_EQ(f.fc(), (Fpu::Register{0x2222222222222222, L::real64, false}));
  EXPECT_EQ(f.store_double(), 0u);  // FA := FB, FB := FC, FC keeps its value
  EXPECT_EQ(f.fa().bits, 0x33333333u);
  EXPECT_EQ(f.fb().bits, 0x2222222222222222u);
  EXPECT_EQ(f.fc().bits, 0x2222222222222222u);
  f.rev();
  EXPECT_EQ(f.fa(), (Fpu::Register{0x2222222222222222, L::real64, false}));
  EXPECT_EQ(f.fb(), (Fpu::Register{0x33333333, L::real32, false}));
  f.dup();
  EXPECT_EQ(f.fa(), f.fb());
  EXPECT_EQ(f.fc(), (Fpu::Register{0x33333333, L::real32, false}));
  f.load_zero_single();
  EXPECT_EQ(f.fa(), (Fpu::Register{0, L::real32, false}));
}

TEST(FpuStack, BinaryOperationsAndComparisons) {
  Fpu f;
  f.load_single(0x40A00000);  // 5
  f.load_single(kThreeF);
  f.load_single(kTwoF);
  f.sub();  // FA := FB - FA = 3 - 2, FB := FC = 5
  EXPECT_EQ(f.fa().bits, kOneF);
  EXPECT_EQ(f.fb().bits, 0x40A00000u);
  EXPECT_EQ(f.gt(), 1u);  // 5 > 1; both popped: FA := FC
  EXPECT_EQ(f.fa().bits, 0x40A00000u);

  f.load_single(kTwoF);
  f.load_single(kTwoF);
  f.load_single(0x7FC00000);
  EXPECT_EQ(f.ordered(), 0u);  // nothing popped, no error
  EXPECT_EQ(f.is_nan(), 1u);
  EXPECT_EQ(f.not_finite(), 1u);
  EXPECT_FALSE(f.error());
  EXPECT_EQ(f.fa().bits, 0x7FC00000u);
  f.store_single();
  EXPECT_EQ(f.ordered(), 1u);
  EXPECT_EQ(f.not_finite(), 0u);
  EXPECT_EQ(f.eq(), 1u);
}

// fpgt / fpeq compare FB with FA on the CWG's total order (t4: "ACWG pp.106 B.2.7"): +0 = -0,
// sign and magnitude of the patterns otherwise, so a NaN is above Inf and equals itself; an Inf
// or NaN operand sets the FP error flag ("ACWG pp.158").
TEST(FpuCompare, TotalOrder) {
  auto cmp = [](std::uint32_t b, std::uint32_t a, bool gt, bool* e) {
    Fpu f;
    f.load_single(b);
    f.load_single(a);
    const std::uint32_t r = gt ? f.gt() : f.eq();
    *e = f.error();
    return r;
  };
  bool e = false;
  EXPECT_EQ(cmp(kTwoF, kOneF, true, &e), 1u);
  EXPECT_FALSE(e);
  EXPECT_EQ(cmp(kOneF, kTwoF, true, &e), 0u);
  EXPECT_EQ(cmp(0xBF800000, 0xC0000000, true, &e), 1u);  // -1 > -2
  EXPECT_EQ(cmp(0x80000000, 0, true, &e), 0u);
  EXPECT_EQ(cmp(0x80000000, 0, false, &e), 1u);
  EXPECT_EQ(cmp(0x00000001, 0x80000001, true, &e), 1u);  // denormals
  EXPECT_EQ(cmp(kInfF, kMaxF, true, &e), 1u);
  EXPECT_TRUE(e);
  EXPECT_EQ(cmp(0x7FC00000, kInfF, true, &e), 1u);
  EXPECT_TRUE(e);
  EXPECT_EQ(cmp(0x7FC00000, 0x7FC00000, false, &e), 1u);
  EXPECT_TRUE(e);
  Fpu f;  // mixed lengths compare values
  f.load_double(kTwo);
  f.load_single(kTwoF);
  EXPECT_EQ(f.eq(), 1u);
}

// The REAL32 NaN constants of t4 (NAN32_*) are the REAL64 ones (NAN64_*) with the fraction shifted
// right 29 places, which fpu.cpp relies on: checked through fpur32tor64, which keeps fractions.
TEST(FpuNan, Real32ConstantsMatchReal64) {
  const std::uint32_t n32[] = {0x7FC00000, 0x7FA00000, 0x7F900000, 0x7F880000,
                               0x7F840000, 0x7F820000, 0x7F804000, 0x7F802000};
  const std::uint64_t n64[] = {0x7FF8000000000000, 0x7FF4000000000000, 0x7FF2000000000000,
                               0x7FF1000000000000, 0x7FF0800000000000, 0x7FF0400000000000,
                               0x7FF0080000000000, 0x7FF0040000000000};
  for (int i = 0; i < 8; ++i) {
    Fpu f;
    f.load_single(n32[i]);
    f.real32_to_real64();
    EXPECT_EQ(f.store_double(), n64[i]) << i;
  }
}

TEST(FpuState, CopiesAreIndependent) {
  Fpu f;
  f.load_single(kOneF);
  f.set_error();
  Fpu saved = f;  // as the ISS saves an interrupted process's FPU
  f.load_single(kTwoF);
  f.clear_error();
  EXPECT_EQ(saved.fa().bits, kOneF);
  EXPECT_TRUE(saved.error());
}

}  // namespace
