// A program written with the SDK (t800sim/program.hpp), run as a workload: its processes placed,
// its channels joined and routed, its kernels' code declared, its results reported with where every
// process ran.
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "sdk/booted.hpp"
#include "sdk/placement.hpp"
#include "t800sim/program.hpp"
#include "workloads/run/workload.hpp"

namespace t800sim::detail {

// Runs a piece of the program's own code -- its factory, its build() -- so that what it throws
// names the workload (`label`: its kind, and its plugin if a plugin registered it): a SettingError
// keeps its keys and a network::ConfigError its place; anything else becomes std::invalid_argument
// (bad input: the program refused its settings), saying what `step` threw.
void run_program_code(const std::string& label, const std::string& step,
                      const std::function<void()>& code);

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
  std::string label_;  // for messages: the kind, and the plugin that registered it
  std::unique_ptr<Program> program_;
  const network::Topology& topology_;
  std::vector<workloads::PlacementEntry> scene_placement_;
  Builder builder_;  // owns the channels the processes' handles point to
  std::vector<PlacedProcess> placed_;
  std::optional<BootedProcessors> booted_;              // its processors that run machine code
  mutable std::vector<workloads::OutputTable> tables_;  // the program's, from results()
};

}  // namespace t800sim::detail
