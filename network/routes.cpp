#include "network/routes.hpp"

#include <algorithm>

namespace network {

Routes::Routes(const Topology& topology)
    : index_(topology), searches_(topology.processors.size()) {}

const Routes::Search& Routes::search(int root) const {
  std::unique_ptr<Search>& kept = searches_[std::size_t(root)];
  if (kept) return *kept;
  const std::size_t n = std::size_t(index_.processors());
  kept = std::make_unique<Search>(Search{std::vector<int>(n, -2), std::vector<int>(n, -1)});
  Search& s = *kept;
  s.parent[std::size_t(root)] = -1;
  s.distance[std::size_t(root)] = 0;
  std::vector<int> frontier{root};
  for (std::size_t next = 0; next < frontier.size(); ++next) {
    const int p = frontier[next];
    for (int q : index_.neighbours(p)) {
      if (s.parent[std::size_t(q)] != -2) continue;
      s.parent[std::size_t(q)] = p;
      s.distance[std::size_t(q)] = s.distance[std::size_t(p)] + 1;
      frontier.push_back(q);
    }
  }
  return s;
}

std::vector<int> Routes::path_from_root(const Search& s, int to) const {
  if (s.parent[std::size_t(to)] == -2) return {};
  std::vector<int> path;
  for (int p = to; p != -1; p = s.parent[std::size_t(p)]) path.push_back(p);
  std::reverse(path.begin(), path.end());
  return path;
}

// The least sequence of link numbers among shortest paths is made greedily: from each processor,
// the lowest link to a processor one hop nearer the destination. (The breadth-first search from
// `from` visits each level in the order of these sequences, so it finds the same path.)
std::vector<int> Routes::path_to_root(const Search& s, int from, int root) const {
  if (s.distance[std::size_t(from)] < 0) return {};
  std::vector<int> path{from};
  for (int p = from; p != root;) {
    const int nearer = s.distance[std::size_t(p)] - 1;
    for (int link = 0; link < kLinksPerProcessor; ++link) {
      if (index_.connection_at(p, link) < 0) continue;
      const int q = index_.peer(p, link).processor;
      if (s.distance[std::size_t(q)] != nearer) continue;
      p = q;
      break;
    }
    path.push_back(p);
  }
  return path;
}

std::vector<int> Routes::path(int from, int to) const {
  const int n = index_.processors();
  if (from < 0 || to < 0 || from >= n || to >= n) return {};
  if (from == to) return {from};
  if (searches_[std::size_t(from)] || !searches_[std::size_t(to)])
    return path_from_root(search(from), to);
  return path_to_root(*searches_[std::size_t(to)], from, to);
}

}  // namespace network
