// PLACED PAR: which processor each declared process runs on. The scene's [placement] table first
// (an entry for a process, a group, or one member of a group), then the program's own choice
// (ProcessDecl::placed_on), then the stated default: the processor wired to the host. Every
// report lists the outcome and what decided it.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "network/config_error.hpp"
#include "network/topology.hpp"
#include "t800sim/program.hpp"
#include "workloads/run/workload.hpp"

namespace t800sim::detail {

struct PlacedProcess {
  std::string name;  // "master", "worker[3]"
  const ProcessDecl* decl = nullptr;
  int index = 0;  // in its group
  int node = 0;
  std::string placed_by;                    // "scene.toml:12", "the program", "default: ..."
  std::optional<network::SourcePos> where;  // the scene line that placed it
};

// Throws network::ConfigError at the scene's entry for a process the program does not declare, a
// processor the network does not have, or a list of the wrong length; std::invalid_argument for
// the same mistakes in the program's own placement.
std::vector<PlacedProcess> place(const std::string& kind, const Builder& builder,
                                 const network::Topology& topology,
                                 const std::vector<workloads::PlacementEntry>& scene);

}  // namespace t800sim::detail
