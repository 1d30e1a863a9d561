// Faults in the link protocol and the CPU (network/faults.hpp, t800/link.hpp, t800/cpu.hpp),
// checked against what the protocol implies: a corrupted byte arrives with its bits flipped (the
// value the receiver reads changes by exactly the mask at that byte), a dropped byte is never
// acknowledged (sender and receiver both wait for ever), a dead link carries nothing after its
// time, a halted processor stops computing at its time; OutputOrFail / InputOrFail give up at their
// deadline.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstdio>
#include <vector>

#include "core_fixtures.hpp"
#include "network/transport/store_and_forward.hpp"
#include "t800/payload_bytes.hpp"

namespace {

using network::FaultSpec;
using network::Machine;
using network::Process;
using t800::Priority;

// A 4-byte INT as a payload, little-endian as the T800 stores it.
void register_word() {
  t800::register_payload_bytes(typeid(std::uint32_t),
                               [](std::any& a, std::int64_t b, std::uint8_t mask) {
                                 auto& v = std::any_cast<std::uint32_t&>(a);
                                 v ^= std::uint32_t(mask) << (8 * b);
                                 return true;
                               });
}

FaultSpec link_fault(FaultSpec::Kind kind, double at_us, int mask = 1) {
  FaultSpec f;
  f.kind = kind;
  f.from = "P0";
  f.to = "P1";
  f.at_us = at_us;
  f.xor_mask = mask;
  return f;
}

FaultSpec halt_fault(const char* processor, double at_us) {
  FaultSpec f;
  f.kind = FaultSpec::Kind::halt;
  f.processor = processor;
  f.at_us = at_us;
  return f;
}

TEST(FaultModel, ACorruptedByteChangesTheValueTheReceiverReads) {
  register_word();
  Machine m(core_test::chain(1), core_test::options(20));
  m.faults().add(link_fault(FaultSpec::Kind::corrupt, 0, 0x80));
  network::arm_faults(m);
  auto& c = m.channel("c", 0, 1);
  std::uint32_t first = 0, second = 0;
  m.spawn(0, "writer", Priority::low, [&](Process& p) {
    p.out(c, {4, std::uint32_t(0x11223344), "word"});
    p.out(c, {4, std::uint32_t(0x11223344), "word"});
  });
  m.spawn(1, "reader", Priority::low, [&](Process& p) {
    first = std::any_cast<std::uint32_t>(p.in(c).payload);
    second = std::any_cast<std::uint32_t>(p.in(c).payload);
  });
  ASSERT_TRUE(m.run().empty());
  EXPECT_EQ(first, 0x112233C4u);   // the first byte on the wire (0x44) arrived as 0x44 ^ 0x80
  EXPECT_EQ(second, 0x11223344u);  // one byte, once
  const network::FaultRecord& r = m.faults().records()[0];
  EXPECT_TRUE(r.fired);
  EXPECT_NE(r.hit.find("byte 1 of 4"), std::string::npos) << r.hit;
}

// A routed message on the wire is the routers' header, then the writer's value: a corrupted byte
// past the header changes the value's byte that many bytes in, one inside it changes nothing.
class RoutedCorruption : public ::testing::TestWithParam<double> {};

TEST_P(RoutedCorruption, ReachesTheWritersValuePastTheHeader) {
  using Bytes = std::vector<std::uint8_t>;
  t800::register_payload_bytes(typeid(Bytes), [](std::any& a, std::int64_t b, std::uint8_t mask) {
    std::any_cast<Bytes&>(a).at(std::size_t(b)) ^= mask;
    return true;
  });
  Machine m(core_test::chain(2), core_test::options(20));
  m.faults().add(link_fault(FaultSpec::Kind::corrupt, GetParam(), 0x80));
  network::arm_faults(m);
  auto& c = m.channel("far", 0, 2);
  Bytes sent(100), received;
  for (std::size_t i = 0; i < sent.size(); ++i) sent[i] = std::uint8_t(i);
  m.spawn(0, "writer", Priority::low, [&](Process& p) {
    p.out(c, {std::int64_t(sent.size()), sent, "block"});
  });
  m.spawn(2, "reader", Priority::low,
          [&](Process& p) { received = std::any_cast<Bytes>(p.in(c).payload); });
  ASSERT_TRUE(m.run().empty());
  ASSERT_STREQ(c.transport->kind_name(), "routed");
  const network::FaultRecord& r = m.faults().records()[0];
  ASSERT_TRUE(r.fired);
  int byte = 0, of = 0;  // 1-based, as the hit names it
  ASSERT_EQ(std::sscanf(r.hit.c_str(), "byte %d of %d", &byte, &of), 2) << r.hit;
  EXPECT_EQ(of, 100 + network::kRouteHeaderBytes);
  EXPECT_EQ(byte <= network::kRouteHeaderBytes, GetParam() == 0.0) << r.hit;
  Bytes expected = sent;
  if (byte > network::kRouteHeaderBytes) {
    expected[std::size_t(byte - 1 - network::kRouteHeaderBytes)] ^= 0x80;
    EXPECT_EQ(r.hit.find("not modelled"), std::string::npos) << r.hit;
  } else {
    EXPECT_NE(r.hit.find("changed (its value is not modelled)"), std::string::npos) << r.hit;
  }
  EXPECT_EQ(received, expected);
}

// At 0 the header's first byte; at 30 us, some 50 bytes into the message.
INSTANTIATE_TEST_SUITE_P(InTheHeaderAndPastIt, RoutedCorruption, ::testing::Values(0.0, 30.0));

TEST(FaultModel, ADroppedByteLeavesSenderAndReceiverWaiting) {
  Machine m(core_test::chain(1), core_test::options(20));
  m.faults().add(link_fault(FaultSpec::Kind::drop, 0));
  network::arm_faults(m);
  auto& c = m.channel("c", 0, 1);
  m.spawn(0, "writer", Priority::low, [&](Process& p) { p.out(c, {16, {}, "block"}); });
  m.spawn(1, "reader", Priority::low, [&](Process& p) { p.in(c); });
  const auto blocked = m.run();
  ASSERT_EQ(blocked.size(), 2u);  // no acknowledge for the writer, no message for the reader
  for (const auto& p : m.processes()) EXPECT_EQ(network::stranding_fault(m, *p), 0) << p->name();
  EXPECT_NE(m.faults().records()[0].hit.find("byte 1 of 16 of message 'block' lost"),
            std::string::npos);
}

TEST(FaultModel, ADeadLinkCarriesWhatWasSentBeforeItsTimeAndNothingAfter) {
  Machine m(core_test::chain(1), core_test::options(20));
  FaultSpec dead = link_fault(FaultSpec::Kind::dead_link, 50);
  m.faults().add(dead);
  network::arm_faults(m);
  auto& c = m.channel("c", 0, 1);
  int received = 0;
  m.spawn(0, "writer", Priority::low, [&](Process& p) {
    p.out(c, {8, {}, "early"});
    p.compute(2000, "wait past the fault");  // 100 us at 20 MHz
    p.out(c, {8, {}, "late"});
  });
  m.spawn(1, "reader", Priority::low, [&](Process& p) {
    for (;;) {
      p.in(c);
      ++received;
    }
  });
  m.run();
  EXPECT_EQ(received, 1);
  EXPECT_TRUE(m.faults().records()[0].fired);
}

TEST(FaultModel, AHaltedProcessorStopsComputingAtItsTime) {
  Machine m(core_test::chain(1), core_test::options(20));
  m.faults().add(halt_fault("P0", 100));
  network::arm_faults(m);
  m.spawn(0, "worker", Priority::low, [](Process& p) { p.compute(1000000, "long"); });
  const auto blocked = m.run();
  ASSERT_EQ(blocked.size(), 1u);
  EXPECT_EQ(network::stranding_fault(m, *m.processes()[0]), 0);
  m.transputer(0).activity().close(sc_core::sc_time_stamp());
  EXPECT_NEAR(m.transputer(0).activity().compute_us(), 100.0, 1e-6);
}

TEST(FaultModel, OutputOrFailAndInputOrFailGiveUpAtTheirDeadline) {
  Machine m(core_test::chain(1), core_test::options(20));
  m.faults().add(halt_fault("P1", 0));
  network::arm_faults(m);
  auto& out = m.channel("out", 0, 1);
  auto& in = m.channel("in", 1, 0);
  bool sent = true, received = true;
  double out_end = 0, in_end = 0;
  m.spawn(0, "master", Priority::low, [&](Process& p) {
    sent = out.transport->send_or_fail(p, {8, {}, "order"}, 200);
    out_end = p.now_us();
    received = in.transport->receive_or_fail(p, 500).has_value();
    in_end = p.now_us();
  });
  ASSERT_TRUE(m.run().empty());
  EXPECT_FALSE(sent);
  EXPECT_FALSE(received);
  // Each gives up at its deadline, then runs resetch (a few cycles).
  EXPECT_GE(out_end, 200.0);
  EXPECT_LT(out_end, 205.0);
  EXPECT_GE(in_end, 500.0);
  EXPECT_LT(in_end, 505.0);
}

}  // namespace
