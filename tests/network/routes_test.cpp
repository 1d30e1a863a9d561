// The link index and the routes (network/link_index.hpp, network/routes.hpp) must answer exactly as
// the definitions they replace on the hot path: the connection at a link end is the first listed
// with that end, and a route is what a breadth-first search from the source finds when it tries
// each processor's links in order (the first to reach a processor is its parent). The references
// below are those definitions written out plainly; the topologies are every generated family at
// several sizes and random wirings with several links between the same pair.
#include <gtest/gtest.h>

#include <queue>
#include <random>
#include <vector>

#include "network/families.hpp"
#include "network/link_index.hpp"
#include "network/routes.hpp"

namespace {

using network::Connection;
using network::LinkEnd;
using network::Topology;

// The connection at (p, link) by reading the list, and the far end.
int listed_connection(const Topology& t, int p, int link) {
  for (std::size_t i = 0; i < t.connections.size(); ++i)
    if (t.connections[i].a == LinkEnd{p, link} || t.connections[i].b == LinkEnd{p, link})
      return int(i);
  return -1;
}

// Breadth-first search from `from`, links 0..3 of each processor in turn.
std::vector<int> breadth_first_path(const Topology& t, int from, int to) {
  const int n = int(t.processors.size());
  std::vector<int> parent(std::size_t(n), -2);
  parent[std::size_t(from)] = -1;
  std::queue<int> frontier;
  frontier.push(from);
  while (!frontier.empty()) {
    const int p = frontier.front();
    frontier.pop();
    for (int link = 0; link < network::kLinksPerProcessor; ++link) {
      const int c = listed_connection(t, p, link);
      if (c < 0) continue;
      const Connection& conn = t.connections[std::size_t(c)];
      const int q = conn.a == LinkEnd{p, link} ? conn.b.processor : conn.a.processor;
      if (parent[std::size_t(q)] != -2) continue;
      parent[std::size_t(q)] = p;
      frontier.push(q);
    }
  }
  if (parent[std::size_t(to)] == -2) return {};
  std::vector<int> path;
  for (int p = to; p != -1; p = parent[std::size_t(p)]) path.insert(path.begin(), p);
  return path;
}

// n processors, each link end used at most once, wired at random (several links between one pair
// allowed, some processors possibly unreachable).
Topology random_topology(int n, std::mt19937& random) {
  Topology t;
  for (int i = 0; i < n; ++i) t.processors.push_back({"P" + std::to_string(i), {}, {}});
  std::vector<LinkEnd> free;
  for (int p = 0; p < n; ++p)
    for (int link = 0; link < network::kLinksPerProcessor; ++link) free.push_back({p, link});
  std::shuffle(free.begin(), free.end(), random);
  while (free.size() >= 2 && random() % 8 != 0) {
    const LinkEnd a = free.back();
    free.pop_back();
    const LinkEnd b = free.back();
    free.pop_back();
    if (a.processor != b.processor) t.connections.push_back({a, b, std::nullopt, {}});
  }
  return t;
}

std::vector<Topology> topologies() {
  std::vector<Topology> all;
  for (network::Family f : {network::Family::tree, network::Family::chain, network::Family::ring,
                            network::Family::mesh})
    for (int workers : {2, 5, 9, 23, 64})
      all.push_back(network::generate(f, workers, {}, {"test", 0, 0}));
  for (int workers : {1, 3, 7})
    all.push_back(network::generate(network::Family::hypercube, workers, {}, {"test", 0, 0}));
  std::mt19937 random(14);
  for (int i = 0; i < 40; ++i) all.push_back(random_topology(2 + int(random() % 30), random));
  return all;
}

TEST(LinkIndex, AnswersAsTheConnectionList) {
  for (const Topology& t : topologies()) {
    const network::LinkIndex index(t);
    for (int p = 0; p < int(t.processors.size()); ++p) {
      for (int link = 0; link < network::kLinksPerProcessor; ++link) {
        ASSERT_EQ(index.connection_at(p, link), listed_connection(t, p, link)) << p << "." << link;
        ASSERT_EQ(index.connection_at(p, link), t.connection_at(p, link));
        if (index.connection_at(p, link) >= 0) {
          EXPECT_EQ(index.peer(p, link), t.peer(p, link));
        }
      }
      EXPECT_EQ(index.neighbours(p), t.neighbours(p));
    }
  }
}

// Both ways of answering: from a search rooted at the source (paths from the master first), and
// greedily from one rooted at the destination (paths to the master, once its search exists).
TEST(Routes, EqualBreadthFirstSearchLowestLinkFirst) {
  for (const Topology& t : topologies()) {
    const int n = int(t.processors.size());
    const network::Routes from_master_first(t);
    for (int q = 0; q < n; ++q) {
      ASSERT_EQ(from_master_first.path(0, q), breadth_first_path(t, 0, q)) << "0 -> " << q;
      ASSERT_EQ(from_master_first.path(q, 0), breadth_first_path(t, q, 0)) << q << " -> 0";
    }
    const network::Routes every_pair(t);
    for (int p = 0; p < n; ++p)
      for (int q = 0; q < n; ++q)
        ASSERT_EQ(every_pair.path(p, q), breadth_first_path(t, p, q)) << p << " -> " << q;
    for (int q = 0; q < n; ++q)
      EXPECT_EQ(t.shortest_path(q, n - 1), breadth_first_path(t, q, n - 1));
  }
}

TEST(Routes, OutOfRangeAndUnreachable) {
  Topology t;
  for (int i = 0; i < 3; ++i) t.processors.push_back({"P" + std::to_string(i), {}, {}});
  t.connections.push_back({{0, 1}, {1, 0}, std::nullopt, {}});
  const network::Routes routes(t);
  EXPECT_TRUE(routes.path(0, 2).empty());
  EXPECT_TRUE(routes.path(2, 0).empty());
  EXPECT_TRUE(routes.path(-1, 0).empty());
  EXPECT_TRUE(routes.path(0, 3).empty());
  EXPECT_EQ(routes.path(1, 1), std::vector<int>{1});
}

}  // namespace
