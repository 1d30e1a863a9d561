// ALT through the SDK: the guard that became ready first is served first, a timer guard fires at
// its time (1 us ticks at high priority), a false pre-condition hides a ready guard and SKIP is
// taken when nothing else is ready.
#include <gtest/gtest.h>

#include "sdk_fixtures.hpp"

namespace {

using namespace t800sim;
using sdk_test::Lambda;

// Three high-priority writers on P0 wait on their timers (30, 20, 10 us) before sending their
// number; the master serves them as they become ready.
TEST(SdkAlt, ServesTheGuardsInTheOrderTheyBecomeReady) {
  std::vector<int> served;
  auto* program = new Lambda([&](Builder& b) {
    const auto c = b.channels<INT>("c", 3, "writer", "master");
    b.processes("writer", 3, [c](Process& p, int i) {
       p.wait_after(p.timer() + 10 * (3 - i));
       p.out(c[std::size_t(i)], i);
     }).high();
    b.process("master", [c, &served](Process& p) {
      for (int k = 0; k < 3; ++k)
        Alt(p).input(c, [&served](int, INT v) { served.push_back(v); }).select();
    });
  });
  ASSERT_TRUE(sdk_test::run(program, sdk_test::chain(1)).blocked.empty());
  EXPECT_EQ(served, (std::vector<int>{2, 1, 0}));
}

// At high priority the clock ticks every microsecond: AFTER t0 + 20 is ready 21 ticks after t0.
TEST(SdkAlt, ATimerGuardFiresAtItsTime) {
  int chosen = -1;
  double at_us = 0, t0_us = 0;
  auto* program = new Lambda([&](Builder& b) {
    const auto c = b.channel<INT>("c", "late", "master");
    b.process("late", [c](Process& p) {
       p.wait_after(p.timer() + 100);
       p.out(c, 1);
     }).high();
    b.process("master", [&, c](Process& p) {
       const std::int64_t t0 = p.timer();
       t0_us = p.now_us();
       chosen = Alt(p).input(c, [](INT) {}).after(t0 + 20, [] {}).select();
       at_us = p.now_us();
       p.in(c);
     }).high();
  });
  ASSERT_TRUE(sdk_test::run(program, sdk_test::chain(1)).blocked.empty());
  EXPECT_EQ(chosen, 1);
  EXPECT_GE(at_us, std::floor(t0_us) + 21.0);
  EXPECT_LT(at_us, std::floor(t0_us) + 22.0 + 5.0);  // + the ALT's own instructions (< 100 cycles)
}

TEST(SdkAlt, PreconditionsAndSkip) {
  std::vector<int> chosen;
  auto* program = new Lambda([&](Builder& b) {
    const auto c = b.channel<INT>("c", "writer", "master");
    b.process("writer", [c](Process& p) { p.out(c, 7); }).high();
    b.process("master", [&, c](Process& p) {
      p.wait_after(p.timer() + 1);  // the writer is waiting by now
      chosen.push_back(Alt(p)
                           .input(
                               c, [](INT) {}, false)
                           .skip([] {})
                           .select());
      chosen.push_back(Alt(p).input(c, [](INT) {}).skip([] {}).select());
    });
  });
  ASSERT_TRUE(sdk_test::run(program, sdk_test::chain(1)).blocked.empty());
  EXPECT_EQ(chosen, (std::vector<int>{1, 0}));
}

}  // namespace
