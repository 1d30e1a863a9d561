// A run that will not end is stopped with a report: work handed back and forth at one simulated
// instant is a livelock, and a stop request (SIGINT, SIGTERM) stops a run as a limit does, naming
// what had not ended.
#include <gtest/gtest.h>

#include <csignal>
#include <systemc>

#include "core_fixtures.hpp"
#include "network/stop_request.hpp"

namespace {

using network::Limit;
using network::Machine;
using network::Process;
using t800::Priority;

// Two processes that wake each other at no time at all, for ever, each beating the heart as an
// ISS core does at every synchronisation.
void ping_pong_at_one_instant(Machine& m) {
  auto a = std::make_shared<sc_core::sc_event>(), b = std::make_shared<sc_core::sc_event>();
  m.spawn(0, "ping", Priority::low, [&m, a, b](Process&) {
    for (;;) {
      m.heartbeat();
      b->notify(sc_core::SC_ZERO_TIME);
      sc_core::wait(*a);
    }
  });
  m.spawn(1, "pong", Priority::low, [&m, a, b](Process&) {
    for (;;) {
      m.heartbeat();
      a->notify(sc_core::SC_ZERO_TIME);
      sc_core::wait(*b);
    }
  });
}

TEST(Stop, WorkHandedBackAndForthAtOneInstantIsALivelock) {
  network::MachineOptions options = core_test::options(20);
  options.livelock_heartbeats = 5000;
  Machine m(core_test::chain(1), options);
  ping_pong_at_one_instant(m);
  EXPECT_TRUE(m.run().empty());  // not a deadlock: they never stopped running
  EXPECT_EQ(m.limit_reached(), Limit::livelock);
  EXPECT_EQ(m.simulated_us(), 0.0);
  ASSERT_EQ(m.running_at_stop().size(), 2u);
  EXPECT_EQ(m.running_at_stop()[0].process, "ping");
  EXPECT_EQ(m.running_at_stop()[1].processor, "P1");
}

// Time that advances is progress, however many heartbeats it takes.
TEST(Stop, HeartbeatsWhileTimeAdvancesAreNoLivelock) {
  network::MachineOptions options = core_test::options(20);
  options.livelock_heartbeats = 10;
  Machine m(core_test::chain(1), options);
  m.spawn(0, "ticker", Priority::low, [&m](Process&) {
    for (int i = 0; i < 1000; ++i) {
      m.heartbeat();
      sc_core::wait(sc_core::sc_time(1, sc_core::SC_NS));
    }
  });
  EXPECT_TRUE(m.run().empty());
  EXPECT_EQ(m.limit_reached(), Limit::none);
  EXPECT_NEAR(m.simulated_us(), 1.0, 1e-9);
}

// A stop request is seen at the next look, and the run stops as after a limit, with the signal.
TEST(Stop, AStopRequestStopsTheRunAtTheNextLook) {
  network::MachineOptions options = core_test::options(20);
  Machine m(core_test::chain(1), options);
  m.spawn(0, "forever", Priority::low, [&m](Process& p) {
    p.set_status_text("computing for ever");
    for (std::int64_t i = 0;; ++i) {
      if (i == 5000) network::request_stop(SIGTERM);
      m.heartbeat();
      sc_core::wait(sc_core::sc_time(1, sc_core::SC_NS));
    }
  });
  m.run();
  EXPECT_EQ(m.limit_reached(), Limit::interrupted);
  EXPECT_EQ(m.stop_signal(), SIGTERM);
  // Looked at every 1024 heartbeats: stopped within the next 1024 after the request.
  EXPECT_GE(m.simulated_us(), 5.0);
  EXPECT_LE(m.simulated_us(), 5.0 + 1.024 + 1e-9);
  ASSERT_EQ(m.running_at_stop().size(), 1u);
  EXPECT_EQ(m.running_at_stop()[0].status, "computing for ever");
}

}  // namespace
