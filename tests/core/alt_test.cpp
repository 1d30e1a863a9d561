// occam's ALT, timers and PRI PAR on the simulated processors: which guard an ALT takes and when,
// on every kind of channel, the two clocks' resolution, and what an ALT costs by the datasheet.
#include <gtest/gtest.h>

#include "core_fixtures.hpp"
#include "network/alt.hpp"

namespace {

using network::Guard;
using network::Process;

constexpr double kCycleUs = 0.05;  // T800-20

Guard input(network::Channel& c, bool enabled = true) {
  Guard g;
  g.kind = Guard::Kind::input;
  g.channel = &c;
  g.enabled = enabled;
  return g;
}

Guard timer(std::int64_t after) {
  Guard g;
  g.kind = Guard::Kind::timer;
  g.after = after;
  return g;
}

// Two writers on one processor, the second channel's first: the ALT takes the guard that became
// ready, then inputs from it.
TEST(Alt, TakesTheGuardThatIsReady) {
  network::Machine m(core_test::chain(1), core_test::options(20));
  auto& a = m.channel("a", 0, 0);
  auto& b = m.channel("b", 0, 0);
  int chosen = -1;
  double when = 0;
  // High-priority writers waiting on their timers (1 us ticks): the CPU stays free.
  m.spawn(0, "late", t800::Priority::high, [&](Process& p) {
    p.wait_after(19);  // 20 us
    p.out(a, {4, {}, "a"});
  });
  m.spawn(0, "early", t800::Priority::high, [&](Process& p) {
    p.wait_after(9);  // 10 us
    p.out(b, {4, {}, "b"});
  });
  m.spawn(0, "alter", t800::Priority::low, [&](Process& p) {
    chosen = network::alternate(p, {input(a), input(b)});
    when = p.now_us();
    p.in(chosen == 0 ? a : b);
    p.in(chosen == 0 ? b : a);
  });
  ASSERT_TRUE(m.run().empty());
  EXPECT_EQ(chosen, 1);
  EXPECT_LT(when, 20.0);
}

// Both ready before the ALT: the first in order (PRI ALT); a false pre-condition hides a ready
// guard; a SKIP guard is always ready.
TEST(Alt, OrderPreconditionsAndSkip) {
  network::Machine m(core_test::chain(1), core_test::options(20));
  auto& a = m.channel("a", 0, 0);
  auto& b = m.channel("b", 0, 0);
  std::vector<int> chosen;
  for (auto* c : {&a, &b})
    m.spawn(0, "writer", t800::Priority::low, [c](Process& p) { p.out(*c, {4, {}, "x"}); });
  m.spawn(0, "alter", t800::Priority::low, [&](Process& p) {
    p.compute(1000, "later");
    chosen.push_back(network::alternate(p, {input(a), input(b)}));
    chosen.push_back(network::alternate(p, {input(a, false), input(b)}));
    Guard skip;
    chosen.push_back(network::alternate(p, {input(a, false), skip}));
    p.in(a);
    p.in(b);
  });
  ASSERT_TRUE(m.run().empty());
  EXPECT_EQ(chosen, (std::vector<int>{0, 1, 1}));
}

// A timer guard: at low priority the clock ticks every 64 us, so AFTER t is ready at (t+1) * 64 us.
TEST(Alt, TimerGuardFiresWhenTheClockPassesItsTime) {
  network::Machine m(core_test::chain(1), core_test::options(20));
  auto& never = m.channel("never", 1, 0);
  double when = 0;
  std::int64_t start = 0;
  m.spawn(0, "alter", t800::Priority::low, [&](Process& p) {
    start = p.clock();
    EXPECT_EQ(network::alternate(p, {input(never), timer(start + 3)}), 1);
    when = p.now_us();
  });
  ASSERT_TRUE(m.run().empty());
  EXPECT_EQ(start, 0);
  EXPECT_GE(when, 4 * 64.0);
  EXPECT_LT(when, 4 * 64.0 + 5.0);  // the ALT's disabling after the wake
}

// A high-priority clock counts microseconds, a low-priority one 64 us ticks; TIMER ? AFTER waits
// for the first tick past its time.
TEST(Timer, ClocksTickAtTheirPriority) {
  network::Machine m(core_test::chain(1), core_test::options(20));
  std::int64_t high = -1, low = -1;
  double woke = 0;
  m.spawn(0, "high", t800::Priority::high, [&](Process& p) {
    p.wait_after(99);  // the clock reads 100 at 100 us
    woke = p.now_us();
    high = p.clock();
  });
  m.spawn(0, "low", t800::Priority::low, [&](Process& p) {
    p.compute(4000, "200 us");
    low = p.clock();
  });
  ASSERT_TRUE(m.run().empty());
  EXPECT_NEAR(woke, 100.0, 2.0);
  EXPECT_EQ(high, 100);
  EXPECT_EQ(low, 3);  // 200-odd us / 64 us
}

// An ALT on a link channel and on a routed channel.
TEST(Alt, WorksOnLinkAndRoutedChannels) {
  // P0 - P1 - P2 - P3: P0's channel to P1 has its link direction alone; P3's reaches P1 through P2.
  network::Machine m(core_test::chain(3), core_test::options(20));
  auto& direct = m.channel("direct", 0, 1);
  auto& routed = m.channel("routed", 3, 1);
  std::vector<int> order;
  m.spawn(0, "near", t800::Priority::low, [&](Process& p) {
    p.compute(2000, "100 us");
    p.out(direct, {16, {}, "near"});
  });
  m.spawn(3, "far", t800::Priority::low, [&](Process& p) { p.out(routed, {16, {}, "far"}); });
  m.spawn(1, "alter", t800::Priority::low, [&](Process& p) {
    for (int i = 0; i < 2; ++i) {
      const int g = network::alternate(p, {input(direct), input(routed)});
      order.push_back(g);
      p.in(g == 0 ? direct : routed);
    }
  });
  ASSERT_TRUE(m.run().empty());
  EXPECT_STREQ(direct.transport->kind_name(), "direct");
  EXPECT_STREQ(routed.transport->kind_name(), "routed");
  EXPECT_EQ(order, (std::vector<int>{1, 0}));  // the far message first, the near one after 100 us
}

// What an ALT with one ready input guard costs, by the datasheet's table plus a cycle per prefix
// byte: alt (pfix + 2), ldl 2, ldc 1, enbc ready (pfix + 7), altwt ready (pfix + 5); then ldl 2,
// ldc 1, ldc 1, disc (pfix + 8), altend (pfix + 4): 20 + 18 = 38 cycles.
TEST(Alt, CostsItsInstructions) {
  network::Machine m(core_test::chain(1), core_test::options(20));
  auto& a = m.channel("a", 0, 0);
  double before = 0, after = 0;
  m.spawn(0, "writer", t800::Priority::low, [&](Process& p) { p.out(a, {4, {}, "x"}); });
  m.spawn(0, "alter", t800::Priority::low, [&](Process& p) {
    p.compute(1000, "let the writer wait");
    before = p.now_us();
    network::alternate(p, {input(a)});
    after = p.now_us();
    p.in(a);
  });
  ASSERT_TRUE(m.run().empty());
  EXPECT_NEAR(after - before, 38 * kCycleUs, 1e-6);
}

// PRI PAR: the high-priority branch, woken by its timer, takes the CPU from the low-priority one.
TEST(PriPar, HighBranchPreemptsTheLowOnes) {
  network::Machine m(core_test::chain(1), core_test::options(20));
  double high_done = 0, low_done = 0;
  m.spawn(0, "parent", t800::Priority::low, [&](Process& p) {
    p.pri_par(
        [&](Process& q) {
          q.wait_after(49);  // 50 us
          q.compute(100, "urgent");
          high_done = q.now_us();
        },
        {[&](Process& q) {
          q.compute(20000, "1 ms of background");
          low_done = q.now_us();
        }});
  });
  ASSERT_TRUE(m.run().empty());
  EXPECT_LT(high_done, 60.0);
  EXPECT_GT(low_done, 1000.0);
}

}  // namespace
