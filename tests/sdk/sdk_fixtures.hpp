// Runs a program written with the SDK on a small network, as `t800sim run` would (placed, joined,
// spawned, run), without a scene file.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "network/families.hpp"
#include "network/faults.hpp"
#include "network/machine.hpp"
#include "network/unwound_frames.hpp"
#include "sdk/program_workload.hpp"
#include "t800sim/alt.hpp"
#include "t800sim/program.hpp"

namespace sdk_test {

inline network::Topology chain(int workers) {
  return network::generate(network::Family::chain, workers, {}, {"test", 0, 0});
}

struct Outcome {
  std::vector<network::BlockedProcess> blocked;
  std::vector<network::FaultRecord> faults;  // what each injected fault did
  workloads::ResultValue results;
  double simulated_us = 0;
};

// Takes ownership of the program; `program` stays usable for reading what it recorded.
template <class P>
Outcome run(P* program, const network::Topology& topology,
            const workloads::Placement& placement = {},
            const std::vector<network::FaultSpec>& faults = {}) {
  network::MachineOptions options;
  options.link.speed_mbps = 20;
  network::Machine machine(topology, options);
  for (const network::FaultSpec& f : faults) machine.faults().add(f);
  network::arm_faults(machine);
  const workloads::Params params;
  const workloads::WorkloadContext context{params, topology, nullptr, &placement};
  t800sim::detail::ProgramWorkload workload("test", std::unique_ptr<t800sim::Program>(program),
                                            context);
  workload.build(machine);
  Outcome o;
  try {
    o.blocked = machine.run();
  } catch (...) {
    network::forget_unwound_frames();  // as workloads::run does, before the machine is destroyed
    throw;
  }
  o.simulated_us = machine.simulated_us();
  o.faults = machine.faults().records();
  if (o.blocked.empty()) o.results = workload.results(machine);
  return o;
}

// A program from a build function, for tests that need no results of their own.
class Lambda : public t800sim::Program {
 public:
  explicit Lambda(std::function<void(t800sim::Builder&)> build) : build_(std::move(build)) {}
  void build(t800sim::Builder& b) override { build_(b); }

 private:
  std::function<void(t800sim::Builder&)> build_;
};

}  // namespace sdk_test
