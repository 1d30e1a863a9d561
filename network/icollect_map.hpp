// The network a configured program was built for, read from the map file the INMOS collector
// (icollect) writes beside its boot file: each "Memory map for 'NAME' processor N TYPE" names a
// processor, and the "Connectivity for network" section lists its wires ("Connect HOST to processor
// 0 link 0", "Connect processor 1 link 1 to processor 0 link 2"). So `t800sim boot raytrace8.btl
// --network raytrace8.map` runs on the network the configuration describes, nothing written by
// hand.
#pragma once

#include <optional>
#include <string>

#include "network/topology.hpp"

namespace network {

// Whether `text` is an icollect map file (it has a connectivity section), so a caller can tell it
// from a TOML topology file.
bool is_icollect_map(const std::string& text);

// The topology of the map file `path` (whose text is `text`). The map gives each processor's family
// (T800, T805, T414) but not its clock: each processor is `each` when given, which must have the
// family's FPU (a T805-25 for a map's "T800" is how a B012 is described), else the family's 20 MHz
// part. Processors are named P0, P1, ... by their numbers in the map. Throws ConfigError naming the
// line and column of what cannot be read.
Topology parse_icollect_map(const std::string& text, const std::string& path,
                            std::optional<t800::ProcessorType> each);

}  // namespace network
