// A workload is a program for a network: it declares channels and places processes (build), and
// after the run reads back what it measured (results). Each kind registers itself
// (workloads/registry.hpp).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "network/machine.hpp"
#include "workloads/dynamics/robot_model.hpp"
#include "workloads/params.hpp"
#include "workloads/placement.hpp"
#include "workloads/registry.hpp"
#include "workloads/run/output_table.hpp"
#include "workloads/run/result_value.hpp"

namespace workloads {

class Workload {
 public:
  virtual ~Workload() = default;
  virtual void build(network::Machine& machine) = 0;
  virtual ResultValue results(const network::Machine& machine) const = 0;
  // After results(): the tables to write to the workload's output_file parameters (none by
  // default; tools/ writes each where its parameter says).
  virtual std::vector<OutputTable> tables() const { return {}; }
  // Whether results() can say what a run stopped before its end did (by a limit or a deadlock: a
  // booted program's instructions and cycles so far, each processor's state): asked only then.
  // Most workloads' results are an answer, and a stopped run has none.
  virtual bool reports_when_stopped() const { return false; }
};

// What a workload is made from: its validated parameters, the network, the robot model for
// workloads that compute dynamics (loaded by the caller from the workload's `robot` file; null for
// the others), and the scene's placement of processes (programs written with the SDK,
// t800sim/program.hpp).
struct WorkloadContext {
  const Params& params;
  const network::Topology& topology;
  const dynamics::RobotModel* robot = nullptr;
  const Placement* placement = nullptr;
};

// The robot model of a workload that needs one; throws std::invalid_argument when none was loaded.
const dynamics::RobotModel& require_robot(const WorkloadContext& context);

// The processor named by a text parameter, or `fallback` when the parameter is empty.
int processor_param(const Params& params, const std::string& name,
                    const network::Topology& topology, int fallback);

}  // namespace workloads
