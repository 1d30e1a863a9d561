#include "workloads/run/workload.hpp"

#include <stdexcept>

namespace workloads {

const dynamics::RobotModel& require_robot(const WorkloadContext& context) {
  if (!context.robot)
    throw std::invalid_argument("this workload needs a robot model (workload.robot)");
  return *context.robot;
}

int processor_param(const Params& params, const std::string& name,
                    const network::Topology& topology, int fallback) {
  const std::string& value = params.text(name);
  if (value.empty()) return fallback;
  const int index = topology.find(value);
  if (index < 0) throw std::invalid_argument("workload." + name + ": no processor named " + value);
  return index;
}

}  // namespace workloads
