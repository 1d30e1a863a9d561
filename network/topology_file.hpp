// Topology files (TOML) -> validated Topology. Format documented in configs/topologies/README.md.
#pragma once

#include <string>

#include "network/topology.hpp"

namespace toml {
inline namespace v3 {
class table;
}
}  // namespace toml

namespace network {

// Reads and validates a topology file. Throws ConfigError with file:line:column.
Topology load_topology(const std::string& path);

// Reads a topology from an already-parsed table (e.g. a scene's inline [topology]); `file` names it in errors.
Topology parse_topology(const toml::table& table, const std::string& file);

}  // namespace network
