// A program as declared (t800sim/program.hpp) made real on a machine: its processes placed, its
// channels joined and routed, its kernels' code declared, its processes spawned. The SDK's
// programs (sdk/program_workload.cpp) and the built-in programs written with it
// (workloads/farm/) both go through here.
#pragma once

#include <string>
#include <vector>

#include "sdk/placement.hpp"

namespace network {
class Machine;
}

namespace t800sim::detail {

// `kind` names the program in errors. A process declared without a body is one the caller spawns
// itself (a built-in workload's master): it is placed and its channels joined, nothing more.
std::vector<PlacedProcess> realise(const std::string& kind, Builder& builder,
                                   network::Machine& machine,
                                   const std::vector<workloads::PlacementEntry>& scene);

// Spawns a process with an SDK body on `node` (a processor index, or network::Machine::kHost):
// how a built-in workload starts the processes it declares without a body -- the host's, and a
// master it drives itself -- and how realise() starts the others. An exception the body lets out
// ends the run with a workloads::ProcessError naming `kind`, the process and its processor.
void spawn(const std::string& kind, network::Machine& machine, int node, const std::string& name,
           const Process::Body& body, bool high_priority = false);

}  // namespace t800sim::detail
