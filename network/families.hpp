// Generated topologies for families of networks, sized by the number of workers. Processor 0 ("P0")
// is the master and holds the host link; workers are P1..Pn in breadth-first order from P0.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "network/topology.hpp"

namespace network {

enum class Family { tree, chain, ring, mesh, hypercube };

std::optional<Family> parse_family(
    std::string_view text);  // "tree", "chain", "ring", "mesh", "hypercube"
std::string_view to_string(Family family);
std::vector<std::string> family_names();

// tree: the paper's farm trees (Figs. 3-5): P0 has three children (its fourth link goes to the
// host); every further node has up to three children; a new level is filled round-robin over its
// parents, so 1, 3, 6 and 9 workers give exactly the paper's networks.
// chain: P0 - P1 - ... - Pn.  ring: the chain closed.  mesh: the most nearly square 2-D grid of n+1
// nodes, P0 in a corner.  hypercube: n+1 must be a power of two; up to 8 processors one per cube node
// (4 links, one kept for the host), beyond that each cube node a chain of 2, 4, ... transputers
// (families.cpp). Throws ConfigError (with `where`) when the family cannot be built with that many
// workers.
Topology generate(Family family, int workers, const t800::ProcessorConfig& processor,
                  const SourcePos& where);

// The family whose generated network of the same size this topology is, link for link (the
// processors in the same order, the same host link, the same connections; names, types and speeds
// aside), or nullopt. configs/topologies/tree-9.toml is the tree of 9 workers; a user's file may be
// a family too.
std::optional<Family> family_of(const Topology& topology);

}  // namespace network
