// Shortest paths between the processors of a topology, for every channel a program declares. A
// breadth-first search from one processor gives the paths from it to all others and its distance to
// all others, which gives the paths from all others to it (below); searches are made when a path
// needs one and kept, so a farm's thousands of channels to and from its master cost one search.
#pragma once

#include <memory>
#include <vector>

#include "network/link_index.hpp"
#include "network/topology.hpp"

namespace network {

class Routes {
 public:
  explicit Routes(const Topology& topology);

  // A shortest path from -> to as processor indices (both included), lowest link first: of all
  // shortest paths, the one whose sequence of link numbers is least -- what a breadth-first search
  // from `from` trying each processor's links in order finds. Empty when unreachable.
  std::vector<int> path(int from, int to) const;
  const LinkIndex& index() const { return index_; }

 private:
  struct Search {
    std::vector<int> parent;    // towards the root; -1 at the root, -2 unreached
    std::vector<int> distance;  // hops from the root, -1 unreached
  };
  const Search& search(int root) const;
  std::vector<int> path_from_root(const Search& s, int to) const;
  std::vector<int> path_to_root(const Search& s, int from, int root) const;

  LinkIndex index_;
  mutable std::vector<std::unique_ptr<Search>> searches_;  // by root, made on demand
};

}  // namespace network
