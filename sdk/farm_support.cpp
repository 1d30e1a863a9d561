// The farm skeleton's dealings with the machine (t800sim/farm.hpp): planning from its timing and
// topology, reading its processors' activity, telling its fault log.
#include <stdexcept>

#include "network/machine.hpp"
#include "network/process.hpp"
#include "t800/link_timing.hpp"
#include "t800sim/farm.hpp"

namespace t800sim::detail {

namespace {

int processor_of(const Builder& b, const std::string& process) {
  for (const ProcessDecl& d : b.declared_processes())
    if (d.name == process && !d.group) {
      if (d.on.empty()) return b.network().host_processor();
      const int node = b.network().find(d.on.front());
      if (node < 0)
        throw std::invalid_argument("the farm's master is placed on " + d.on.front() +
                                    ", which the network does not have");
      return node;
    }
  throw std::invalid_argument("the farm's master, process " + process +
                              ", is not declared before the farm is built");
}

// The list scheduler's view of each worker: its distance from the master in hops sets when its
// input arrives and what each returned result costs (t800sim/farm_schedule.hpp).
Allocation static_schedule(const network::Machine& m, const FarmPlan& plan,
                           std::int64_t shared_bytes, std::int64_t result_bytes) {
  const double cycle_ns = m.compute_model(plan.master).cycle_ns();
  const t800::LinkTiming link(m.options().link);
  const double hop_overhead =
      double(m.compute_model(plan.master).communication_cycles(0, false)) * cycle_ns;
  std::vector<double> task_ns;
  for (std::int64_t c : plan.task_cycles) task_ns.push_back(double(c) * cycle_ns);
  std::vector<WorkerCosts> costs;
  for (int w : plan.workers) {
    const double hops = double(m.route(plan.master, w).size() - 1);
    costs.push_back({hops * (link.arrival_ns(shared_bytes) + hop_overhead),
                     hops * double(result_bytes) * link.byte_period_ns,
                     hops * (link.data_packet_ns + hop_overhead)});
  }
  return schedule_static(task_ns, costs);
}

network::Machine& machine_of(Process& p) {
  return p.impl().machine();
}

}  // namespace

FarmPlan plan_farm(const Builder& b, const std::string& master,
                   const std::vector<std::string>& worker_processors,
                   const std::vector<FarmTask>& tasks, const FarmOptions& options,
                   std::int64_t shared_bytes, std::int64_t result_bytes) {
  const network::Machine* m = b.machine();
  if (!m) throw std::logic_error("a farm is built on a machine (Builder::attach)");
  if (worker_processors.empty())
    throw std::invalid_argument("the farm needs at least one worker besides the master");
  FarmPlan plan;
  plan.master = processor_of(b, master);
  for (const std::string& name : worker_processors) {
    const int node = b.network().find(name);
    if (node < 0)
      throw std::invalid_argument("farm worker processor " + name + ": the network has none");
    plan.workers.push_back(node);
  }
  plan.worker_names = worker_processors;
  for (const FarmTask& t : tasks)
    plan.task_cycles.push_back(m->compute_model(plan.workers.front()).cycles(t.kernel.work()));
  if (options.schedule == FarmSchedule::explicit_allocation) {
    std::vector<std::string> task_names;
    for (const FarmTask& t : tasks) task_names.push_back(t.name);
    plan.allocation = parse_allocation(options.allocation, task_names, worker_processors,
                                       options.allocation_setting);
  } else if (options.schedule == FarmSchedule::static_list) {
    plan.allocation = static_schedule(*m, plan, shared_bytes, result_bytes);
  } else {
    plan.allocation.assign(plan.workers.size(), {});
  }
  return plan;
}

// The tasks' cycles on this worker with its memory as placed (code off chip costs more), and the
// bytes on the links, hop by hop.
double farm_predicted_us(Process& master, const FarmPlan& plan, std::size_t w,
                         const std::vector<FarmTask>& tasks, const std::vector<INT>& task_list,
                         std::int64_t bytes) {
  const network::Machine& m = machine_of(master);
  const t800::LinkTiming link(m.options().link);
  const double hops = double(m.topology().shortest_path(plan.master, plan.workers[w]).size() - 1);
  const t800::ComputeModel& model = m.compute_model(plan.workers[w]);
  double compute_ns = 0;
  for (INT t : task_list) compute_ns += double(model.cycles(tasks[std::size_t(t)].kernel.work()));
  compute_ns *= model.cycle_ns();
  return (compute_ns + hops * link.arrival_ns(bytes)) / 1000.0;
}

std::vector<double> farm_busy_now(Process& p, const FarmPlan& plan) {
  network::Machine& m = machine_of(p);
  std::vector<double> busy;
  for (int w : plan.workers) busy.push_back(m.transputer(w).activity().busy_us_now());
  return busy;
}

namespace {
// "P2, P5, P8": the workers of one failure (a halted processor takes its subtree with it).
std::string names_of(const FarmPlan& plan, const std::vector<std::size_t>& ws) {
  std::string s;
  for (std::size_t w : ws) s += (s.empty() ? "" : ", ") + plan.worker_names[w];
  return s;
}
}  // namespace

void farm_lost(Process& master, const FarmPlan& plan, const std::vector<std::size_t>& ws) {
  network::Machine& m = machine_of(master);
  const std::string by = "the master's InputOrFail / OutputOrFail deadline (" + names_of(plan, ws) +
                         " did not answer)";
  for (std::size_t w : ws)
    m.faults().detected(m, m.topology().shortest_path(plan.master, plan.workers[w]), by);
}

void farm_recovered(Process& master, const FarmPlan& plan, const std::vector<std::size_t>& ws,
                    const std::string& to) {
  network::Machine& m = machine_of(master);
  const std::string how = "the master gave the tasks of " + names_of(plan, ws) + " to " + to;
  for (std::size_t w : ws)
    m.faults().recovered(m, m.topology().shortest_path(plan.master, plan.workers[w]), how);
}

void farm_corrupted(Process& master, const FarmPlan& plan, std::size_t w, bool order) {
  network::Machine& m = machine_of(master);
  const std::string& name = plan.worker_names[w];
  m.faults().detected(m, m.topology().shortest_path(plan.master, plan.workers[w]),
                      order ? name + "'s checksum of the master's order"
                            : "the master's checksum of " + name + "'s reply");
}

void farm_resent(Process& master, const FarmPlan& plan, std::size_t w) {
  network::Machine& m = machine_of(master);
  m.faults().recovered(m, m.topology().shortest_path(plan.master, plan.workers[w]),
                       "the master sent " + plan.worker_names[w] + " its order again");
}

void farm_stop(Process& p, const std::string& why) {
  p.impl().stop(why);
}

}  // namespace t800sim::detail
