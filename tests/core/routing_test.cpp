// A message over h hops through software routers follows the store-and-forward formula built from
// the datasheet's instruction cycles and the link protocol's constants (docs/t800-timing.md).
#include <gtest/gtest.h>

#include <cmath>

#include "core_fixtures.hpp"
#include "network/transport/store_and_forward.hpp"

namespace {

constexpr double kCycleNs = 50.0;  // T800-20
constexpr double kMbps = 20.0;

// The CPU's part of one communication, as occam compiles it and the datasheet times it: ldlp
// buffer (1), ldl channel (2), ldc length (1, one more per prefix byte: lengths from 16 to 255
// take one), in/out (19, plus 2 a word when it copies the message).
double setup_cycles(std::int64_t bytes, bool copies = false) {
  const double ldc = bytes < 16 ? 1 : 2;
  return 1 + 2 + ldc + 19 + (copies ? 2.0 * double((bytes + 3) / 4) : 0.0);
}

// One message of B bytes on an uncontended link, from its first data bit to the arrival of its last
// byte.
double link_time_ns(std::int64_t bytes) {
  using namespace t800::timing;
  const double bit = 1000.0 / kMbps;
  const double process = kAckProcessBits * bit + kAckProcessNs;
  const double period =
      std::max(kDataPacketBits * bit, kAckDetectNs + kAckPacketBits * bit + process);
  return double(bytes - 1) * period + kDataPacketBits * bit;
}

class RoutedMessage : public ::testing::TestWithParam<int> {};

TEST_P(RoutedMessage, FollowsStoreAndForwardFormula) {
  const int hops = GetParam();
  const std::int64_t payload = 96;
  network::Machine m(core_test::chain(hops), core_test::options(kMbps));
  auto& c = m.channel("far", 0, hops);
  double arrival_us = 0;
  m.spawn(0, "sender", t800::Priority::low, [&](network::Process& p) {
    p.out(c, {payload, {}, "x"});
  });
  m.spawn(hops, "receiver", t800::Priority::low, [&](network::Process& p) {
    p.in(c);
    arrival_us = p.now_us();
  });
  ASSERT_TRUE(m.run().empty());
  ASSERT_STREQ(c.transport->kind_name(), "routed");

  // Sender set-up, then per hop the link time and (except at the end) the router's output set-up,
  // then the last router's copy into the reader's buffer, and the router re-arming its input before
  // the low-priority reader gets the CPU: T(h) = S(B) + h L(B) + (h-1) S(B) + S_copy(payload) +
  // S(0).
  const std::int64_t B = payload + network::kRouteHeaderBytes;
  const double expected_ns = setup_cycles(B) * kCycleNs * hops + hops * link_time_ns(B) +
                             (setup_cycles(payload, true) + setup_cycles(0)) * kCycleNs;
  EXPECT_NEAR(arrival_us * 1000.0, expected_ns, 1.0);
}

INSTANTIATE_TEST_SUITE_P(Hops, RoutedMessage, ::testing::Values(2, 3, 4, 6));

// Neighbours alone on a link direction talk directly: no router, no header.
TEST(DirectChannel, NeighboursUseTheLinkDirectly) {
  network::Machine m(core_test::chain(1), core_test::options(kMbps));
  auto& c = m.channel("near", 0, 1);
  double arrival_us = 0;
  m.spawn(0, "sender", t800::Priority::low, [&](network::Process& p) { p.out(c, {96, {}, "x"}); });
  m.spawn(1, "receiver", t800::Priority::low, [&](network::Process& p) {
    p.in(c);
    arrival_us = p.now_us();
  });
  ASSERT_TRUE(m.run().empty());
  EXPECT_STREQ(c.transport->kind_name(), "direct");
  EXPECT_NEAR(arrival_us * 1000.0, setup_cycles(96) * kCycleNs + link_time_ns(96), 1.0);
}

// The payload a workload sends is the payload it receives, also through routers.
TEST(RoutedChannel, CarriesThePayload) {
  network::Machine m(core_test::chain(3), core_test::options(kMbps));
  auto& c = m.channel("far", 0, 3);
  std::vector<double> got;
  m.spawn(0, "sender", t800::Priority::low, [&](network::Process& p) {
    p.out(c, {24, std::vector<double>{1.5, -2.0, 3.25}, "values"});
  });
  m.spawn(3, "receiver", t800::Priority::low,
          [&](network::Process& p) { got = std::any_cast<std::vector<double>>(p.in(c).payload); });
  ASSERT_TRUE(m.run().empty());
  EXPECT_EQ(got, (std::vector<double>{1.5, -2.0, 3.25}));
}

// A program that waits forever is reported, naming the process and what it waits for.
TEST(Deadlock, IsReportedWithTheBlockedProcess) {
  network::Machine m(core_test::chain(1), core_test::options(kMbps));
  auto& c = m.channel("never", 1, 0);
  m.spawn(0, "waiter", t800::Priority::low, [&](network::Process& p) { p.in(c); });
  const auto blocked = m.run();
  ASSERT_EQ(blocked.size(), 1u);
  EXPECT_EQ(blocked[0].process, "waiter");
  EXPECT_EQ(blocked[0].processor, "P0");
  EXPECT_NE(blocked[0].status.find("never"), std::string::npos);
}

// The link between two nodes is the first listed in the machine's links that joins them (a's end of
// it), found here by reading the list; Machine::link_between answers from an index of link ends.
// Two links join P0 and P1, the first listed on P0's higher link; the host is on P0.link0.
TEST(LinkBetween, IsTheFirstListedLinkJoiningTheNodes) {
  network::Topology t;
  for (int i = 0; i < 3; ++i) t.processors.push_back({"P" + std::to_string(i), {}, {}});
  t.connections.push_back({{0, 3}, {1, 1}, std::nullopt, {}});
  t.connections.push_back({{0, 1}, {1, 2}, std::nullopt, {}});
  t.connections.push_back({{2, 0}, {1, 3}, std::nullopt, {}});
  t.host = network::LinkEnd{0, 0};
  const network::Machine m(t, core_test::options(kMbps));
  const std::vector<int> nodes{network::Machine::kHost, 0, 1, 2};
  for (int a : nodes)
    for (int b : nodes) {
      std::optional<std::pair<t800::Link*, int>> listed;
      for (const network::Machine::LinkInfo& l : m.links()) {
        if (listed) break;
        if (l.node[0] == a && l.node[1] == b) listed = std::make_pair(l.link, 0);
        if (l.node[1] == a && l.node[0] == b) listed = std::make_pair(l.link, 1);
      }
      EXPECT_EQ(m.link_between(a, b), listed) << a << " -> " << b;
    }
  EXPECT_EQ(m.link_between(0, 1)->first, m.links()[0].link);  // the first listed, not link 1's
}

}  // namespace
