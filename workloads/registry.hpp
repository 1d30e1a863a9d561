// The workload kinds the simulator knows: each registers itself once, next to its code, with its
// parameters (kind, summary, types, ranges, help) and its factory. Scene validation, `t800sim run
// --help`, the runner and plugins all go through here; nothing else lists kinds or parameters.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "workloads/params.hpp"

namespace workloads {

class Workload;
struct WorkloadContext;
using WorkloadFactory = std::function<std::unique_ptr<Workload>(const WorkloadContext&)>;

// Throws std::invalid_argument for a kind registered twice or a parameter declared twice.
void register_kind(WorkloadInfo info, WorkloadFactory make);

// For a static object in a workload's file: registers the kind when the program starts.
struct Registration {
  Registration(WorkloadInfo info, WorkloadFactory make) {
    register_kind(std::move(info), std::move(make));
  }
};

// Every kind, sorted by name.
std::vector<WorkloadInfo> workload_catalog();
// nullptr for an unknown kind; stays valid while the program runs.
const WorkloadInfo* find_workload(const std::string& kind);
// Throws std::invalid_argument for an unknown kind, or what the factory throws (a setting the
// topology cannot host).
std::unique_ptr<Workload> make_workload(const std::string& kind, const WorkloadContext& context);

}  // namespace workloads
