// A program written with the SDK (t800sim/program.hpp), run as a workload: its processes placed,
// its channels joined and routed, its kernels' code declared, its results reported with where every
// process ran.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "sdk/placement.hpp"
#include "t800sim/program.hpp"
#include "workloads/run/workload.hpp"

namespace t800sim::detail {

class ProgramWorkload : public workloads::Workload {
 public:
  ProgramWorkload(std::string kind, std::unique_ptr<Program> program,
                  const workloads::WorkloadContext& context);

  void build(network::Machine& machine) override;
  workloads::ResultValue results(const network::Machine& machine) const override;
  std::vector<workloads::OutputTable> tables() const override { return tables_; }

 private:
  void check_tables() const;

  std::string kind_;
  std::unique_ptr<Program> program_;
  const network::Topology& topology_;
  std::vector<workloads::PlacementEntry> scene_placement_;
  Builder builder_;  // owns the channels the processes' handles point to
  std::vector<PlacedProcess> placed_;
  mutable std::vector<workloads::OutputTable> tables_;  // the program's, from results()
};

}  // namespace t800sim::detail
