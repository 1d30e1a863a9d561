// A workload is a program for a network: it declares channels and places processes (build), and after the
// run reads back what it measured (results). Each kind is declared in catalog.cpp and made here.
#pragma once

#include <memory>
#include <string>

#include "network/machine.hpp"
#include "workloads/dynamics/robot_model.hpp"
#include "workloads/params.hpp"
#include "workloads/run/result_value.hpp"

namespace workloads {

class Workload {
 public:
  virtual ~Workload() = default;
  virtual void build(network::Machine& machine) = 0;
  virtual ResultValue results(const network::Machine& machine) const = 0;
};

// What a workload is made from: its validated parameters, the network, and the robot model for workloads
// that compute dynamics (loaded by the caller from the workload's `robot` file; null for the others).
struct WorkloadContext {
  const Params& params;
  const network::Topology& topology;
  const dynamics::RobotModel* robot = nullptr;
};

// Throws std::invalid_argument for a kind without an implementation, or a setting the topology cannot host
// (e.g. two processors that are not neighbours where neighbours are needed), with a message for the user.
std::unique_ptr<Workload> make_workload(const std::string& kind, const WorkloadContext& context);

// The robot model of a workload that needs one; throws std::invalid_argument when none was loaded.
const dynamics::RobotModel& require_robot(const WorkloadContext& context);

// The processor named by a text parameter, or `fallback` when the parameter is empty.
int processor_param(const Params& params, const std::string& name, const network::Topology& topology,
                    int fallback);

}  // namespace workloads
