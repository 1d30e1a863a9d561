#include "workloads/run/run.hpp"

#include <algorithm>
#include <chrono>
#include <memory>
#include <utility>
#include <vector>

#include "network/families.hpp"
#include "network/unwound_frames.hpp"

#include "workloads/run/process_error.hpp"
#include "workloads/run/workload.hpp"

namespace workloads {

namespace {

FootprintReport footprint(const t800::MemoryMap& map) {
  using Kind = t800::MemoryRegion::Kind;
  FootprintReport f;
  f.on_chip_bytes = map.on_chip_bytes();
  f.reserved_bytes = map.bytes(Kind::reserved);
  f.workspace_bytes = map.bytes(Kind::workspace);
  f.data_bytes = map.bytes(Kind::data);
  f.code_bytes = map.bytes(Kind::code);
  f.library_bytes = map.bytes(Kind::library);
  for (const t800::MemoryRegion& r : map.regions())
    if (r.external) {
      f.external_bytes += r.bytes;
      f.off_chip.push_back(r.name);
    }
  f.external_access_cycles = map.external_cycles();
  return f;
}

std::vector<ProcessorReport> processor_reports(const network::Machine& m, double total_us) {
  std::vector<ProcessorReport> out;
  for (int i = 0; i < m.processors(); ++i) {
    const t800::ProcessorActivity& a = m.transputer(i).activity();
    ProcessorReport r;
    r.name = m.node_name(i);
    r.type = std::string(m.compute_model(i).processor().name);
    r.memory = footprint(m.compute_model(i).memory());
    r.compute_us = a.compute_us();
    r.communicate_us = a.communicate_us();
    r.busy_us = a.busy_us();
    r.idle_us = total_us - r.busy_us;
    r.utilisation = total_us > 0 ? r.busy_us / total_us : 0;
    out.push_back(r);
  }
  return out;
}

std::vector<LinkReport> link_reports(const network::Machine& m, double total_us) {
  std::vector<LinkReport> out;
  for (const auto& info : m.links()) {
    for (int d = 0; d < 2; ++d) {
      const t800::LinkActivity& a = info.link->activity(d);
      LinkReport r;
      r.name =
          m.node_name(info.node[d]) + "->" + m.node_name(info.node[1 - d]) + " (" + info.name + ")";
      r.bytes = a.bytes();
      r.messages = a.messages();
      r.busy_us = a.busy_us();
      r.utilisation = total_us > 0 ? r.busy_us / total_us : 0;
      out.push_back(r);
    }
  }
  return out;
}

std::vector<TraceTrack> trace_tracks(const network::Machine& m, const RunReport& report) {
  std::vector<TraceTrack> tracks;
  for (int i = 0; i < m.processors(); ++i)
    tracks.push_back({TraceTrack::Kind::processor, report.processors[std::size_t(i)].name,
                      m.transputer(i).activity().intervals()});
  std::size_t next = 0;  // link_reports lists both directions of every link, in this order
  for (const auto& info : m.links())
    for (int d = 0; d < 2; ++d)
      tracks.push_back(
          {TraceTrack::Kind::link, report.links[next++].name, info.link->activity(d).intervals()});
  return tracks;
}

// A workload that failed says so in its results' `failure` (elimination, trajectory); any other
// result with a NaN or an infinity failed as well, whether or not the workload noticed.
std::string failure_of(const ResultValue& results) {
  if (const ResultValue* failure = results.get("failure"); failure && !failure->to_text().empty())
    return failure->to_text();
  const std::string at = results.first_non_finite();
  return at.empty() ? "" : "workload." + at + " is not a finite number (NaN or infinite)";
}

RunSetting setting_of(const RunInputs& in) {
  RunSetting s;
  s.kind = in.kind;
  s.precision = in.options.precision;
  s.precision_source = in.precision_source;
  s.network_source = in.topology.source;
  if (const auto family = network::family_of(in.topology))
    s.network_family = std::string(network::to_string(*family));
  for (const network::ProcessorSpec& p : in.topology.processors) {
    const std::string type(t800::to_string(p.config.type));
    if (std::find(s.processor_types.begin(), s.processor_types.end(), type) ==
        s.processor_types.end())
      s.processor_types.push_back(type);
  }
  return s;
}

ResultValue setting_value(const RunSetting& s) {
  ResultValue v;
  v.set("kind", s.kind);
  ResultValue precision;
  precision.set("value", std::string(t800::to_string(s.precision)));
  precision.set("source", s.precision_source);
  v.set("precision", precision);
  ResultValue net;
  net.set("source", s.network_source);
  net.set("family", s.network_family);
  ResultValue types = ResultValue::list();
  for (const std::string& t : s.processor_types) types.push(t);
  net.set("processor_types", types);
  v.set("network", net);
  return v;
}

// Processes a fault left waiting for ever are the fault's (its record lists them); the others, if
// any, are a deadlock. A fault that took effect unrecovered means the results are not results.
void account_faults(const network::Machine& machine, RunReport& report) {
  report.faults = machine.faults().records();
  if (report.faults.empty()) return;
  std::vector<network::BlockedProcess> deadlocked;
  for (const network::BlockedProcess& b : report.blocked) {
    int fault = -1;
    for (const auto& p : machine.processes())
      if (p->name() == b.process && machine.node_name(p->node()) == b.processor && !p->ended())
        fault = network::stranding_fault(machine, *p);
    if (fault < 0)
      deadlocked.push_back(b);
    else
      report.faults[std::size_t(fault)].stranded.push_back(b.process + " on " + b.processor);
  }
  if (deadlocked.empty()) report.wait_cycle.clear();
  report.blocked = deadlocked;
}

std::string unrecovered_fault(const RunReport& report) {
  for (const network::FaultRecord& f : report.faults)
    if (f.fired && f.recovered_how.empty())
      return "fault " + f.describe() + " (" + f.hit + ") was " +
             (f.detected_by.empty() ? "not detected" : "detected by " + f.detected_by) +
             " and not recovered: the results are not results";
  return "";
}

ResultValue fault_value(const network::FaultRecord& f) {
  ResultValue r;
  r.set("kind", std::string(network::to_string(f.spec.kind)));
  r.set("where", f.spec.where());
  r.set("when_us", f.spec.at_us);
  r.set("took_effect", f.fired);
  if (f.fired) {
    r.set("took_effect_us", f.fired_us);
    r.set("hit", f.hit);
  }
  r.set("detected_by", f.detected_by);
  if (f.detected_us >= 0) r.set("detected_us", f.detected_us);
  r.set("recovered_how", f.recovered_how);
  if (f.recovered_us >= 0) {
    r.set("recovered_us", f.recovered_us);
    r.set("cost_us", f.cost_us());
  }
  ResultValue stranded = ResultValue::list();
  for (const std::string& p : f.stranded) stranded.push(p);
  r.set("stranded", stranded);
  return r;
}

}  // namespace

Realised realise(const RunInputs& in) {
  Realised r;
  r.machine = std::make_unique<network::Machine>(in.topology, in.options);
  for (const network::FaultSpec& f : in.faults) r.machine->faults().add(f);
  network::arm_faults(*r.machine);
  r.workload = make_workload(
      in.kind, WorkloadContext{in.params, in.topology, in.robot.get(), &in.placement});
  r.workload->build(*r.machine);
  r.machine->prepare();
  return r;
}

namespace {

// A machine whose processes were left standing (MachineOptions::tear_down false) must never be
// destroyed -- its threads still refer to it -- so it is kept, reachable (a leak checker does not
// report it), until the program exits.
void leave_standing(std::unique_ptr<network::Machine> machine) {
  static auto* standing = new std::vector<std::unique_ptr<network::Machine>>();
  standing->push_back(std::move(machine));
}

}  // namespace

namespace {

// Runs the realised scene and gathers its report; what it throws leaves through run(), which
// clears the unwound frames before `realised` (program, builder, machine) is destroyed.
RunReport simulate(const RunInputs& in, Realised& realised) {
  network::Machine& machine = *realised.machine;
  const std::unique_ptr<Workload>& workload = realised.workload;
  RunReport report;
  report.name = in.name;
  report.setting = setting_of(in);
  report.fidelity = in.options.fidelity;
  report.run_time_checks = in.options.checked;
  try {
    report.blocked = machine.run();
  } catch (...) {
    throw_recorded_process_error();  // in place of SystemC's report of it
    throw;
  }
  report.wait_cycle = machine.wait_cycle();
  report.limit = machine.limit_reached();
  report.stop_signal = machine.stop_signal();
  report.running_at_stop = machine.running_at_stop();
  report.trace_forecast = machine.trace_forecast();
  report.simulated_us = machine.simulated_us();
  report.events = machine.events();
  report.elaboration_s = machine.elaboration_s();
  report.processors = processor_reports(machine, report.simulated_us);
  report.links = link_reports(machine, report.simulated_us);
  if (in.options.keep_intervals) report.tracks = trace_tracks(machine, report);
  account_faults(machine, report);
  if (report.blocked.empty() && report.limit == network::Limit::none) {
    report.failure = unrecovered_fault(report);
    if (report.failure.empty()) {
      report.workload = workload->results(machine);
      report.tables = workload->tables();
      report.failure = failure_of(report.workload);
    }
  } else if (workload->reports_when_stopped()) {  // a limit or a deadlock
    report.workload = workload->results(machine);
  }
  return report;
}

}  // namespace

RunReport run(const RunInputs& in) {
  const auto start = std::chrono::steady_clock::now();
  Realised realised = realise(in);
  RunReport report;
  try {
    report = simulate(in, realised);
  } catch (...) {
    network::forget_unwound_frames();
    throw;
  }
  report.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!realised.machine->tears_down()) leave_standing(std::move(realised.machine));
  return report;
}

