#include "network/activity_delta.hpp"

#include "network/process.hpp"

namespace network {

namespace {

double to_us(const sc_core::sc_time& t) {
  return t.to_seconds() * 1e6;
}

std::vector<t800::Interval> shifted(const std::vector<t800::Interval>& from, std::size_t first,
                                    double by_us) {
  std::vector<t800::Interval> out(from.begin() + std::ptrdiff_t(first), from.end());
  for (t800::Interval& i : out) {
    i.start_us += by_us;
    i.end_us += by_us;
  }
  return out;
}

}  // namespace

std::int64_t clock_events(Machine& m) {
  std::int64_t n = 0;
  for (int i = 0; i < m.processors(); ++i) {
    const t800::CpuStatistics& s = m.transputer(i).cpu().statistics();
    n += s.clock_dependent + s.timeslices;
  }
  return n;
}

ActivitySnapshot snapshot(Machine& m) {
  ActivitySnapshot s;
  s.at = t800::sim_now();
  for (int i = 0; i < m.processors(); ++i) {
    const t800::ProcessorActivity& a = m.transputer(i).activity();
    s.compute_us.push_back(a.compute_us());
    s.communicate_us.push_back(a.communicate_us());
    s.first_busy_us.push_back(a.first_busy_us());
    s.last_busy_us.push_back(a.last_busy_us());
    s.processor_intervals.push_back(a.intervals().size());
  }
  for (const auto& info : m.links())
    for (int d = 0; d < 2; ++d) {
      const t800::LinkActivity& a = info.link->activity(d);
      s.bytes.push_back(a.bytes());
      s.messages.push_back(a.messages());
      s.link_busy_us.push_back(a.busy_us());
      s.link_intervals.push_back(a.intervals().size());
    }
  s.clock = clock_events(m);
  return s;
}

ActivityDelta delta_since(Machine& m, const ActivitySnapshot& before) {
  ActivityDelta d;
  d.duration = t800::sim_now() - before.at;
  const double start_us = to_us(before.at);
  for (int i = 0; i < m.processors(); ++i) {
    const std::size_t k = std::size_t(i);
    const t800::ProcessorActivity& a = m.transputer(i).activity();
    ProcessorDelta p;
    p.compute_us = a.compute_us() - before.compute_us[k];
    p.communicate_us = a.communicate_us() - before.communicate_us[k];
    if (before.first_busy_us[k] < 0 && a.first_busy_us() >= 0)
      p.first_busy_us = a.first_busy_us() - start_us;
    if (a.last_busy_us() != before.last_busy_us[k]) p.last_busy_us = a.last_busy_us() - start_us;
    p.intervals = shifted(a.intervals(), before.processor_intervals[k], -start_us);
    d.processors.push_back(std::move(p));
  }
  std::size_t k = 0;
  for (const auto& info : m.links())
    for (int dir = 0; dir < 2; ++dir, ++k) {
      const t800::LinkActivity& a = info.link->activity(dir);
      LinkDelta l;
      l.bytes = a.bytes() - before.bytes[k];
      l.messages = a.messages() - before.messages[k];
      l.busy_us = a.busy_us() - before.link_busy_us[k];
      l.intervals = shifted(a.intervals(), before.link_intervals[k], -start_us);
      d.links.push_back(std::move(l));
    }
  return d;
}

void credit(Machine& m, const ActivityDelta& d, const sc_core::sc_time& start) {
  const double start_us = to_us(start);
  auto at = [start_us](double offset) { return offset < 0 ? -1.0 : start_us + offset; };
  for (int i = 0; i < m.processors(); ++i) {
    const ProcessorDelta& p = d.processors[std::size_t(i)];
    m.transputer(i).activity().credit(p.compute_us, p.communicate_us, at(p.first_busy_us),
                                      at(p.last_busy_us), shifted(p.intervals, 0, start_us));
  }
  std::size_t k = 0;
  for (const auto& info : m.links())
    for (int dir = 0; dir < 2; ++dir, ++k) {
      const LinkDelta& l = d.links[k];
      info.link->activity(dir).credit(l.bytes, l.messages, l.busy_us,
                                      shifted(l.intervals, 0, start_us));
    }
}

void replay(Process& p, const ActivityDelta& d) {
  const sc_core::sc_time start = t800::sim_now();
  sc_core::wait(d.duration);
  credit(p.machine(), d, start);
}

std::string unquiet(Machine& m) {
  for (int i = 0; i < m.processors(); ++i)
    if (!m.transputer(i).activity().idle()) return m.node_name(i) + " was busy";
  for (const auto& info : m.links())
    if (!info.link->quiet()) return "link " + info.name + " was not quiet";
  return {};
}

}  // namespace network
