// Which connection is plugged into each link end of a topology, found in constant time: a topology
// lists its connections, and asking "what is at P7.link2?" by reading the list is a scan that,
// asked for every link of every processor, made elaborating 1024 transputers quadratic (issue 14).
#pragma once

#include <vector>

#include "network/topology.hpp"

namespace network {

class LinkIndex {
 public:
  // Connections with an end out of range are left out (validate() reports them).
  explicit LinkIndex(const Topology& topology);

  // As Topology::connection_at: the connection at (processor, link) -- the first listed, should a
  // faulty topology use an end twice -- or -1.
  int connection_at(int processor, int link) const { return at(processor, link).connection; }
  // The far end of the connection at (processor, link); requires connection_at(...) >= 0.
  LinkEnd peer(int processor, int link) const { return at(processor, link).peer; }
  // As Topology::neighbours: processors adjacent to p in link order, each once.
  const std::vector<int>& neighbours(int p) const { return neighbours_[std::size_t(p)]; }
  int processors() const { return int(neighbours_.size()); }

 private:
  struct End {
    int connection = -1;
    LinkEnd peer;
  };
  const End& at(int processor, int link) const {
    return ends_[std::size_t(processor) * kLinksPerProcessor + std::size_t(link)];
  }
  std::vector<End> ends_;  // kLinksPerProcessor per processor
  std::vector<std::vector<int>> neighbours_;
};

}  // namespace network
