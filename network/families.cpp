#include "network/families.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>

namespace network {

namespace {

constexpr Family kFamilies[] = {Family::tree, Family::chain, Family::ring, Family::mesh,
                                Family::hypercube};

// P0 and the workers: the largest network simulated (topology.hpp); it also keeps a mistyped
// "--set network.workers=1000000" from hanging the tool.
constexpr int kMaxWorkers = kMaxProcessors - 1;

// A topology under construction: P0..Pn, P0.link0 to the host, every item at `where`.
struct Builder {
  Topology topology;
  SourcePos where;

  Builder(Family family, int workers, const t800::ProcessorConfig& config, SourcePos at)
      : where(std::move(at)) {
    const std::string family_name(to_string(family));
    topology.name = family_name + "-" + std::to_string(workers);
    topology.description = "generated " + family_name + " of " + std::to_string(workers) +
                           (workers == 1 ? " worker" : " workers") + " plus the master P0";
    topology.source = "family:" + family_name + "(" + std::to_string(workers) + ")";
    for (int i = 0; i <= workers; ++i)
      topology.processors.push_back({"P" + std::to_string(i), config, where});
    topology.host = LinkEnd{0, 0};
  }
  void link(int p, int p_link, int q, int q_link) {
    topology.connections.push_back({{p, p_link}, {q, q_link}, std::nullopt, where});
  }
};

// Level by level: the children of a level are dealt round-robin over its nodes (P4 to P1, P5 to P2,
// P6 to P3, P7 to P1, ...), so 1, 3, 6 and 9 workers give the paper's Figs. 3-5. A child's link0
// goes to its parent; a parent uses links 1, 2, 3 for its children; P0.link0 is the host's.
void build_tree(Builder& b, int workers) {
  std::vector<int> parents{0};
  std::vector<int> children_of(static_cast<std::size_t>(workers) + 1, 0);
  int next = 1;
  while (next <= workers) {
    std::vector<int> level;
    const int capacity = 3 * static_cast<int>(parents.size());
    for (int i = 0; i < capacity && next <= workers; ++i, ++next) {
      const int parent = parents[static_cast<std::size_t>(i) % parents.size()];
      const int slot = ++children_of[static_cast<std::size_t>(parent)];
      b.link(parent, slot, next, 0);
      level.push_back(next);
    }
    parents = level;
  }
}

// Pi.link1 -> P(i+1).link0, as in a tree where every node has one child.
void build_chain(Builder& b, int workers) {
  for (int i = 0; i < workers; ++i) b.link(i, 1, i + 1, 0);
}

// The chain closed by Pn.link1 -> P0.link2.
void build_ring(Builder& b, int workers) {
  build_chain(b, workers);
  b.link(workers, 1, 0, 2);
}

struct MeshShape {
  int rows, cols;
};

// The most nearly square grid of `nodes`: an exact rows x cols rectangle with cols <= 2 rows if one
// exists (largest rows <= sqrt(nodes) first); otherwise floor(sqrt(nodes)) rows of
// ceil(nodes / rows) columns with the last row partly filled.
MeshShape mesh_shape(int nodes) {
  const int root = static_cast<int>(std::floor(std::sqrt(static_cast<double>(nodes))));
  for (int rows = root; rows >= 1 && 2 * rows * rows >= nodes; --rows)
    if (nodes % rows == 0) return {rows, nodes / rows};
  return {root, (nodes + root - 1) / root};
}

// Row-major numbering from P0 in the top-left corner. Links by compass: 0 up, 1 right, 2 down,
// 3 left, so P0.link0 (up, off the grid) is free for the host.
void build_mesh(Builder& b, int workers) {
  const int nodes = workers + 1;
  const MeshShape shape = mesh_shape(nodes);
  for (int p = 0; p < nodes; ++p) {
    const int col = p % shape.cols;
    if (col + 1 < shape.cols && p + 1 < nodes) b.link(p, 1, p + 1, 3);
    if (p + shape.cols < nodes) b.link(p, 2, p + shape.cols, 0);
  }
}

// A T800 has four links and P0 keeps one for the host, so one transputer per cube node stops at three
// dimensions. Beyond, each cube node is a chain of c transputers (c a power of two) that share its
// dimensions, two each: the smallest c with 2c >= d, as 2^d * c = n+1.
struct CubeShape {
  int dimensions, chain;
};

std::optional<CubeShape> cube_shape(int nodes) {
  if (nodes < 2 || (nodes & (nodes - 1)) != 0) return std::nullopt;  // not a power of two
  for (int chain = 1; chain <= nodes; chain *= 2) {
    int d = 0;
    while ((chain << d) < nodes) ++d;
    if (d <= (chain == 1 ? 3 : 2 * chain)) return CubeShape{d, chain};
  }
  return std::nullopt;
}

// One transputer per cube node (c = 1): dimension k joins Pi and Pi^(2^k) through link k+1 on both
// sides; link0 stays free (P0's is the host's). Chains (c > 1): transputer j of cube node v is
// P(v*c + j); link0 and link1 join it to j-1 and j+1 of its chain, and links 2 and 3 carry dimensions
// 2j and 2j+1 to transputer j of the neighbouring cube nodes; P0's link0 is the host's.
void build_hypercube(Builder& b, int workers) {
  const CubeShape shape = *cube_shape(workers + 1);
  const int c = shape.chain;
  if (c > 1)
    b.topology.description += ": " + std::to_string(1 << shape.dimensions) + " cube nodes of " +
                              std::to_string(c) + " transputers in a chain, " +
                              std::to_string(shape.dimensions) + " dimensions";
  for (int v = 0; v < (1 << shape.dimensions); ++v)
    for (int j = 0; j + 1 < c; ++j) b.link(v * c + j, 1, v * c + j + 1, 0);
  for (int k = 0; k < shape.dimensions; ++k) {
    const int link = c == 1 ? k + 1 : 2 + k % 2;
    const int j = c == 1 ? 0 : k / 2;
    for (int v = 0; v < (1 << shape.dimensions); ++v)
      if ((v & (1 << k)) == 0) b.link(v * c + j, link, (v | (1 << k)) * c + j, link);
  }
}

void check_size(Family family, int workers, const SourcePos& where) {
  const std::string name(to_string(family));
  if (workers < 1)
    throw ConfigError(where,
                      "a " + name + " needs at least 1 worker, got " + std::to_string(workers));
  if (workers > kMaxWorkers)
    throw ConfigError(where, "a " + name + " of " + std::to_string(workers) +
                                 " workers is too large: at most " + std::to_string(kMaxWorkers) +
                                 " workers");
  if (family == Family::ring && workers < 2)
    throw ConfigError(where, "a ring needs at least 2 workers (3 processors with P0), got " +
                                 std::to_string(workers));
  if (family == Family::hypercube && !cube_shape(workers + 1))
    throw ConfigError(where, "a hypercube of " + std::to_string(workers) +
                                 " workers is not possible: P0 plus the workers must be a power of "
                                 "two, so workers = 1, 3, 7, 15, ..., 1023");
}

}  // namespace

std::optional<Family> parse_family(std::string_view text) {
  for (Family f : kFamilies)
    if (text == to_string(f)) return f;
  return std::nullopt;
}

std::string_view to_string(Family family) {
  switch (family) {
    case Family::tree:
      return "tree";
    case Family::chain:
      return "chain";
    case Family::ring:
      return "ring";
    case Family::mesh:
      return "mesh";
    case Family::hypercube:
      return "hypercube";
  }
  return "?";
}

std::vector<std::string> family_names() {
  std::vector<std::string> names;
  for (Family f : kFamilies) names.emplace_back(to_string(f));
  return names;
}

Topology generate(Family family, int workers, const t800::ProcessorConfig& processor,
                  const SourcePos& where) {
  check_size(family, workers, where);
  Builder b(family, workers, processor, where);
  switch (family) {
    case Family::tree:
      build_tree(b, workers);
      break;
    case Family::chain:
      build_chain(b, workers);
      break;
    case Family::ring:
      build_ring(b, workers);
      break;
    case Family::mesh:
      build_mesh(b, workers);
      break;
    case Family::hypercube:
      build_hypercube(b, workers);
      break;
  }
  validate(b.topology);
  return std::move(b.topology);
}

namespace {

std::vector<std::pair<std::pair<int, int>, std::pair<int, int>>> wiring(const Topology& t) {
  std::vector<std::pair<std::pair<int, int>, std::pair<int, int>>> wires;
  for (const Connection& c : t.connections) {
    std::pair<int, int> a{c.a.processor, c.a.link}, b{c.b.processor, c.b.link};
    wires.emplace_back(std::min(a, b), std::max(a, b));
  }
  std::sort(wires.begin(), wires.end());
  return wires;
}

}  // namespace

std::optional<Family> family_of(const Topology& topology) {
  const int workers = int(topology.processors.size()) - 1;
  if (workers < 1 || workers > kMaxWorkers) return std::nullopt;
  for (Family f : kFamilies) {
    Topology generated;
    try {
      generated = generate(f, workers, t800::ProcessorConfig{}, SourcePos{});
    } catch (const ConfigError&) {
      continue;  // no network of this family has that size
    }
    if (generated.host == topology.host && wiring(generated) == wiring(topology)) return f;
  }
  return std::nullopt;
}

}  // namespace network