ResultValue RunReport::to_value() const {
  ResultValue v;
  v.set("scene", name);
  v.set("simulated_us", simulated_us);
  v.set("wall_s", wall_s);
  v.set("elaboration_s", elaboration_s);
  v.set("events", std::int64_t(events));
  v.set("setting", setting_value(setting));
  ResultValue f;
  f.set("links", std::string(t800::to_string(fidelity.links)));
  f.set("compute", std::string(t800::to_string(fidelity.compute)));
  f.set("compute_cost", std::string(t800::to_string(fidelity.compute_cost)));
  f.set("skip_numerics", fidelity.skip_numerics);
  f.set("reuse_steps", fidelity.reuse_steps);
  v.set("fidelity", std::move(f));
  ResultValue compiler;
  compiler.set("run_time_checks", run_time_checks);
  v.set("compiler", std::move(compiler));
  ResultValue procs = ResultValue::list();
  for (const ProcessorReport& p : processors) {
    ResultValue r;
    r.set("name", p.name);
    r.set("busy_us", p.busy_us);
    r.set("compute_us", p.compute_us);
    r.set("communicate_us", p.communicate_us);
    r.set("idle_us", p.idle_us);
    r.set("utilisation", p.utilisation);
    r.set("type", p.type);
    ResultValue mem;
    mem.set("on_chip_bytes", std::int64_t(p.memory.on_chip_bytes));
    mem.set("reserved_bytes", std::int64_t(p.memory.reserved_bytes));
    mem.set("workspace_bytes", std::int64_t(p.memory.workspace_bytes));
    mem.set("data_bytes", std::int64_t(p.memory.data_bytes));
    mem.set("code_bytes", std::int64_t(p.memory.code_bytes));
    mem.set("library_bytes", std::int64_t(p.memory.library_bytes));
    mem.set("external_bytes", std::int64_t(p.memory.external_bytes));
    ResultValue off = ResultValue::list();
    for (const std::string& name : p.memory.off_chip) off.push(ResultValue(name));
    mem.set("off_chip", std::move(off));
    mem.set("external_access_cycles", std::int64_t(p.memory.external_access_cycles));
    r.set("memory", std::move(mem));
    procs.push(std::move(r));
  }
  v.set("processors", std::move(procs));
  ResultValue links_value = ResultValue::list();
  for (const LinkReport& l : links) {
    ResultValue r;
    r.set("name", l.name);
    r.set("bytes", l.bytes);
    r.set("messages", l.messages);
    r.set("busy_us", l.busy_us);
    r.set("utilisation", l.utilisation);
    links_value.push(std::move(r));
  }
  v.set("links", std::move(links_value));
  if (!failure.empty()) v.set("failure", failure);
  if (!faults.empty()) {
    ResultValue list = ResultValue::list();
    for (const network::FaultRecord& f : faults) list.push(fault_value(f));
    v.set("faults", std::move(list));
  }
  if (limit != network::Limit::none) {
    v.set("stopped_by", network::to_string(limit));
    if (stop_signal) v.set("stop_signal", std::int64_t(stop_signal));
    ResultValue list = ResultValue::list();
    for (const auto& p : running_at_stop) {
      ResultValue r;
      r.set("process", p.process);
      r.set("processor", p.processor);
      r.set("status", p.status);
      list.push(std::move(r));
    }
    v.set("running_at_stop", std::move(list));
  }
  if (!blocked.empty()) {
    ResultValue b = ResultValue::list();
    for (const auto& p : blocked) {
      ResultValue r;
      r.set("process", p.process);
      r.set("processor", p.processor);
      r.set("status", p.status);
      r.set("waits_for", p.waits_for);
      b.push(std::move(r));
    }
    v.set("deadlock", std::move(b));
    ResultValue cycle = ResultValue::list();
    for (const std::string& step : wait_cycle) cycle.push(step);
    v.set("wait_cycle", std::move(cycle));
  }
  v.set("workload", workload);
  return v;
}

}  // namespace workloads
