// The FPU's software rounding (every directed mode, and round-to-nearest where an operand is an
// unrounded REAL32) against an independent oracle: this host's IEEE 754 hardware, put in each
// rounding mode with fesetround, on many operands from a fixed generator (denormals, ties, near
// cancellation, overflow). The T800's own choices are left out: NaN results (its NaNs are not the
// host's) and operations on infinities; the FP error flag is compared with the host's invalid,
// division-by-zero and overflow flags. The host operation runs in a function the compiler may not
// look into or move (noipa), so no flag such as -frounding-math is needed for the oracle.
#include <gtest/gtest.h>

#include <cfenv>
#include <cmath>
#include <cstdint>
#include <cstring>

#include "t800/iss/fpu.hpp"

namespace {

using t800::iss::Fpu;
using R = Fpu::Rounding;

const R kModes[] = {R::nearest, R::zero, R::plus, R::minus};
const int kHostModes[] = {FE_TONEAREST, FE_TOWARDZERO, FE_UPWARD, FE_DOWNWARD};

enum HostOp { kAdd, kSub, kMul, kDiv, kSqrt, kNarrow, kIntegral };

template <typename T>
__attribute__((noipa)) T host(int op, T x, T y) {
  switch (op) {
    case kAdd:
      return x + y;
    case kSub:
      return x - y;
    case kMul:
      return x * y;
    case kDiv:
      return x / y;
    case kSqrt:
      return std::sqrt(y);
    case kIntegral:
      return std::nearbyint(y);
  }
  return x;
}
__attribute__((noipa)) float host_narrow(double y) {
  return float(y);
}
__attribute__((noipa)) float host_from_int(std::int32_t n) {
  return float(n);
}
__attribute__((noipa)) double host_widen(float y) {
  return double(y);
}

struct HostResult {
  std::uint64_t bits;
  bool error;
};

template <typename T, typename F>
HostResult in_mode(int mode, F f) {
  std::feclearexcept(FE_ALL_EXCEPT);
  std::fesetround(kHostModes[mode]);
  const T r = f();
  std::fesetround(FE_TONEAREST);
  const bool e = std::fetestexcept(FE_INVALID | FE_DIVBYZERO | FE_OVERFLOW) != 0;
  std::uint64_t bits = 0;
  std::memcpy(&bits, &r, sizeof r);
  return {bits, e};
}

// A fixed xorshift generator of operand patterns: random, denormal, close in exponent to the
// other operand (cancellation), or with a short fraction (ties).
struct Gen {
  std::uint64_t s = 0x9E3779B97F4A7C15u;
  std::uint64_t next() {
    s ^= s << 13;
    s ^= s >> 7;
    s ^= s << 17;
    return s;
  }
  std::uint64_t real64(std::uint64_t near) {
    const std::uint64_t r = next(), kind = r % 4;
    std::uint64_t sign = (r >> 8) & 1, exp = (r >> 16) % 2047, frac = next() & 0xFFFFFFFFFFFFF;
    if (kind == 1) exp = 0;
    if (kind == 2)
      exp = std::uint64_t(std::max<std::int64_t>(
          0, std::min<std::int64_t>(
                 2046, std::int64_t((near >> 52) & 0x7FF) + std::int64_t(r >> 58) - 31)));
    if ((r >> 20) % 3 == 0) frac &= ~((std::uint64_t(1) << (r >> 26) % 52) - 1);
    return sign << 63 | exp << 52 | frac;
  }
  std::uint32_t real32(std::uint32_t near) {
    const std::uint64_t r = next(), kind = r % 4;
    std::uint32_t sign = (r >> 8) & 1, exp = (r >> 16) % 255, frac = next() & 0x7FFFFF;
    if (kind == 1) exp = 0;
    if (kind == 2)
      exp = std::uint32_t(std::max(0, std::min(254, int((near >> 23) & 0xFF) + int(r >> 59) - 15)));
    if ((r >> 20) % 3 == 0) frac &= ~((1u << (r >> 26) % 23) - 1);
    return sign << 31 | exp << 23 | frac;
  }
};

bool host_nan64(std::uint64_t b) {
  return (b & 0x7FF0000000000000) == 0x7FF0000000000000 && (b & 0xFFFFFFFFFFFFF) != 0;
}
bool host_nan32(std::uint64_t b) {
  return (b & 0x7F800000) == 0x7F800000 && (b & 0x7FFFFF);
}

constexpr int kPairs = 40000;

TEST(FpuHostOracle, Real64ArithmeticInDirectedModes) {
  Gen g;
  const int ops[] = {kAdd, kSub, kMul, kDiv, kSqrt};
  void (Fpu::*fpu_ops[])() = {&Fpu::add, &Fpu::sub, &Fpu::mul, &Fpu::div};
  int compared = 0;
  for (int i = 0; i < kPairs; ++i) {
    const std::uint64_t x = g.real64(0), y = g.real64(x);
    double dx, dy;
    std::memcpy(&dx, &x, 8);
    std::memcpy(&dy, &y, 8);
    for (int m = 1; m < 4; ++m) {
      for (int op : ops) {
        const HostResult h = in_mode<double>(m, [&] { return host<double>(op, dx, dy); });
        if (host_nan64(h.bits)) continue;
        Fpu f;
        f.load_double(x);
        f.load_double(y);
        if (op == kSqrt) {
          f.sqrt_first();
          f.set_rounding(kModes[m]);
          f.sqrt_last();
        } else {
          f.set_rounding(kModes[m]);
          (f.*fpu_ops[op])();
        }
        ASSERT_EQ(f.fa().bits, h.bits)
            << std::hex << "op " << op << " mode " << m << " x " << x << " y " << y;
        ASSERT_EQ(f.error(), h.error) << std::hex << "op " << op << " x " << x << " y " << y;
        ++compared;
      }
    }
  }
  EXPECT_GT(compared, kPairs * 3 * 4);
}

// REAL32 operations in the directed modes (canonical operands) and in all four modes with both
// operands unrounded (fpunoround of their exact REAL64 values), which takes the software path in
// round-to-nearest too.
TEST(FpuHostOracle, Real32ArithmeticInEveryMode) {
  Gen g;
  const int ops[] = {kAdd, kSub, kMul, kDiv};
  void (Fpu::*fpu_ops[])() = {&Fpu::add, &Fpu::sub, &Fpu::mul, &Fpu::div};
  for (int i = 0; i < kPairs; ++i) {
    const std::uint32_t x = g.real32(0), y = g.real32(x);
    float fx, fy;
    std::memcpy(&fx, &x, 4);
    std::memcpy(&fy, &y, 4);
    for (int m = 0; m < 4; ++m) {
      for (int op : ops) {
        const HostResult h = in_mode<float>(m, [&] { return host<float>(op, fx, fy); });
        if (host_nan32(h.bits)) continue;
        for (int wide = 0; wide < 2; ++wide) {
          if (m != 0 && wide) continue;
          Fpu f;
          if (wide) {
            f.load_double(in_mode<double>(0, [&] { return host_widen(fx); }).bits);
            f.no_round();
            f.load_double(in_mode<double>(0, [&] { return host_widen(fy); }).bits);
            f.no_round();
          } else {
            f.load_single(x);
            f.load_single(y);
          }
          f.set_rounding(kModes[m]);
          (f.*fpu_ops[op])();
          ASSERT_EQ(f.fa().bits, h.bits) << std::hex << "op " << op << " mode " << m << " wide "
                                         << wide << " x " << x << " y " << y;
          ASSERT_EQ(f.error(), h.error) << std::hex << "op " << op << " x " << x << " y " << y;
        }
      }
    }
  }
}

TEST(FpuHostOracle, ConversionsAndIntegralInEveryMode) {
  Gen g;
  for (int i = 0; i < kPairs; ++i) {
    const std::uint64_t y = g.real64(0x4700000000000000);  // many near REAL32's range limits
    double dy;
    std::memcpy(&dy, &y, 8);
    if (host_nan64(y)) continue;
    const auto n = std::int32_t(std::uint32_t(g.next()) >> (g.next() % 32));
    for (int m = 0; m < 4; ++m) {
      const HostResult h = in_mode<float>(m, [&] { return host_narrow(dy); });
      Fpu f;
      f.load_double(y);
      f.set_rounding(kModes[m]);
      f.real64_to_real32();
      ASSERT_EQ(f.fa().bits, h.bits) << std::hex << "mode " << m << " y " << y;
      const bool inf = (y & 0x7FF0000000000000) == 0x7FF0000000000000;
      if (!inf) {
        ASSERT_EQ(f.error(), h.error) << std::hex << "mode " << m << " y " << y;
      }

      const HostResult hi = in_mode<double>(m, [&] { return host<double>(kIntegral, 0, dy); });
      Fpu fi;
      fi.load_double(y);
      fi.set_rounding(kModes[m]);
      fi.to_integral();
      ASSERT_EQ(fi.fa().bits, hi.bits) << std::hex << "mode " << m << " y " << y;

      const HostResult hn = in_mode<float>(m, [&] { return host_from_int(n); });
      Fpu fn;
      fn.set_rounding(kModes[m]);
      fn.load_int32_as_real32(n);
      ASSERT_EQ(fn.fa().bits, hn.bits) << "mode " << m << " n " << n;
    }
    if (!std::isinf(dy) && std::fabs(dy) < 1e18) {  // fpstnli32 is floor mod 2^32
      Fpu f;
      f.load_double(y);
      ASSERT_EQ(f.store_int32(), std::uint32_t(std::int64_t(std::floor(dy)))) << std::hex << y;
    }
  }
}

}  // namespace
