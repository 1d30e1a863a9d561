#include "network/link_index.hpp"

#include <algorithm>

namespace network {

LinkIndex::LinkIndex(const Topology& topology)
    : ends_(topology.processors.size() * kLinksPerProcessor),
      neighbours_(topology.processors.size()) {
  const int n = int(topology.processors.size());
  auto in_range = [n](const LinkEnd& e) {
    return e.processor >= 0 && e.processor < n && e.link >= 0 && e.link < kLinksPerProcessor;
  };
  for (std::size_t i = 0; i < topology.connections.size(); ++i) {
    const Connection& c = topology.connections[i];
    for (const auto& [end, far] : {std::pair{c.a, c.b}, std::pair{c.b, c.a}}) {
      if (!in_range(end) || !in_range(far)) continue;  // validate() reports it
      End& slot = ends_[std::size_t(end.processor) * kLinksPerProcessor + std::size_t(end.link)];
      if (slot.connection < 0) slot = {int(i), far};
    }
  }
  for (int p = 0; p < processors(); ++p)
    for (int link = 0; link < kLinksPerProcessor; ++link) {
      if (connection_at(p, link) < 0) continue;
      std::vector<int>& list = neighbours_[std::size_t(p)];
      const int q = peer(p, link).processor;
      // Two links between the same pair (a ring of two) still make one neighbour.
      if (std::find(list.begin(), list.end(), q) == list.end()) list.push_back(q);
    }
}

}  // namespace network
