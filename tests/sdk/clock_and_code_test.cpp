// Ways a process's time is read or charged through the SDK: clock() reads the TIMER without the
// instructions timer() charges, instant() and us_between() measure an interval exactly, and
// cycles(Instructions) prices a sequence of instructions written out, by the T800's instruction
// timings (the T800 datasheet: ldc and add 1 cycle each).
#include <gtest/gtest.h>

#include "sdk_fixtures.hpp"
#include "t800/isa/instruction.hpp"

namespace {

using namespace t800sim;
using sdk_test::Lambda;
using t800::isa::Op;

// At high priority the clock ticks every 1 us. TIMER ? AFTER t wakes the process when the clock
// reads t + 1; clock() then reads that, in no time; timer() reads the same tick, a few cycles
// later.
TEST(SdkClock, ClockReadsTheTimerWithoutChargingIt) {
  std::int64_t t0 = -1, after_wait = -1, by_timer = -1;
  double before_us = -1, after_clock_us = -1, after_timer_us = -1;
  auto* program = new Lambda([&](Builder& b) {
    b.process("p", [&](Process& p) {
       t0 = p.clock();
       p.wait_after(t0 + 10);
       before_us = p.now_us();
       after_wait = p.clock();
       after_clock_us = p.now_us();
       by_timer = p.timer();
       after_timer_us = p.now_us();
     }).high();
  });
  ASSERT_TRUE(sdk_test::run(program, sdk_test::chain(1)).blocked.empty());
  EXPECT_EQ(after_wait, t0 + 11);
  EXPECT_EQ(after_clock_us, before_us);
  EXPECT_EQ(by_timer, after_wait);
  EXPECT_GT(after_timer_us, before_us);
}

// An interval between two instants is exact: the same 3000 cycles (150 us on a T800-20, 50 ns a
// cycle) measure the same, bit for bit, early in the run and after 50 simulated seconds, where a
// difference of now_us() readings is rounded at the absolute times.
TEST(SdkClock, IntervalsBetweenInstantsDoNotDependOnWhenTheyLie) {
  double early_us = -1, late_us = -1;
  auto* program = new Lambda([&](Builder& b) {
    b.process("p", [&](Process& p) {
       auto measure = [&p] {
         const Process::Instant from = p.instant();
         p.compute(3000);
         return Process::us_between(from, p.instant());
       };
       p.compute(7);
       early_us = measure();
       p.compute(1'000'000'001);
       late_us = measure();
     }).high();
  });
  ASSERT_TRUE(sdk_test::run(program, sdk_test::chain(1)).blocked.empty());
  EXPECT_NEAR(early_us, 3000 * 0.05, 1e-9);
  EXPECT_EQ(late_us, early_us);
}

TEST(SdkCode, InstructionsArePricedByTheirTimings) {
  const Instructions code{{Op::ldc, 1, 0, false, {}, "1"},
                          {Op::ldc, 2, 0, false, {}, "2"},
                          {Op::add, 0, 0, false, {}, "+"}};
  std::int64_t cycles = -1;
  double before_us = -1, after_us = -1;
  auto* program = new Lambda([&](Builder& b) {
    b.process("p", [&](Process& p) {
      cycles = p.cycles(code);
      before_us = p.now_us();
      p.compute(p.cycles(code) * 1000);
      after_us = p.now_us();
    });
  });
  ASSERT_TRUE(sdk_test::run(program, sdk_test::chain(1)).blocked.empty());
  EXPECT_EQ(cycles, 3);
  EXPECT_NEAR(after_us - before_us, 3000 * 0.05, 1e-9);  // 3000 cycles of 50 ns
}

}  // namespace
