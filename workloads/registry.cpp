#include "workloads/registry.hpp"

#include <algorithm>
#include <deque>
#include <set>
#include <stdexcept>

#include "workloads/run/workload.hpp"

namespace workloads {

namespace {

struct Kind {
  WorkloadInfo info;
  WorkloadFactory make;
};

// A deque: find_workload hands out pointers that must outlive later registrations (plugins).
std::deque<Kind>& kinds() {
  static std::deque<Kind> k;
  return k;
}

const Kind* find_kind(const std::string& name) {
  for (const Kind& k : kinds())
    if (k.info.kind == name) return &k;
  return nullptr;
}

}  // namespace

void register_kind(WorkloadInfo info, WorkloadFactory make) {
  if (info.kind.empty()) throw std::invalid_argument("a workload kind needs a name");
  if (find_kind(info.kind))
    throw std::invalid_argument("workload kind " + info.kind + " is registered twice");
  std::set<std::string> names;
  for (const ParamSpec& p : info.params)
    if (!names.insert(p.name).second)
      throw std::invalid_argument("workload kind " + info.kind + " declares parameter " + p.name +
                                  " twice");
  for (ParamType once : {ParamType::robot_file, ParamType::precision})
    if (std::count_if(info.params.begin(), info.params.end(),
                      [once](const ParamSpec& p) { return p.type == once; }) > 1)
      throw std::invalid_argument("workload kind " + info.kind + " declares more than one " +
                                  to_string(once) + " parameter");
  if (!make) throw std::invalid_argument("workload kind " + info.kind + " has no factory");
  kinds().push_back({std::move(info), std::move(make)});
}

std::vector<WorkloadInfo> workload_catalog() {
  std::vector<WorkloadInfo> all;
  for (const Kind& k : kinds()) all.push_back(k.info);
  std::sort(all.begin(), all.end(),
            [](const WorkloadInfo& a, const WorkloadInfo& b) { return a.kind < b.kind; });
  return all;
}

const WorkloadInfo* find_workload(const std::string& kind) {
  const Kind* k = find_kind(kind);
  return k ? &k->info : nullptr;
}

std::unique_ptr<Workload> make_workload(const std::string& kind, const WorkloadContext& context) {
  const Kind* k = find_kind(kind);
  if (!k) throw std::invalid_argument("no workload kind " + kind);
  return k->make(context);
}

}  // namespace workloads
