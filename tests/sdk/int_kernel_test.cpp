// t800sim::Int, occam's INT as a recording scalar: it computes what occam's INT arithmetic
// computes (checked + - * / \, / towards zero, \ with the dividend's sign, logical shifts of 0 to
// 32 places, INT ROUND to nearest with ties to even), its misuse is an error naming the kernel,
// and its work is recorded as INT nodes and arrays, counted as integer operations.
#include <gtest/gtest.h>

#include <cstdint>
#include <functional>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "t800sim/kernel.hpp"

namespace {

using t800::codegen::ElementType;
using t800::codegen::KernelError;
using t800::codegen::NodeKind;
using t800sim::Int;
using t800sim::Real32;
using t800sim::Real64;

std::string error_of(const std::function<void()>& body) {
  try {
    t800sim::record_kernel<Real64>("INTS", body);
  } catch (const KernelError& e) {
    return e.what();
  }
  return "(no error)";
}

// The reference: the same operations on 64-bit integers, checked against INT's range by hand.
TEST(IntScalar, ArithmeticIsThatOfTheIntegersWhereTheResultIsAnInt) {
  std::mt19937 random(25);
  std::uniform_int_distribution<std::int32_t> small(-46000, 46000);
  for (int trial = 0; trial < 2000; ++trial) {
    const std::int64_t a = small(random), b = small(random);
    EXPECT_EQ((Int(std::int32_t(a)) + Int(std::int32_t(b))).value(), a + b);
    EXPECT_EQ((Int(std::int32_t(a)) - Int(std::int32_t(b))).value(), a - b);
    EXPECT_EQ((Int(std::int32_t(a)) * Int(std::int32_t(b))).value(), a * b);
    if (b != 0) {
      const std::int64_t q = (Int(std::int32_t(a)) / Int(std::int32_t(b))).value();
      const std::int64_t r = (Int(std::int32_t(a)) % Int(std::int32_t(b))).value();
      EXPECT_EQ(q * b + r, a);                    // a = q b + r
      EXPECT_LT(r < 0 ? -r : r, b < 0 ? -b : b);  // |r| < |b|
      EXPECT_TRUE(r == 0 || (r < 0) == (a < 0));  // r has a's sign (occam's \)
    }
  }
}

TEST(IntScalar, ShiftsAreLogicalFromZeroToThirtyTwoPlaces) {
  EXPECT_EQ((Int(-1) >> Int(28)).value(), 15);
  EXPECT_EQ((Int(1) << Int(31)).value(), std::numeric_limits<std::int32_t>::min());
  EXPECT_EQ((Int(-1) << Int(32)).value(), 0);
  EXPECT_EQ((Int(-1) >> Int(32)).value(), 0);
  EXPECT_EQ((~Int(0)).value(), -1);
  EXPECT_EQ((Int(0x0FF0) & Int(0x00FF)).value(), 0x00F0);
  EXPECT_EQ((Int(0x0F00) | Int(0x00F0)).value(), 0x0FF0);
  EXPECT_EQ((Int(0x0FF0) ^ Int(0x00FF)).value(), 0x0F0F);
}

TEST(IntScalar, ConversionsRoundAsTheFpuDoes) {
  EXPECT_EQ(t800sim::int_round(Real64(2.5)).value(), 2);  // ties to even
  EXPECT_EQ(t800sim::int_round(Real64(3.5)).value(), 4);
  EXPECT_EQ(t800sim::int_round(Real32(-2.5f)).value(), -2);
  EXPECT_EQ(t800sim::int_trunc(Real64(-2.9)).value(), -2);
  EXPECT_EQ(t800sim::to_real<Real64>(Int(16777217)).value(), 16777217.0);   // exact
  EXPECT_EQ(t800sim::to_real<Real32>(Int(16777217)).value(), 16777216.0f);  // to nearest even
}

TEST(IntScalar, WhatIsNotAnIntIsAnErrorNamingTheKernel) {
  const auto expect_error = [](const std::function<void()>& body, const std::string& what) {
    const std::string message = error_of(body);
    EXPECT_NE(message.find("kernel \"INTS\""), std::string::npos) << message;
    EXPECT_NE(message.find(what), std::string::npos) << message;
  };
  expect_error([] { (void)(Int(std::numeric_limits<std::int32_t>::max()) + Int(1)); }, "overflow");
  expect_error([] { (void)(Int(std::numeric_limits<std::int32_t>::min()) - Int(1)); }, "overflow");
  expect_error([] { (void)(Int(65536) * Int(65536)); }, "overflow");
  expect_error([] { (void)(-Int(std::numeric_limits<std::int32_t>::min())); }, "overflow");
  expect_error([] { (void)(Int(std::numeric_limits<std::int32_t>::min()) / Int(-1)); }, "overflow");
  expect_error([] { (void)(Int(7) / Int(0)); }, "division by zero");
  expect_error([] { (void)(Int(7) % Int(0)); }, "division by zero");
  expect_error([] { (void)(Int(1) << Int(33)); }, "shift");
  expect_error([] { (void)(Int(1) >> Int(-1)); }, "shift");
  expect_error([] { (void)t800sim::int_round(Real64(3e9)); }, "not an INT");
}

TEST(IntScalar, AnIntMadeBeforeTheKernelAndReadUndeclaredIsAnError) {
  const Int outside = 3;
  const std::string message = error_of([&] {
    Int y = 2;
    t800sim::declare_variable(y, "y");
    y = y + outside;
  });
  EXPECT_NE(message.find("t800sim::Int"), std::string::npos) << message;
}

// The recording holds INT arrays and INT nodes, the counts integer operations.
TEST(IntScalar, IsRecordedAsIntNodesAndCountedAsIntegerWork) {
  std::vector<Int> x{Int(3), Int(4)};
  Int k = 0;
  const t800sim::Kernel kernel = t800sim::record_kernel<Real64>("K", [&] {
    t800sim::declare(x, "x");
    t800sim::declare_variable(k, "k");
    k = x[0] * x[1] + Int(1);
  });
  const auto& r = *kernel.work().code;
  ASSERT_EQ(r.arrays().size(), 2u);
  EXPECT_EQ(r.arrays()[0].element, ElementType::int32);
  int ints = 0, reals = 0;
  for (const auto& n : r.nodes()) (n.integer ? ints : reals)++;
  EXPECT_EQ(reals, 0);
  EXPECT_GE(ints, 4);  // two loads, a product, a constant, a sum
  EXPECT_EQ(k.value(), 13);
  EXPECT_EQ(kernel.work().mix.int_simple, 1);  // the sum
  EXPECT_EQ(kernel.work().mix.int_mul, 1);     // the product
  EXPECT_EQ(kernel.work().mix.fp_operations(), 0);
}

}  // namespace
