// The T414's floating-point support instructions (unpacksn, postnormsn, roundsn, ldinf, cflerr)
// run on a T414 ISS. Two kinds of reference, neither of them the code under test:
// - register values worked out by hand from the IEEE 754 single-length layout (sign, 8-bit
//   exponent biased by 127, 23-bit fraction) and the instructions' definitions (CWG; the ST20C2
//   manual for unpacksn; t414_float_support.hpp), each case written out below;
// - whole multiplications done the way the T414's REAL32 library does them (unpack both, lmul the
//   fractions, norm, postnormsn, roundsn, OR in the sign), compared bit for bit with the host's own
//   IEEE single-precision multiply (x86-64 SSE, or any IEEE host: -ffp-contract=off), ties to even
//   included; that the tie cases really are ties is checked in exact double arithmetic.
// Cycles: the T414 datasheet's figures (pahihu/t4 Notebook.txt, "T414 Floating-point support
// operation codes", typical), plus the one cycle of each operation's pfix (codes >= #10).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "tests/iss/iss_fixtures.hpp"

namespace {

using iss_test::TestMachine;
using iss_test::Word;
using t800::iss::StopReason;

constexpr auto kT414 = t800::ProcessorType::T414_20;
constexpr std::int64_t kMemory = 1 << 16;

using iss_test::Stack;

std::string hex(Word w) {
  char text[16];
  std::snprintf(text, sizeof text, "#%08X", w);
  return text;
}

// Runs `body` on a T414 after `ajw 16` (workspace word 0 is postnormsn's exponent).
Stack run_t414(const std::string& body) {
  return iss_test::run_stack(body, kT414, kMemory);
}

float as_float(Word w) {
  float f;
  std::memcpy(&f, &w, 4);
  return f;
}
Word bits(float f) {
  Word w;
  std::memcpy(&w, &f, 4);
  return w;
}

// unpacksn with B = 5 beforehand, so C = 4 * 5 + type.
Stack unpack(Word packed) {
  return run_t414("ldc 5\nldc " + hex(packed) + "\nunpacksn");
}

TEST(IssT414Float, UnpackNormalNumbers) {
  // 1.0 = #3F800000: exponent field 127, fraction 0; the implied one goes to bit 31.
  Stack s = unpack(0x3F800000u);
  EXPECT_EQ(s.a, 0x80000000u);
  EXPECT_EQ(s.b, 127u);
  EXPECT_EQ(s.c, 4u * 5 + 1);
  // -1.0: the same, the sign is dropped.
  s = unpack(0xBF800000u);
  EXPECT_EQ(s.a, 0x80000000u);
  EXPECT_EQ(s.b, 127u);
  EXPECT_EQ(s.c, 21u);
  // 1.5 = #3FC00000: fraction #400000, moved up 8 places, with the implied one: #C0000000.
  s = unpack(0x3FC00000u);
  EXPECT_EQ(s.a, 0xC0000000u);
  EXPECT_EQ(s.b, 127u);
  // The largest finite number #7F7FFFFF: exponent 254, fraction all ones.
  s = unpack(0x7F7FFFFFu);
  EXPECT_EQ(s.a, 0xFFFFFF00u);
  EXPECT_EQ(s.b, 254u);
  EXPECT_EQ(s.c, 21u);
  EXPECT_FALSE(s.error);
}

TEST(IssT414Float, UnpackDenormalsZeroInfinityNaN) {
  // The smallest denormal #00000001: fraction 1 at bit 8, no implied one, exponent 1 (0.f x
  // 2^-126), type 1.
  Stack s = unpack(0x00000001u);
  EXPECT_EQ(s.a, 0x00000100u);
  EXPECT_EQ(s.b, 1u);
  EXPECT_EQ(s.c, 21u);
  // 2^-127 = #00400000: fraction #400000 -> #40000000.
  s = unpack(0x00400000u);
  EXPECT_EQ(s.a, 0x40000000u);
  EXPECT_EQ(s.b, 1u);
  EXPECT_EQ(s.c, 21u);
  // +0 and -0: everything zero, type 0.
  for (Word zero : {0x00000000u, 0x80000000u}) {
    s = unpack(zero);
    EXPECT_EQ(s.a, 0u);
    EXPECT_EQ(s.b, 0u);
    EXPECT_EQ(s.c, 20u);
  }
  // +Inf and -Inf: exponent 255, fraction 0, type 2.
  for (Word inf : {0x7F800000u, 0xFF800000u}) {
    s = unpack(inf);
    EXPECT_EQ(s.a, 0u);
    EXPECT_EQ(s.b, 255u);
    EXPECT_EQ(s.c, 22u);
  }
  // A quiet NaN #7FC00000: exponent 255, fraction #400000 -> #40000000, type 3.
  s = unpack(0x7FC00000u);
  EXPECT_EQ(s.a, 0x40000000u);
  EXPECT_EQ(s.b, 255u);
  EXPECT_EQ(s.c, 23u);
  EXPECT_FALSE(s.error);  // unpacksn signals nothing
}

TEST(IssT414Float, UnpackedPartsGiveTheHostsValue) {
  // For finite numbers, A / 2^31 * 2^(B - 127) is the number's magnitude (exact in double).
  for (float f : {1.0f, 0.1f, 3.14159f, 6.5e-39f, 1.0e-45f, 3.0e38f, 1234.5f}) {
    const Stack s = unpack(bits(f));
    EXPECT_EQ(std::ldexp(double(s.a), int(s.b) - 127 - 31), double(f)) << f;
  }
}

TEST(IssT414Float, LoadInfinity) {
  const Stack s = run_t414("ldc 1\nldc 2\nldinf");
  EXPECT_EQ(s.a, 0x7F800000u);  // +Inf
  EXPECT_EQ(s.b, 2u);
  EXPECT_EQ(s.c, 1u);
}

TEST(IssT414Float, CflerrSetsErrorOnInfinityAndNaN) {
  for (Word w : {0x7F800000u, 0xFF800000u, 0x7FC00000u, 0x7F800001u, 0xFFFFFFFFu}) {
    const Stack s = run_t414("ldc " + hex(w) + "\ncflerr");
    EXPECT_TRUE(s.error) << hex(w);
    EXPECT_EQ(s.a, w);  // the stack is unchanged
  }
  for (Word w : {0x3F800000u, 0x7F7FFFFFu, 0x00000001u, 0x80000000u, 0u}) {
    EXPECT_FALSE(run_t414("ldc " + hex(w) + "\ncflerr").error) << hex(w);
  }
}

// postnormsn with workspace word 0 = `temp`, C = places, B = fraction, A = guard.
Stack post_normalise(std::int32_t temp, Word places, Word fraction, Word guard) {
  return run_t414("ldc " + std::to_string(temp) + "\nstl 0\nldc " + hex(places) + "\nldc " +
                  hex(fraction) + "\nldc " + hex(guard) + "\npostnormsn");
}

TEST(IssT414Float, PostNormaliseNormalAndOverflow) {
  // Exponent 130 - 3 = 127: C := 127, fraction and guard unchanged.
  Stack s = post_normalise(130, 3, 0x80000000u, 0x1234u);
  EXPECT_EQ(s.c, 127u);
  EXPECT_EQ(s.b, 0x80000000u);
  EXPECT_EQ(s.a, 0x1234u);
  // 255 itself is the infinities' exponent: C := 255 (roundsn delivers infinity).
  EXPECT_EQ(post_normalise(255, 0, 0x80000000u, 0).c, 255u);
  // 300 - 2 = 298: too large, C := 255.
  s = post_normalise(300, 2, 0xC0000000u, 7);
  EXPECT_EQ(s.c, 255u);
  EXPECT_EQ(s.b, 0xC0000000u);
  EXPECT_EQ(s.a, 7u);
}

TEST(IssT414Float, PostNormaliseDenormalises) {
  // Exponent 1 - 1 = 0: a denormal, shifted right 1 - 0 = 1 place, C := 0.
  Stack s = post_normalise(1, 1, 0x80000000u, 0);
  EXPECT_EQ(s.b, 0x40000000u);
  EXPECT_EQ(s.a, 0u);
  EXPECT_EQ(s.c, 0u);
  // Exponent -2: 3 places. B:A = #80000000:#00000010 >> 3 = #10000000:#00000002, and the old
  // guard word is ORed in as a sticky bit: A = #12.
  s = post_normalise(-2, 0, 0x80000000u, 0x10u);
  EXPECT_EQ(s.b, 0x10000000u);
  EXPECT_EQ(s.a, 0x12u);
  EXPECT_EQ(s.c, 0u);
  // Exponent -31: 32 places, the fraction becomes the guard word.
  s = post_normalise(-31, 0, 0x80000000u, 0);
  EXPECT_EQ(s.b, 0u);
  EXPECT_EQ(s.a, 0x80000000u);
  EXPECT_EQ(s.c, 0u);
  // Exponent 0 - 40 = -40: below half the smallest denormal, everything zero.
  s = post_normalise(0, 40, 0xFFFFFFFFu, 0xFFFFFFFFu);
  EXPECT_EQ(s.a, 0u);
  EXPECT_EQ(s.b, 0u);
  EXPECT_EQ(s.c, 0u);
}

// roundsn with C = exponent, B = fraction (implied one at bit 31), A = guard.
Stack round(Word exponent, Word fraction, Word guard) {
  return run_t414("ldc " + hex(exponent) + "\nldc " + hex(fraction) + "\nldc " + hex(guard) +
                  "\nroundsn");
}

TEST(IssT414Float, RoundToNearestTiesToEven) {
  // Exact: 1.0.
  Stack s = round(127, 0x80000000u, 0);
  EXPECT_EQ(s.a, 0x3F800000u);
  EXPECT_EQ(s.b, 0x3F800000u);  // B holds the result too
  EXPECT_EQ(s.c, 0u);           // C >> 9
  // Below half an ulp (round bit 0, everything below set): down.
  EXPECT_EQ(round(127, 0x8000007Fu, 0xFFFFFFFFu).a, 0x3F800000u);
  // Above half (round bit 1, the guard word non-zero): up.
  EXPECT_EQ(round(127, 0x80000080u, 1).a, 0x3F800001u);
  // Above half through B's own low bits.
  EXPECT_EQ(round(127, 0x800000C0u, 0).a, 0x3F800001u);
  // Exactly half: to the even neighbour, down from #3F800000, up from the odd #3F800001.
  EXPECT_EQ(round(127, 0x80000080u, 0).a, 0x3F800000u);
  EXPECT_EQ(round(127, 0x80000180u, 0).a, 0x3F800002u);
  // A carry out of the fraction raises the exponent: (2 - 2^-24) rounds to 2.0.
  EXPECT_EQ(round(127, 0xFFFFFF80u, 0).a, 0x40000000u);
  // ... and from the largest finite magnitude to infinity.
  EXPECT_EQ(round(254, 0xFFFFFF80u, 1).a, 0x7F800000u);
  // The largest denormal plus more than half an ulp becomes the smallest normal number.
  EXPECT_EQ(round(0, 0x7FFFFF80u, 1).a, 0x00800000u);
  // A denormal.
  EXPECT_EQ(round(0, 0x00000100u, 0).a, 0x00000001u);
}

TEST(IssT414Float, RoundOverflowGivesInfinity) {
  const Stack s = round(255, 0x80000000u, 0);
  EXPECT_EQ(s.a, 0x7F800000u);
  EXPECT_EQ(s.b, 0x80000000u);
  EXPECT_EQ(s.c, 0u);  // B << 1
  EXPECT_EQ(round(300, 0xC0000001u, 0).c, 0x80000002u);
}

// x * y as the T414's REAL32 library computes it: the product of the unpacked fractions (each
// 1.f or 0.f at bit 31) is P = xf * yf, worth P / 2^62; norm shifts it left `places` until bit 63
// is set, so the biased exponent is (ex + ey - 126) - places, which postnormsn computes from
// workspace word 0 = ex + ey - 126 and C = places. Finite operands only.
Word t414_multiply(Word x, Word y) {
  const std::string program = "ldc " + hex(x) + "\nunpacksn\nstl 1\nstl 2\n" +  // xf, ex
                              "ldc " + hex(y) + "\nunpacksn\nstl 3\nstl 4\n" +  // yf, ey
                              "ldl 2\nldl 4\nadd\nadc -126\nstl 0\n"
                              "ldc 0\nldl 1\nldl 3\nlmul\n"  // B:A = xf * yf
                              "norm\npostnormsn\nroundsn\n"
                              "ldc " +
                              hex((x ^ y) & 0x80000000u) + "\nor\nstl 5\nldl 5";
  return run_t414(program).a;
}

Word host_multiply(Word x, Word y) {
  volatile float fx = as_float(x), fy = as_float(y);  // no folding at compile time
  return bits(fx * fy);
}

void expect_multiply(Word x, Word y) {
  EXPECT_EQ(hex(t414_multiply(x, y)), hex(host_multiply(x, y)))
      << as_float(x) << " * " << as_float(y) << " (" << hex(x) << " * " << hex(y) << ")";
}

TEST(IssT414Float, MultiplyRoundTripsMatchTheHost) {
  const std::vector<std::pair<float, float>> cases = {
      {1.0f, 1.0f},
      {1.5f, 2.0f},
      {0.1f, 0.1f},
      {3.0f, 1.0f / 3.0f},
      {-2.5f, 4.0f},
      {-7.0f, -0.125f},
      {1.0e20f, 1.0e18f},
      {123456.7f, 0.000321f},
      {3.0e38f, 1.0f},
      {1.17549435e-38f, 0.5f},                         // normal to denormal
      {1.0e-30f, 1.0e-10f},                            // a denormal result
      {1.0e-40f, 1.0e10f},                             // a denormal operand, normal result
      {1.0e-45f, 0.75f},                               // 3/4 of the smallest denormal: up to it
      {1.0e-30f, 1.0e-30f},                            // underflow to zero
      {-1.0e-30f, 1.0e-30f},                           // to -0
      {1.0e30f, 1.0e30f},                              // overflow to infinity
      {-1.0e30f, 1.0e30f},                             // to -infinity
      {as_float(0x5F800000u), as_float(0x5F800000u)},  // 2^64 * 2^64 = 2^128: just past
      {3.4028235e38f, 1.0000001f},                     // rounds up past the largest finite
  };
  for (const auto& [x, y] : cases) expect_multiply(bits(x), bits(y));
}

TEST(IssT414Float, MultiplyTiesRoundToEven) {
  // Products exactly halfway between two floats (checked exactly in double: a float product is
  // exact in 48 bits). (1 + 2^-23) * 1.5 = 1.5 + 2^-23 + 2^-24: the lower neighbour is odd, so up;
  // (1 + 3 * 2^-23) * 1.5 = 1.5 + 2^-21 + 2^-24: the lower neighbour is even, so down.
  const std::vector<std::pair<Word, Word>> ties = {
      {0x3F800001u, 0x3FC00000u}, {0x3F800003u, 0x3FC00000u}, {0x3F800001u, 0x40400000u},  // * 3
      {0xBF800003u, 0x3FC00000u},  // negative
      {0x00000003u, 0x3F000000u},  // a denormal halved: 1.5 ulps -> 2
      {0x00000005u, 0x3F000000u},  // 2.5 ulps -> 2
      {0x00000001u, 0x3F000000u},  // half the smallest denormal -> 0
  };
  for (const auto& [x, y] : ties) {
    const double exact = double(as_float(x)) * double(as_float(y));
    const float near = float(exact);
    const float lo = double(near) > exact ? std::nextafter(near, -INFINITY) : near;
    const float hi = std::nextafter(lo, INFINITY);
    EXPECT_EQ(double(lo) + double(hi), 2 * exact) << hex(x) << " * " << hex(y) << " is not a tie";
    expect_multiply(x, y);
  }
}

TEST(IssT414Float, MultiplyManyOperandsMatchTheHost) {
  // A fixed pseudo-random set of finite operands, normal and denormal, of every magnitude.
  std::uint32_t state = 0x2545F491u;
  auto next = [&] {
    state ^= state << 13;
    state ^= state >> 17;
    state ^= state << 5;
    return state;
  };
  int tested = 0;
  while (tested < 200) {
    Word x = next(), y = next();
    if (tested % 2) {  // every other pair in the ordinary range: exponents 100 ... 154
      x = (x & 0x807FFFFFu) | ((100 + x % 55) << 23);
      y = (y & 0x807FFFFFu) | ((100 + y % 55) << 23);
    }
    if ((x & 0x7F800000u) == 0x7F800000u || (y & 0x7F800000u) == 0x7F800000u) continue;
    expect_multiply(x, y);
    ++tested;
  }
}

TEST(IssT414Float, CyclesAreTheDatasheets) {
  // The T414 datasheet's typical cycles, plus 1 for each operation's pfix byte.
  auto cycles = [](const std::string& op) {
    TestMachine m(kT414, kMemory);
    m.boot("ajw 16\nldc 140\nstl 0\nldc 3\nldc #3F800000\nldc 0\n" + op + "\nstopp\n");
    EXPECT_EQ(m.run(), StopReason::idle);
    return m.core.cycle();
  };
  const std::int64_t none = cycles("");
  EXPECT_EQ(cycles("unpacksn") - none, 15 + 1);
  EXPECT_EQ(cycles("postnormsn") - none, 5 + 1);
  EXPECT_EQ(cycles("roundsn") - none, 12 + 1);
  EXPECT_EQ(cycles("ldinf") - none, 1 + 1);
  EXPECT_EQ(cycles("cflerr") - none, 3 + 1);
}

TEST(IssT414Float, TheT800HasNoneOfThem) {
  for (const char* op : {"unpacksn", "postnormsn", "roundsn", "ldinf", "cflerr"}) {
    TestMachine m(t800::ProcessorType::T800_20, kMemory);
    m.boot(std::string("ajw 16\nldc 1\n") + op + "\nstopp\n");
    EXPECT_EQ(m.run(), StopReason::halted) << op;
    ASSERT_TRUE(m.core.halt_report().has_value());
    EXPECT_NE(m.core.halt_report()->reason.find("not an instruction of the T800"),
              std::string::npos)
        << m.core.halt_report()->reason;
  }
}

}  // namespace
