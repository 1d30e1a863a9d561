// The recorder behind traces: totals always, intervals only when asked (docs/architecture.md: when no trace is
// asked for, nothing per-interval is stored). Each test runs one small SystemC simulation (one per
// process).
#include <gtest/gtest.h>

#include <systemc>

#include "t800/activity.hpp"

using sc_core::SC_NS;
using sc_core::sc_time;
using t800::ProcessorState;

namespace {

struct Driver : sc_core::sc_module {
  t800::ProcessorActivity cpu;
  t800::LinkActivity link;

  Driver(const sc_core::sc_module_name& name, bool keep) : sc_module(name) {
    cpu.keep_intervals(keep);
    link.keep_intervals(keep);
    SC_THREAD(body);
  }
  SC_HAS_PROCESS(Driver);

  void body() {
    cpu.set_cpu(ProcessorState::compute, "D11");
    wait(10, SC_NS);
    cpu.set_cpu(ProcessorState::idle);
    cpu.transfer_begin();  // a link engine moves a message: communicating with an idle CPU
    link.packet(sc_core::sc_time_stamp(), sc_time(550, SC_NS), true);
    wait(550, SC_NS);
    link.packet(sc_core::sc_time_stamp(), sc_time(100, SC_NS),
                false);  // the acknowledge, back to back
    wait(100, SC_NS);
    cpu.transfer_end();
    link.message_done(1, "torques");
    wait(40, SC_NS);
    cpu.close(sc_core::sc_time_stamp());
  }
};

}  // namespace

TEST(Activity, WithoutATraceOnlyTotalsAreKept) {
  Driver d("driver", false);
  sc_core::sc_start();
  EXPECT_NEAR(d.cpu.compute_us(), 0.010, 1e-12);
  EXPECT_NEAR(d.cpu.communicate_us(), 0.650, 1e-12);
  EXPECT_NEAR(d.link.busy_us(), 0.650, 1e-12);
  EXPECT_TRUE(d.cpu.intervals().empty());
  EXPECT_TRUE(d.link.intervals().empty());
}

TEST(Activity, WithATraceIntervalsCarryStatesAndLabels) {
  Driver d("driver", true);
  sc_core::sc_start();
  const auto& cpu = d.cpu.intervals();
  ASSERT_EQ(cpu.size(), 2u);
  EXPECT_EQ(cpu[0].state, int(ProcessorState::compute));
  EXPECT_EQ(cpu[0].label, "D11");
  EXPECT_NEAR(cpu[0].end_us - cpu[0].start_us, 0.010, 1e-12);
  EXPECT_EQ(cpu[1].state, int(ProcessorState::communicate));
  EXPECT_NEAR(cpu[1].end_us - cpu[1].start_us, 0.650, 1e-12);
  // Packets that touch are one slice, named after the message once it is done.
  const auto& link = d.link.intervals();
  ASSERT_EQ(link.size(), 1u);
  EXPECT_EQ(link[0].label, "torques");
  EXPECT_NEAR(link[0].end_us - link[0].start_us, 0.650, 1e-12);
}
