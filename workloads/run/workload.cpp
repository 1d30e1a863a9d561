#include "workloads/run/workload.hpp"

#include <stdexcept>

#include "workloads/setting_error.hpp"

namespace workloads {

const dynamics::RobotModel& require_robot(const WorkloadContext& context) {
  if (!context.robot)
    throw SettingError({"workload.robot"}, "this workload needs a robot model (workload.robot)");
  return *context.robot;
}

int processor_param(const Params& params, const std::string& name,
                    const network::Topology& topology, int fallback) {
  const std::string& value = params.text(name);
  if (value.empty()) return fallback;
  const int index = topology.find(value);
  if (index < 0)
    throw SettingError({"workload." + name}, "workload." + name + ": no processor named " + value);
  return index;
}

}  // namespace workloads
