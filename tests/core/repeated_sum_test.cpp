// add_repeatedly (t800/repeated_sum.hpp) must land on the very double a loop of additions reaches:
// a closed-form message adds its packets' busy time in one call, and the reports of the fidelity
// levels are compared bit for bit. The reference is the loop itself.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <random>

#include "t800/repeated_sum.hpp"

namespace {

double loop(double sum, double term, std::int64_t times) {
  for (std::int64_t i = 0; i < times; ++i) sum += term;
  return sum;
}

void expect_as_loop(double sum, double term, std::int64_t times) {
  const double expected = loop(sum, term, times);
  const double got = t800::add_repeatedly(sum, term, times);
  EXPECT_EQ(got, expected) << std::hexfloat << "sum " << sum << " term " << term << " times "
                           << times;
}

// The durations links add: packets of 11 and 2 bits at 5, 10 and 20 Mbit/s, in microseconds as
// LinkActivity computes them.
TEST(RepeatedSum, PacketDurationsFromAnyRunningTotal) {
  const double bit_us[] = {0.2, 0.1, 0.05};
  std::mt19937_64 random(14);
  std::uniform_real_distribution<double> start(0, 1e7);
  for (double bit : bit_us)
    for (double term : {bit * 11, bit * 2})
      for (std::int64_t times : {0, 1, 2, 3, 4, 5, 17, 4096, 100000}) {
        expect_as_loop(0, term, times);
        for (int i = 0; i < 20; ++i) expect_as_loop(start(random), term, times);
      }
}

// Terms exactly halfway between two doubles of the sum's binade round to even: the step differs
// with the sum's parity until the first such rounding.
TEST(RepeatedSum, TermsHalfwayBetweenDoublesRoundToEven) {
  for (double sum : {1.0, 1.0 + 0x1p-52, 3.0, 3.0 + 0x1p-51, 1024.0 + 0x1p-42})
    for (int half : {1, 3, 5, 7})
      for (std::int64_t times : {3, 4, 9, 1000, 123457}) {
        const double ulp = std::ldexp(1.0, std::ilogb(sum) - 52);
        expect_as_loop(sum, half * ulp / 2, times);
      }
}

// Sums crossing many binades, terms lost in the sum, terms below half an ulp.
TEST(RepeatedSum, CrossingBinadesAndVanishingTerms) {
  expect_as_loop(0.5, 0.3, 1000000);
  expect_as_loop(1e-3, 1e-3, 100000);
  expect_as_loop(0x1p53, 1.0, 1000);  // 1 is half an ulp: lost, ties to even
  expect_as_loop(0x1p53 + 2, 1.0, 1000);
  expect_as_loop(1e20, 1e3, 100000);
  std::mt19937_64 random(6);
  std::uniform_real_distribution<double> unit(0, 1);
  for (int i = 0; i < 200; ++i) {
    const double sum = std::ldexp(unit(random), int(unit(random) * 60) - 20);
    const double term = std::ldexp(unit(random) + 0.5, int(unit(random) * 30) - 20);
    expect_as_loop(sum, term, std::int64_t(unit(random) * 50000));
  }
}

}  // namespace
