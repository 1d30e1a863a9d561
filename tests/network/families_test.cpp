// Generated networks: sizes, link budgets, the paper's trees, and path lengths in closed form.
#include "network/families.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <tuple>

#include "network/topology_file.hpp"
#include "test_util.hpp"

namespace {

using nettest::fails_at;
using network::Family;
using network::generate;
using network::Topology;

const network::SourcePos kWhere{"scene.toml", 7, 11};

Topology make(Family family, int workers) {
  return generate(family, workers, {}, kWhere);
}

int path_length(const Topology& t, int from, int to) {
  return static_cast<int>(t.shortest_path(from, to).size()) - 1;  // in hops
}

int links_used(const Topology& t, int p) {
  int used = p == t.host_processor() ? 1 : 0;
  for (int link = 0; link < network::kLinksPerProcessor; ++link)
    used += t.connection_at(p, link) >= 0;
  return used;
}

// A connection as an order-free tuple, for comparing structures.
std::tuple<int, int, int, int> key(const network::Connection& c) {
  auto a = std::pair{c.a.processor, c.a.link}, b = std::pair{c.b.processor, c.b.link};
  if (b < a) std::swap(a, b);
  return {a.first, a.second, b.first, b.second};
}

void expect_same_structure(const Topology& file, const Topology& generated) {
  ASSERT_EQ(file.processors.size(), generated.processors.size());
  for (std::size_t i = 0; i < file.processors.size(); ++i)
    EXPECT_EQ(file.processors[i].name, generated.processors[i].name);
  EXPECT_EQ(file.host, generated.host);
  std::vector<std::tuple<int, int, int, int>> a, b;
  for (const auto& c : file.connections) a.push_back(key(c));
  for (const auto& c : generated.connections) b.push_back(key(c));
  std::sort(a.begin(), a.end());
  std::sort(b.begin(), b.end());
  EXPECT_EQ(a, b);
}

struct Size {
  Family family;
  int workers;
};

// Readable names in failure messages and ctest listings.
void PrintTo(const Size& s, std::ostream* os) {
  *os << network::to_string(s.family) << "(" << s.workers << ")";
}

class FamilySizes : public ::testing::TestWithParam<Size> {};

TEST_P(FamilySizes, ValidShape) {
  const Size s = GetParam();
  const Topology t = make(s.family, s.workers);
  ASSERT_EQ(t.processors.size(), static_cast<std::size_t>(s.workers) + 1);
  for (int i = 0; i <= s.workers; ++i) {
    EXPECT_EQ(t.processors[static_cast<std::size_t>(i)].name, "P" + std::to_string(i));
    EXPECT_LE(links_used(t, i), 4);
    EXPECT_EQ(t.shortest_path(0, i).front(), 0);  // every worker reachable from the master
  }
  EXPECT_EQ(t.host, (network::LinkEnd{0, 0}));
  EXPECT_EQ(t.connection_at(0, 0), -1);  // the host's link is left free
  EXPECT_EQ(t.processors[0].where.line, kWhere.line);
  EXPECT_EQ(t.source, "family:" + std::string(network::to_string(s.family)) + "(" +
                          std::to_string(s.workers) + ")");
  EXPECT_NO_THROW(network::validate(t));
}

std::vector<Size> all_sizes() {
  std::vector<Size> sizes;
  for (int n : {1, 2, 3, 5, 6, 9, 12, 13, 40, 100}) {
    sizes.push_back({Family::tree, n});
    sizes.push_back({Family::chain, n});
    sizes.push_back({Family::mesh, n});
    if (n >= 2) sizes.push_back({Family::ring, n});
  }
  for (int n : {1, 3, 7}) sizes.push_back({Family::hypercube, n});
  return sizes;
}

INSTANTIATE_TEST_SUITE_P(Families, FamilySizes, ::testing::ValuesIn(all_sizes()),
                         [](const auto& info) {
                           return std::string(network::to_string(info.param.family)) +
                                  std::to_string(info.param.workers);
                         });

TEST(Families, NamesRoundTrip) {
  for (const std::string& name : network::family_names())
    EXPECT_EQ(network::to_string(*network::parse_family(name)), name);
  EXPECT_EQ(network::family_names().size(), 5u);
  EXPECT_FALSE(network::parse_family("torus").has_value());
}

TEST(Families, TreeIsFilledRoundRobin) {
  const Topology t = make(Family::tree, 9);
  // Level 1 on P0.link1..3, then P4, P5, P6 on link1 of P1, P2, P3, then P7, P8, P9 on link2.
  const int parent_of[] = {-1, 0, 0, 0, 1, 2, 3, 1, 2, 3};
  const int parent_link[] = {-1, 1, 2, 3, 1, 1, 1, 2, 2, 2};
  for (int child = 1; child <= 9; ++child) {
    EXPECT_EQ(t.peer(child, 0), (network::LinkEnd{parent_of[child], parent_link[child]}))
        << "P" << child;
  }
  EXPECT_EQ(path_length(t, 0, 9), 2);
  EXPECT_EQ(t.shortest_path(7, 8), (std::vector<int>{7, 1, 0, 2, 8}));
}

TEST(Families, LargeTreeUsesThreeChildrenPerNode) {
  const Topology t = make(Family::tree, 39);  // 3 + 9 + 27: three full levels
  for (int p = 0; p < 13; ++p) EXPECT_EQ(links_used(t, p), 4) << "P" << p;
  for (int p = 13; p <= 39; ++p) EXPECT_EQ(links_used(t, p), 1) << "P" << p;
  EXPECT_EQ(path_length(t, 0, 39), 3);
}

TEST(Families, PaperTreesMatchTheHandWrittenFiles) {
  for (int workers : {1, 3, 6, 9}) {
    SCOPED_TRACE("tree-" + std::to_string(workers));
    const Topology file = network::load_topology(
        nettest::source_dir() + "/configs/topologies/tree-" + std::to_string(workers) + ".toml");
    expect_same_structure(file, make(Family::tree, workers));
  }
}

TEST(Families, OtherFilesMatchTheirFamilies) {
  const std::string dir = nettest::source_dir() + "/configs/topologies/";
  expect_same_structure(network::load_topology(dir + "chain-5.toml"), make(Family::chain, 4));
  expect_same_structure(network::load_topology(dir + "pipeline-6.toml"), make(Family::chain, 5));
  expect_same_structure(network::load_topology(dir + "pair.toml"), make(Family::chain, 1));
  expect_same_structure(network::load_topology(dir + "ring-8.toml"), make(Family::ring, 7));
  expect_same_structure(network::load_topology(dir + "mesh-3x3.toml"), make(Family::mesh, 8));
}

// Reports say which family a network is wired as, whatever its source.
TEST(Families, FamilyOfRecognisesFilesWiredAsAFamily) {
  const std::string dir = nettest::source_dir() + "/configs/topologies/";
  EXPECT_EQ(network::family_of(network::load_topology(dir + "tree-9.toml")), Family::tree);
  EXPECT_EQ(network::family_of(network::load_topology(dir + "ring-8.toml")), Family::ring);
  EXPECT_EQ(network::family_of(network::load_topology(dir + "mesh-3x3.toml")), Family::mesh);
  EXPECT_EQ(network::family_of(make(Family::hypercube, 7)), Family::hypercube);
  // One link moved: no family's network any more.
  Topology moved = network::load_topology(dir + "tree-3.toml");
  ASSERT_FALSE(moved.connections.empty());
  moved.connections.back().b.link = moved.connections.back().b.link == 3 ? 2 : 3;
  EXPECT_EQ(network::family_of(moved), std::nullopt);
  EXPECT_EQ(network::family_of(network::load_topology(dir + "elimination-m3.toml")), std::nullopt);
}

TEST(Families, ChainPathLengths) {
  const Topology t = make(Family::chain, 9);
  for (int i = 0; i <= 9; ++i)
    for (int j = 0; j <= 9; ++j) EXPECT_EQ(path_length(t, i, j), std::abs(i - j));
  EXPECT_EQ(t.shortest_path(0, 3), (std::vector<int>{0, 1, 2, 3}));
}

TEST(Families, RingPathLengths) {
  const int n = 8;
  const Topology t = make(Family::ring, n - 1);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      EXPECT_EQ(path_length(t, i, j), std::min(std::abs(i - j), n - std::abs(i - j)));
  EXPECT_EQ(t.peer(7, 1), (network::LinkEnd{0, 2}));
}

TEST(Families, MeshPathLengthsAreManhattan) {
  for (int side : {3, 4}) {
    const Topology t = make(Family::mesh, side * side - 1);
    for (int i = 0; i < side * side; ++i)
      for (int j = 0; j < side * side; ++j)
        EXPECT_EQ(path_length(t, i, j),
                  std::abs(i / side - j / side) + std::abs(i % side - j % side));
    EXPECT_EQ(t.peer(0, 1), (network::LinkEnd{1, 3}));     // right
    EXPECT_EQ(t.peer(0, 2), (network::LinkEnd{side, 0}));  // down
  }
}

TEST(Families, MeshShapeIsNearlySquare) {
  // 8 processors: an exact 2 x 4 grid.
  const Topology eight = make(Family::mesh, 7);
  EXPECT_EQ(eight.neighbours(0), (std::vector<int>{1, 4}));
  EXPECT_EQ(eight.neighbours(7), (std::vector<int>{3, 6}));
  // 10 processors: no rectangle with cols <= 2 rows, so 3 rows of 4 with the last row holding two.
  const Topology ten = make(Family::mesh, 9);
  EXPECT_EQ(ten.neighbours(0), (std::vector<int>{1, 4}));
  EXPECT_EQ(ten.neighbours(8), (std::vector<int>{4, 9}));
  EXPECT_EQ(ten.neighbours(9), (std::vector<int>{5, 8}));
  EXPECT_EQ(ten.neighbours(7), (std::vector<int>{3, 6}));  // nothing below P7
  // 7 processors (prime): 2 rows of 4 and 3.
  EXPECT_EQ(make(Family::mesh, 6).neighbours(4), (std::vector<int>{0, 5}));
}

TEST(Families, HypercubePathLengthsAreHamming) {
  for (int workers : {1, 3, 7}) {
    const Topology t = make(Family::hypercube, workers);
    for (int i = 0; i <= workers; ++i)
      for (int j = 0; j <= workers; ++j)
        EXPECT_EQ(path_length(t, i, j), __builtin_popcount(static_cast<unsigned>(i ^ j)));
  }
}

TEST(Families, ProcessorConfigIsApplied) {
  t800::ProcessorConfig config;
  config.type = t800::ProcessorType::T800_30;
  const Topology t = generate(Family::ring, 4, config, kWhere);
  for (const auto& p : t.processors) EXPECT_EQ(p.config.type, t800::ProcessorType::T800_30);
}

TEST(Families, TooFewWorkers) {
  for (Family f : {Family::tree, Family::chain, Family::mesh, Family::hypercube})
    EXPECT_TRUE(fails_at([&] { make(f, 0); }, "scene.toml", 7, 11, {"at least 1 worker, got 0"}));
  EXPECT_TRUE(fails_at([&] { make(Family::tree, -3); }, "scene.toml", 7, 11, {"got -3"}));
  EXPECT_TRUE(fails_at([&] { make(Family::ring, 1); }, "scene.toml", 7, 11,
                       {"a ring needs at least 2 workers"}));
}

TEST(Families, HypercubeSizes) {
  for (int workers : {2, 4, 5, 6, 8, 14, 1000})
    EXPECT_TRUE(fails_at([&] { make(Family::hypercube, workers); }, "scene.toml", 7, 11,
                         {"hypercube of " + std::to_string(workers) + " workers is not possible",
                          "workers = 1, 3, 7, 15, ..., 1023"}));
}

// Beyond 8 processors a cube node is a chain of c transputers sharing its d dimensions two each
// (2^d c = n + 1, the smallest c with 2c >= d): the links are the chains' and d 2^(d-1) for the cube,
// and transputers j of two cube nodes are as many hops apart as their cube nodes differ in bits.
TEST(Families, LargeHypercubesAreCubesOfChains) {
  struct Shape {
    int workers, dimensions, chain;
  };
  for (const Shape& s : {Shape{15, 3, 2}, Shape{63, 4, 4}, Shape{1023, 8, 4}}) {
    const Topology t = make(Family::hypercube, s.workers);
    const int cube_nodes = 1 << s.dimensions;
    EXPECT_EQ(int(t.connections.size()),
              cube_nodes * (s.chain - 1) + s.dimensions * cube_nodes / 2)
        << s.workers;
    const int step = std::max(1, cube_nodes / 7);  // some 50 pairs of cube nodes
    for (int v = 0; v < cube_nodes; v += step)
      for (int w = 1; w < cube_nodes; w += step + 1)
        for (int j = 0; j < s.chain; ++j) {
          // Along the chain to the transputer of each dimension that differs, across, and back.
          int hops = 0, at = j;
          for (int k = 0; k < s.dimensions; ++k)
            if ((v ^ w) & (1 << k)) hops += std::abs(at - k / 2) + 1, at = k / 2;
          hops += std::abs(at - j);
          EXPECT_LE(path_length(t, v * s.chain + j, w * s.chain + j), hops) << s.workers;
          EXPECT_GE(path_length(t, v * s.chain + j, w * s.chain + j),
                    __builtin_popcount(static_cast<unsigned>(v ^ w)));
        }
  }
}

TEST(Families, TooManyWorkers) {
  EXPECT_TRUE(fails_at([&] { make(Family::chain, 5000); }, "scene.toml", 7, 11,
                       {"too large", "at most 1023"}));
}

}  // namespace
