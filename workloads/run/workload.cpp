#include "workloads/run/workload.hpp"

#include <functional>
#include <map>
#include <stdexcept>

#include "workloads/setting_error.hpp"

#include "workloads/farm/dynamics_farm.hpp"
#include "workloads/links/link_workloads.hpp"
#include "workloads/livermore/livermore_workload.hpp"
#include "workloads/pipeline/pipeline.hpp"
#include "workloads/trajectory/trajectory.hpp"

namespace workloads {

namespace {
using Factory = std::function<std::unique_ptr<Workload>(const WorkloadContext&)>;

const std::map<std::string, Factory>& factories() {
  static const std::map<std::string, Factory> f = {
      {"pingpong", make_pingpong},
      {"link-stream", make_link_stream},
      {"dynamics-farm", make_dynamics_farm},
      {"elimination", make_elimination},
      {"trajectory", make_trajectory},
      {"livermore7", make_livermore7},
  };
  return f;
}
}  // namespace

std::unique_ptr<Workload> make_workload(const std::string& kind, const WorkloadContext& context) {
  auto it = factories().find(kind);
  if (it == factories().end()) throw std::invalid_argument("no implementation for workload kind " + kind);
  return it->second(context);
}

const dynamics::RobotModel& require_robot(const WorkloadContext& context) {
  if (!context.robot)
    throw SettingError({"workload.robot"}, "this workload needs a robot model (workload.robot)");
  return *context.robot;
}

int processor_param(const Params& params, const std::string& name, const network::Topology& topology,
                    int fallback) {
  const std::string& value = params.text(name);
  if (value.empty()) return fallback;
  const int index = topology.find(value);
  if (index < 0)
    throw SettingError({"workload." + name}, "workload." + name + ": no processor named " + value);
  return index;
}

}  // namespace workloads
