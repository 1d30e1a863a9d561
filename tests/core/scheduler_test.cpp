// The T800 scheduler: timeslicing of low-priority processes, preemption by high priority, internal
// channels (docs/t800-timing.md sections 3 and 7).
#include <gtest/gtest.h>

#include "core_fixtures.hpp"

namespace {

constexpr double kCycleUs = 0.05;  // T800-20
const double kSliceUs = t800::timing::kTimesliceUs;

TEST(Timeslicing, TwoLowPriorityProcessesShareTheCpu) {
  auto opts = core_test::options(20);
  opts.keep_intervals = true;
  network::Machine m(core_test::chain(1), opts);
  const std::int64_t cycles = 200000;  // 10 ms each
  double end_us[2] = {0, 0};
  for (int i = 0; i < 2; ++i)
    m.spawn(0, "worker" + std::to_string(i), t800::Priority::low, [&, i](network::Process& p) {
      p.compute(cycles, "w" + std::to_string(i));
      end_us[i] = p.now_us();
    });
  ASSERT_TRUE(m.run().empty());

  // Together they need 20 ms of CPU; sliced, neither finishes near 10 ms.
  EXPECT_NEAR(std::max(end_us[0], end_us[1]), 2 * cycles * kCycleUs, 1e-6);
  EXPECT_GT(std::min(end_us[0], end_us[1]), 2 * cycles * kCycleUs - 2 * kSliceUs - 1e-6);
  // Every slice but the last of each lasts between one and two timeslice periods, and they
  // alternate.
  const auto& slices = m.transputer(0).activity().intervals();
  ASSERT_GE(slices.size(), 6u);
  for (std::size_t i = 0; i + 2 < slices.size(); ++i) {
    const double length = slices[i].end_us - slices[i].start_us;
    EXPECT_GE(length, kSliceUs - 1e-6) << "slice " << i;
    EXPECT_LE(length, 2 * kSliceUs + 1e-6) << "slice " << i;
    EXPECT_NE(slices[i].label, slices[i + 1].label) << "slice " << i;
  }
  EXPECT_GE(m.transputer(0).cpu().statistics().timeslices, 5);
}

TEST(Timeslicing, ALoneProcessIsNeverSliced) {
  network::Machine m(core_test::chain(1), core_test::options(20));
  m.spawn(0, "alone", t800::Priority::low, [](network::Process& p) { p.compute(200000, "alone"); });
  ASSERT_TRUE(m.run().empty());
  EXPECT_EQ(m.transputer(0).cpu().statistics().timeslices, 0);
  EXPECT_NEAR(m.simulated_us(), 200000 * kCycleUs, 1e-6);
}

TEST(Preemption, HighPriorityPreemptsWithinTheLatency) {
  auto opts = core_test::options(20);
  opts.keep_intervals = true;
  network::Machine m(core_test::chain(1), opts);
  auto& wake = m.channel("wake", 1, 0);
  double arrived_us = 0, low_end_us = 0;
  const std::int64_t low_cycles = 200000, high_cycles = 2000;
  // The handler starts first, arms its input and deschedules; the background process then has the
  // CPU.
  m.spawn(0, "handler", t800::Priority::high, [&](network::Process& p) {
    p.in(wake);
    p.compute(high_cycles, "handler");
  });
  m.spawn(0, "background", t800::Priority::low, [&](network::Process& p) {
    p.compute(low_cycles, "background");
    low_end_us = p.now_us();
  });
  m.spawn(1, "sender", t800::Priority::low, [&](network::Process& p) {
    p.compute(20000, "delay");  // 1 ms
    p.out(wake, {4, {}, "wake"});
  });
  ASSERT_TRUE(m.run().empty());
  EXPECT_EQ(m.transputer(0).cpu().statistics().preemptions, 1);  // only the wake-up

  // Find the message's arrival: the end of the link transfer into P0 = the start of the handler's
  // CPU work minus the latency; check the handler's compute began within [typical, max] latency of
  // the arrival.
  const auto& iv = m.transputer(0).activity().intervals();
  double handler_start = -1;
  for (const auto& i : iv)
    if (i.label == "handler") {
      handler_start = i.start_us;
      break;
    }
  ASSERT_GT(handler_start, 0);
  // The 4-byte message arrives at: sender's 1 ms + out set-up, then 3 byte periods + one data
  // packet.
  // A link communication's CPU part: ldlp, ldl, ldc (a length below 16), out/in = 1 + 2 + 1 + 19.
  constexpr int kLinkSetUp = 1 + 2 + 1 + 19;
  arrived_us = 1000.0 + kLinkSetUp * kCycleUs + (3 * 0.575 + 0.55);
  EXPECT_GE(handler_start - arrived_us, t800::timing::kInterruptLatencyTypical * kCycleUs - 1e-6);
  EXPECT_LE(handler_start - arrived_us, t800::timing::kInterruptLatencyMax * kCycleUs + 1e-6);
  // The background process loses exactly the CPU time the handler used, and the memory cycles the
  // input DMA took while it computed (one per byte of the 4-byte message).
  const double handler_cpu = (high_cycles + kLinkSetUp) * kCycleUs;
  const double dma_cycles = 4 * t800::timing::kLinkDmaCyclesPerByte * kCycleUs;
  EXPECT_NEAR(low_end_us, low_cycles * kCycleUs + handler_cpu + dma_cycles, 1e-6);
  EXPECT_EQ(m.transputer(0).cpu().statistics().stolen_cycles,
            4 * t800::timing::kLinkDmaCyclesPerByte);
}

TEST(InternalChannel, SecondToArriveCopiesTheMessage) {
  network::Machine m(core_test::chain(1), core_test::options(20));
  auto& c = m.channel("local", 0, 0);
  double reader_end = 0;
  m.spawn(0, "writer", t800::Priority::low, [&](network::Process& p) { p.out(c, {40, {}, "x"}); });
  m.spawn(0, "reader", t800::Priority::low, [&](network::Process& p) {
    p.compute(1000, "work");
    p.in(c);
    reader_end = p.now_us();
  });
  ASSERT_TRUE(m.run().empty());
  EXPECT_STREQ(c.transport->kind_name(), "internal");
  // Each end: ldlp, ldl, ldc 40 (pfix, ldc), then out/in. The writer arrives first: 1 + 2 + 2 + 19,
  // and deschedules; the reader: 1000, then 1 + 2 + 2 + (2w + 19) with w = 10 words.
  EXPECT_NEAR(reader_end, ((1 + 2 + 2 + 19) + 1000 + (1 + 2 + 2 + 2 * 10 + 19)) * kCycleUs, 1e-6);
}

TEST(Par, BranchesRunConcurrentlyAndJoin) {
  // P1 sends to both its neighbours at once over two different links: the DMA engines run
  // concurrently, so the pair takes about one message time, not two.
  network::Machine m(core_test::chain(2), core_test::options(20));
  auto& left = m.channel("left", 1, 0);
  auto& right = m.channel("right", 1, 2);
  double end_us = 0;
  m.spawn(1, "parent", t800::Priority::low, [&](network::Process& p) {
    p.par({[&](network::Process& q) {
             q.out(left, {1000, {}, "l"});
           },
           [&](network::Process& q) {
             q.out(right, {1000, {}, "r"});
           }});
    end_us = p.now_us();
  });
  m.spawn(0, "left reader", t800::Priority::low, [&](network::Process& p) { p.in(left); });
  m.spawn(2, "right reader", t800::Priority::low, [&](network::Process& p) { p.in(right); });
  ASSERT_TRUE(m.run().empty());
  EXPECT_STREQ(left.transport->kind_name(), "direct");
  const double one_message_us = 1000 * 0.575;
  EXPECT_GT(end_us, one_message_us);
  EXPECT_LT(end_us, 1.02 * one_message_us);
}

}  // namespace
