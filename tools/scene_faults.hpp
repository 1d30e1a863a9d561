// The faults a run injects (network/faults.hpp): a scene's [[fault]] tables and the `--fault` flags
// of run and sweep, read into network::FaultSpec and checked against the scene's network, each
// error naming the file, line and column (or the flag) and the valid forms.
//
//   [[fault]]                       --fault kind=corrupt,link=L1->E2,at_us=150,xor=64
//   kind = "corrupt"                kinds: corrupt, drop (link = "A->B", one direction),
//   link = "L1->E2"                        dead-link (link = "A-B", both directions),
//   at_us = 150                            halt (processor = "P3")
//   xor = 64                        at_us: simulated time from which it acts; xor (corrupt only,
//                                   1..255, default 1): the bits of the byte that flip
#pragma once

#include <string>
#include <vector>

#include <toml++/toml.h>

#include "network/faults.hpp"
#include "network/topology.hpp"

namespace tools {

// The [[fault]] array of a scene (nullptr: none).
std::vector<network::FaultSpec> read_faults(const toml::node* faults, const std::string& file,
                                            const network::Topology& topology);
// One --fault flag's value.
network::FaultSpec parse_fault_flag(const std::string& text, const network::Topology& topology);

}  // namespace tools
