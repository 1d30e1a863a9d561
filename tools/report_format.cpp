#include "tools/report_format.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

namespace tools {

namespace {

const char* limit_name(network::Limit limit) {
  switch (limit) {
    case network::Limit::sim_time:
      return "simulated-time";
    case network::Limit::trace_size:
      return "trace-size";
    case network::Limit::livelock:
      return "livelock";
    case network::Limit::interrupted:
      return "stop-request";
    default:
      return "wall-time";
  }
}

}  // namespace

std::string format_text(const workloads::RunReport& r, const std::string& note) {
  std::string out = fmt::format("scene {}\n", r.name);
  out += fmt::format("simulated time  {:.3f} us\n", r.simulated_us);
  out += fmt::format("simulator       {:.3f} s wall, {} events\n", r.wall_s, r.events);
  const workloads::RunSetting& s = r.setting;
  out += fmt::format("workload kind   {}\n", s.kind);
  out += fmt::format("precision       {} ({})\n", t800::to_string(s.precision), s.precision_source);
  out += fmt::format("network         {}{}, {} processor{} ({})\n", s.network_source,
                     s.network_family.empty() || s.network_source.rfind("family:", 0) == 0
                         ? ""
                         : " (wired as family " + s.network_family + ", " +
                               std::to_string(r.processors.size() - 1) +
                               (r.processors.size() == 2 ? " worker)" : " workers)"),
                     r.processors.size(), r.processors.size() == 1 ? "" : "s",
                     fmt::join(s.processor_types, ", "));
  if (!note.empty()) out += note + "\n";
  out += fmt::format("\n{:<12} {:>12} {:>12} {:>14} {:>12} {:>8}\n", "processor", "busy_us",
                     "compute_us", "communicate_us", "idle_us", "util_%");
  for (const auto& p : r.processors)
    out += fmt::format("{:<12} {:>12.3f} {:>12.3f} {:>14.3f} {:>12.3f} {:>8.1f}\n", p.name,
                       p.busy_us, p.compute_us, p.communicate_us, p.idle_us, 100.0 * p.utilisation);
  out += fmt::format("\n{:<44} {:>10} {:>9} {:>12} {:>8}\n", "link direction", "bytes", "messages",
                     "busy_us", "util_%");
  for (const auto& l : r.links)
    if (l.bytes > 0 || l.busy_us > 0)
      out += fmt::format("{:<44} {:>10} {:>9} {:>12.3f} {:>8.1f}\n", l.name, l.bytes, l.messages,
                         l.busy_us, 100.0 * l.utilisation);
  if (!r.faults.empty()) out += "\nfaults\n";
  for (const network::FaultRecord& f : r.faults) {
    out += "  " + f.describe() + ": ";
    if (!f.fired) {
      out += "no effect (nothing it could hit after that time)\n";
      continue;
    }
    out += fmt::format("took effect at {:.3f} us ({})", f.fired_us, f.hit);
    out += f.detected_by.empty()
               ? ", not detected"
               : fmt::format(", detected by {} at {:.3f} us", f.detected_by, f.detected_us);
    out += f.recovered_how.empty()
               ? ", not recovered"
               : fmt::format(", recovered: {} (done at {:.3f} us, {:.3f} us after it took effect)",
                             f.recovered_how, f.recovered_us, f.cost_us());
    if (!f.stranded.empty()) out += fmt::format("; left waiting: {}", fmt::join(f.stranded, ", "));
    out += "\n";
  }
  if (r.limit != network::Limit::none) {
    out += fmt::format(
        "\nSTOPPED by the {} limit before the run ended{}\n", limit_name(r.limit),
        r.workload.is_record() && !r.workload.record().empty() ? "" : ": no workload results");
    for (const auto& p : r.running_at_stop)
      out += fmt::format("  {} on {}: {}\n", p.process, p.processor, p.status);
  } else if (!r.blocked.empty()) {
    out += "\nDEADLOCK: the simulation ran out of events with processes still blocked:\n";
    for (const network::FaultRecord& f : r.faults)
      if (f.fired)  // as the faults section above says it
        out += "  (after the fault " + f.describe() +
               (f.recovered_how.empty() ? ", not recovered)\n"
                                        : ", recovered: " + f.recovered_how + ")\n");
    for (const auto& b : r.blocked)
      out += fmt::format("  {} on {}: {}, waiting for {}\n", b.process, b.processor, b.status,
                         b.waits_for);
    if (!r.wait_cycle.empty()) {
      out += "the cycle of waits:\n";
      for (const std::string& step : r.wait_cycle) out += "  " + step + "\n";
    }
  } else {
    out += "\nworkload\n" + r.workload.to_text(2);
    if (!r.failure.empty()) out += "\nFAILED: " + r.failure + "\n";
  }
  return out;
}

std::string format_json(const workloads::RunReport& r) {
  return r.to_value().to_json() + "\n";
}

}  // namespace tools
