// Link throughput against the datasheet (DBK Table 8.1, docs/t800-timing.md section 6).
#include <gtest/gtest.h>

#include "core_fixtures.hpp"

using core_test::stream;
using t800::LinkProtocol;

TEST(LinkRate, OneDirection20Mbit) {
  const auto r = stream(20, false, LinkProtocol::overlapped);
  RecordProperty("kBps", std::to_string(r.forward_kBps));
  EXPECT_NEAR(r.forward_kBps, 1740, 0.02 * 1740);
}

TEST(LinkRate, OneDirection10Mbit) {
  const auto r = stream(10, false, LinkProtocol::overlapped);
  RecordProperty("kBps", std::to_string(r.forward_kBps));
  EXPECT_NEAR(r.forward_kBps, 910, 0.02 * 910);
}

TEST(LinkRate, BothDirections20Mbit) {
  const auto r = stream(20, true, LinkProtocol::overlapped);
  RecordProperty("kBps", std::to_string(r.forward_kBps + r.backward_kBps));
  EXPECT_NEAR(r.forward_kBps + r.backward_kBps, 2350, 0.03 * 2350);
  EXPECT_NEAR(r.forward_kBps, r.backward_kBps, 0.01 * r.forward_kBps);  // the protocol is symmetric
}

TEST(LinkRate, BothDirections10Mbit) {
  const auto r = stream(10, true, LinkProtocol::overlapped);
  RecordProperty("kBps", std::to_string(r.forward_kBps + r.backward_kBps));
  EXPECT_NEAR(r.forward_kBps + r.backward_kBps, 1250, 0.03 * 1250);
}

// T414-style links acknowledge only after the whole packet: "about 0.8 MB/s" one way at 20 Mbit/s. This rate is
// a prediction of the model (its latencies were derived from the T800 rates only), so the band is wider.
TEST(LinkRate, T414StyleIsAboutPointEightMBps) {
  const auto r = stream(20, false, LinkProtocol::t414);
  RecordProperty("kBps", std::to_string(r.forward_kBps));
  EXPECT_NEAR(r.forward_kBps, 800, 0.15 * 800);
}

// Message boundaries with late (T414) acknowledges: many short messages, each must complete.
TEST(LinkRate, T414ManyShortMessagesComplete) {
  const auto r = stream(20, true, LinkProtocol::t414, 3, 200);
  EXPECT_GT(r.forward_kBps, 0);
  EXPECT_NEAR(r.forward_kBps, r.backward_kBps, 0.02 * r.forward_kBps);
}
