// A deadlock report says who waits for whom: the cycle of waits when the blocked processes close
// one, else where the waits end (a process that has ended, or nobody at the other end of a
// channel).
#include <gtest/gtest.h>

#include "core_fixtures.hpp"

namespace {

using network::Machine;
using network::Process;
using t800::Priority;

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

// Occam's classic mistake: both ends output first, so each waits for the other to input.
TEST(WaitCycle, TwoProcessesThatBothOutputFirst) {
  Machine m(core_test::chain(1), core_test::options(20));
  auto& there = m.channel("there", 0, 1);
  auto& back = m.channel("back", 1, 0);
  m.spawn(0, "left", Priority::low, [&](Process& p) {
    p.out(there, {4, {}, "x"});
    p.in(back);
  });
  m.spawn(1, "right", Priority::low, [&](Process& p) {
    p.out(back, {4, {}, "y"});
    p.in(there);
  });
  ASSERT_EQ(m.run().size(), 2u);
  const std::vector<std::string>& cycle = m.wait_cycle();
  ASSERT_EQ(cycle.size(), 2u);
  EXPECT_EQ(cycle[0], "left on P0 waits to output on channel there for right on P1");
  EXPECT_EQ(cycle[1], "right on P1 waits to output on channel back for left on P0");
}

// The master hands work to two workers and collects the results; worker 2 was wired to a channel
// the master never writes. work2 and spare share the link P0 -> P2, so both are routed: the
// master's output is taken by P2's router, and the master waits for worker 2's result, worker 2 for
// the master.
TEST(WaitCycle, AMisWiredFarm) {
  Machine m(core_test::tree(2), core_test::options(20));
  auto& work1 = m.channel("work1", 0, 1);
  auto& work2 = m.channel("work2", 0, 2);
  auto& wrong = m.channel("spare", 0, 2);  // declared, never written
  auto& result1 = m.channel("result1", 1, 0);
  auto& result2 = m.channel("result2", 2, 0);
  m.spawn(0, "master", Priority::low, [&](Process& p) {
    p.out(work1, {8, {}, "work"});
    p.out(work2, {8, {}, "work"});
    p.in(result1);
    p.in(result2);
  });
  m.spawn(1, "worker1", Priority::low, [&](Process& p) {
    p.in(work1);
    p.out(result1, {8, {}, "result"});
  });
  m.spawn(2, "worker2", Priority::low, [&](Process& p) {
    p.in(wrong);
    p.out(result2, {8, {}, "result"});
  });
  const auto blocked = m.run();
  ASSERT_EQ(blocked.size(), 2u);
  const std::vector<std::string>& cycle = m.wait_cycle();
  ASSERT_EQ(cycle.size(), 2u);
  EXPECT_EQ(cycle[0], "master on P0 waits to input from channel result2 for worker2 on P2");
  EXPECT_EQ(cycle[1], "worker2 on P2 waits to input from channel spare for master on P0");
}

// A three-stage pipeline whose last stage ends without reading: no cycle; the middle stage waits
// for a reader that has ended, the first for the middle one.
TEST(WaitCycle, ALastStageThatNeverReads) {
  Machine m(core_test::chain(2), core_test::options(20));
  auto& first = m.channel("first", 0, 1);
  auto& second = m.channel("second", 1, 2);
  m.spawn(0, "source", Priority::low, [&](Process& p) {
    for (int i = 0; i < 2; ++i) p.out(first, {4, {}, "item"});
  });
  m.spawn(1, "middle", Priority::low, [&](Process& p) {
    for (int i = 0; i < 2; ++i) p.out(second, {4, {}, "item"}), p.in(first);
  });
  m.spawn(2, "sink", Priority::low, [&](Process& p) { p.compute(100, "not reading"); });
  const auto blocked = m.run();
  ASSERT_EQ(blocked.size(), 2u);
  EXPECT_TRUE(m.wait_cycle().empty());
  for (const network::BlockedProcess& b : blocked) {
    if (b.process == "middle")
      EXPECT_EQ(b.waits_for, "nobody: no process on P2 inputs from channel second") << b.waits_for;
    else
      EXPECT_TRUE(contains(b.waits_for, "middle on P1")) << b.waits_for;
  }
}

}  // namespace
