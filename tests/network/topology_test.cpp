// Topology's queries and validate() on topologies built in code (files are in topology_file_test).
#include "network/topology.hpp"

#include <gtest/gtest.h>

#include "test_util.hpp"

namespace {

using nettest::fails_at;
using network::Connection;
using network::LinkEnd;
using network::SourcePos;
using network::Topology;

// P0..P(n-1), host on P0.link0, processor i declared at mem:i+1:1.
Topology bare(int n) {
  Topology t;
  t.name = "t";
  t.source = "mem";
  for (int i = 0; i < n; ++i)
    t.processors.push_back({"P" + std::to_string(i), {}, {"mem", i + 1, 1}});
  t.host = LinkEnd{0, 0};
  return t;
}

void connect(Topology& t, int p, int pl, int q, int ql, int line) {
  t.connections.push_back(Connection{{p, pl}, {q, ql}, std::nullopt, SourcePos{"mem", line, 3}});
}

// P0 - P1 - P2 with P0.link2 - P2.link3 closing a triangle.
Topology triangle() {
  Topology t = bare(3);
  connect(t, 0, 1, 1, 0, 10);
  connect(t, 1, 1, 2, 0, 11);
  connect(t, 0, 2, 2, 3, 12);
  return t;
}

TEST(Topology, FindAndConnections) {
  const Topology t = triangle();
  EXPECT_EQ(t.find("P2"), 2);
  EXPECT_EQ(t.find("P9"), -1);
  EXPECT_EQ(t.connection_at(0, 1), 0);
  EXPECT_EQ(t.connection_at(2, 3), 2);
  EXPECT_EQ(t.connection_at(0, 0), -1);  // the host's link is not a connection
  EXPECT_EQ(t.peer(2, 0), (LinkEnd{1, 1}));
  EXPECT_EQ(t.peer(0, 2), (LinkEnd{2, 3}));
  EXPECT_EQ(t.host_processor(), 0);
}

TEST(Topology, NeighboursInLinkOrderWithoutRepeats) {
  Topology t = triangle();
  EXPECT_EQ(t.neighbours(0), (std::vector<int>{1, 2}));
  EXPECT_EQ(t.neighbours(2), (std::vector<int>{1, 0}));
  // Two links between the same pair give one neighbour.
  Topology two = bare(2);
  connect(two, 0, 1, 1, 0, 1);
  connect(two, 0, 2, 1, 1, 2);
  EXPECT_EQ(two.neighbours(0), (std::vector<int>{1}));
}

TEST(Topology, ShortestPathIsDeterministicLowestLinkFirst) {
  Topology t = bare(4);  // a square: P0-P1-P3 and P0-P2-P3, two equal routes
  connect(t, 0, 2, 2, 0, 1);
  connect(t, 0, 1, 1, 0, 2);
  connect(t, 1, 1, 3, 0, 3);
  connect(t, 2, 1, 3, 1, 4);
  EXPECT_EQ(t.shortest_path(0, 3), (std::vector<int>{0, 1, 3}));  // via P0.link1, not link2
  EXPECT_EQ(t.shortest_path(3, 0), (std::vector<int>{3, 1, 0}));
  EXPECT_EQ(t.shortest_path(2, 2), (std::vector<int>{2}));
  EXPECT_TRUE(t.shortest_path(0, 7).empty());
}

TEST(Topology, ShortestPathEmptyWhenUnreachable) {
  Topology t = bare(3);
  connect(t, 0, 1, 1, 0, 1);
  EXPECT_TRUE(t.shortest_path(0, 2).empty());
}

TEST(TopologyValidate, AcceptsAValidNetwork) {
  EXPECT_NO_THROW(network::validate(triangle()));
}

TEST(TopologyValidate, NoProcessors) {
  Topology t;
  t.source = "mem";
  EXPECT_TRUE(fails_at([&] { network::validate(t); }, "mem", 0, 0, {"no processors"}));
}

TEST(TopologyValidate, DuplicateNames) {
  Topology t = triangle();
  t.processors[2].name = "P1";
  EXPECT_TRUE(fails_at([&] { network::validate(t); }, "mem", 3, 1,
                       {"duplicate processor name 'P1'", "first defined at mem:2:1"}));
}

TEST(TopologyValidate, LinkIndexOutsideRange) {
  Topology t = triangle();
  t.connections[1].b.link = 4;
  EXPECT_TRUE(fails_at([&] { network::validate(t); }, "mem", 11, 3,
                       {"link index 4 of processor 'P2' is outside 0-3", "link0 to link3"}));
  t.connections[1].b.link = -1;
  EXPECT_TRUE(fails_at([&] { network::validate(t); }, "mem", 11, 3, {"link index -1"}));
}

TEST(TopologyValidate, ProcessorIndexOutsideRange) {
  Topology t = triangle();
  t.connections[0].b.processor = 7;
  EXPECT_TRUE(fails_at([&] { network::validate(t); }, "mem", 10, 3, {"processor #7", "#0 to #2"}));
}

TEST(TopologyValidate, LinkEndUsedTwice) {
  Topology t = triangle();
  connect(t, 1, 2, 2, 0, 13);  // P2.link0 already goes to P1.link1
  EXPECT_TRUE(
      fails_at([&] { network::validate(t); }, "mem", 13, 3,
               {"P2.link0 is already connected to P1.link1 (mem:11:3)", "only one connection"}));
}

TEST(TopologyValidate, LinkEndUsedByTheHost) {
  Topology t = triangle();
  connect(t, 0, 0, 1, 3, 14);
  EXPECT_TRUE(fails_at([&] { network::validate(t); }, "mem", 14, 3,
                       {"P0.link0 is already connected to the host"}));
}

TEST(TopologyValidate, SelfLoop) {
  Topology t = triangle();
  connect(t, 1, 2, 1, 3, 15);
  EXPECT_TRUE(fails_at([&] { network::validate(t); }, "mem", 15, 3,
                       {"connects processor 'P1' to itself", "two different processors"}));
}

TEST(TopologyValidate, LinkSpeed) {
  Topology t = triangle();
  for (double ok : {5.0, 10.0, 20.0}) {
    t.connections[2].speed_mbps = ok;
    EXPECT_NO_THROW(network::validate(t));
  }
  t.connections[2].speed_mbps = 12.5;
  EXPECT_TRUE(fails_at([&] { network::validate(t); }, "mem", 12, 3,
                       {"link speed 12.5 Mbit/s is not supported", "5, 10 or 20 Mbit/s"}));
}

TEST(TopologyValidate, UnreachableProcessorsAreNamed) {
  Topology t = bare(5);
  connect(t, 0, 1, 1, 0, 10);
  connect(t, 3, 1, 4, 0, 11);  // P3 - P4 are an island; P2 is alone
  EXPECT_TRUE(fails_at([&] { network::validate(t); }, "mem", 3, 1,
                       {"processors P2, P3, P4 cannot be reached from the host (P0.link0)"}));
}

TEST(TopologyValidate, NoHost) {
  Topology t = triangle();
  t.host.reset();
  EXPECT_TRUE(fails_at([&] { network::validate(t); }, "mem", 0, 0,
                       {"no host connection", "host = \"P0.link0\""}));
}

TEST(TopologyValidate, HostLinkOutsideRange) {
  Topology t = triangle();
  t.host = LinkEnd{0, 4};
  EXPECT_TRUE(fails_at([&] { network::validate(t); }, "mem", 0, 0, {"link index 4"}));
}

}  // namespace
