// A program's word to the run's fault report through the SDK (Process::fault_detected and
// fault_recovered): a fault that took effect on the path named counts, once; the first detection
// and the first recovery are the ones the report keeps; a path off the fault counts nothing; a
// processor the network lacks is an error.
#include <gtest/gtest.h>

#include "sdk_fixtures.hpp"

namespace {

using namespace t800sim;
using sdk_test::Lambda;

network::FaultSpec drop_on_p0_to_p1() {
  network::FaultSpec f;
  f.kind = network::FaultSpec::Kind::drop;
  f.from = "P0";
  f.to = "P1";
  f.at_us = 0;
  return f;
}

// P0 -> P1 drops its first byte: the sender's OutputOrFail gives up at 200 us, the receiver's
// InputOrFail at 300 us; the sender reports what it saw and how it went on.
TEST(SdkFaultReport, ADetectedAndRecoveredFaultIsReportedOnceWithTheFirstWords) {
  bool delivered = true;
  int on_path = -1, again = -1, elsewhere = -1, after_recovery = -1;
  bool unknown_rejected = false;
  double detected_at_us = -1;
  auto* program = new Lambda([&](Builder& b) {
    const auto c = b.channel<INT>("c", "sender", "receiver");
    b.process("sender", [&, c](Process& p) {
      delivered = p.out_or_fail(c.out(), 42, 200.0);
      detected_at_us = p.now_us();
      elsewhere = p.fault_detected({"P1", "P2"}, "nobody");
      on_path = p.fault_detected({"P0", "P1"}, "the sender's deadline");
      again = p.fault_detected({"P0", "P1"}, "a second look");
      p.fault_recovered({"P0", "P1"}, "the sender went on without it");
      after_recovery = p.fault_detected({"P0", "P1"}, "a third look");
      try {
        p.fault_detected({"P0", "P9"}, "a typo");
      } catch (const std::invalid_argument&) {
        unknown_rejected = true;
      }
    });
    b.process("receiver", [c](Process& p) { p.in_or_fail(c.in(), 300.0); }).placed_on("P1");
  });
  const auto o = sdk_test::run(program, sdk_test::chain(2), {}, {drop_on_p0_to_p1()});
  ASSERT_TRUE(o.blocked.empty());
  EXPECT_FALSE(delivered);
  EXPECT_EQ(elsewhere, 0);  // P1 -> P2 is another link
  EXPECT_EQ(on_path, 1);
  EXPECT_EQ(again, 1);           // still unrecovered: it counts, the first words stay
  EXPECT_EQ(after_recovery, 0);  // recovered faults count no more
  EXPECT_TRUE(unknown_rejected);
  ASSERT_EQ(o.faults.size(), 1u);
  const network::FaultRecord& r = o.faults.front();
  EXPECT_TRUE(r.fired);
  EXPECT_EQ(r.detected_by, "the sender's deadline");
  EXPECT_EQ(r.detected_us, detected_at_us);
  EXPECT_EQ(r.recovered_how, "the sender went on without it");
  EXPECT_EQ(r.recovered_us, detected_at_us);  // the same instant: nothing ran in between
}

// A halted processor is on a path when the path passes through it (not only at its end).
TEST(SdkFaultReport, AHaltedProcessorCountsOnAPathThroughIt) {
  network::FaultSpec halt;
  halt.kind = network::FaultSpec::Kind::halt;
  halt.processor = "P1";
  halt.at_us = 0;
  int through = -1, beside = -1;
  auto* program = new Lambda([&](Builder& b) {
    b.process("watcher", [&](Process& p) {
      p.wait_after(p.timer() + 10);  // low priority: 640 us; the halt has taken effect
      beside = p.fault_detected({"P0"}, "a path that misses P1");
      through = p.fault_detected({"P0", "P1", "P2"}, "the watcher");
    });
    b.process("victim", [](Process& p) { p.compute(100000); }).placed_on("P1");
  });
  const auto o = sdk_test::run(program, sdk_test::chain(2), {}, {halt});
  EXPECT_EQ(beside, 0);
  EXPECT_EQ(through, 1);
  ASSERT_EQ(o.faults.size(), 1u);
  EXPECT_EQ(o.faults.front().detected_by, "the watcher");
  EXPECT_TRUE(o.faults.front().recovered_how.empty());
}

}  // namespace
