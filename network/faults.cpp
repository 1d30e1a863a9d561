#include "network/faults.hpp"

#include <algorithm>
#include <sstream>
#include <stdexcept>

#include "network/machine.hpp"

namespace network {

namespace {

std::string format_us(double us) {
  std::ostringstream s;
  s << us;
  return s.str();
}

int node_of(const Machine& m, const std::string& name) {
  const int node = m.topology().find(name);
  if (node < 0) throw std::logic_error("fault names an unknown processor " + name);
  return node;
}

// The link from `from` to `to` and the end of it at `from`.
std::pair<t800::Link*, int> link_of(const Machine& m, const FaultSpec& f) {
  const auto link = m.link_between(node_of(m, f.from), node_of(m, f.to));
  if (!link) throw std::logic_error("fault on " + f.where() + ": not neighbours");
  return *link;
}

bool adjacent_in(const std::vector<int>& path, int a, int b) {
  for (std::size_t i = 0; i + 1 < path.size(); ++i)
    if ((path[i] == a && path[i + 1] == b) || (path[i] == b && path[i + 1] == a)) return true;
  return false;
}

}  // namespace

const char* to_string(FaultSpec::Kind kind) {
  switch (kind) {
    case FaultSpec::Kind::corrupt:
      return "corrupt";
    case FaultSpec::Kind::drop:
      return "drop";
    case FaultSpec::Kind::dead_link:
      return "dead-link";
    case FaultSpec::Kind::halt:
      return "halt";
  }
  return "?";
}

std::string FaultSpec::where() const {
  switch (kind) {
    case Kind::corrupt:
    case Kind::drop:
      return from + "->" + to;
    case Kind::dead_link:
      return from + "-" + to;
    case Kind::halt:
      return processor;
  }
  return "?";
}

std::string FaultRecord::describe() const {
  return std::string(to_string(spec.kind)) + " on " + spec.where() + " at " +
         format_us(spec.at_us) + " us";
}

void FaultLog::fired(std::size_t i, const std::string& what) {
  FaultRecord& r = records_.at(i);
  if (r.fired) return;
  r.fired = true;
  r.fired_us = t800::sim_now().to_seconds() * 1e6;
  r.hit = what;
}

bool FaultLog::on_path(const Machine& m, const FaultRecord& r, const std::vector<int>& path) const {
  if (r.spec.kind == FaultSpec::Kind::halt)
    return std::find(path.begin(), path.end(), m.topology().find(r.spec.processor)) != path.end();
  return adjacent_in(path, m.topology().find(r.spec.from), m.topology().find(r.spec.to));
}

int FaultLog::detected(const Machine& m, const std::vector<int>& path, const std::string& by) {
  int n = 0;
  for (FaultRecord& r : records_) {
    if (!r.fired || !r.recovered_how.empty() || !on_path(m, r, path)) continue;
    ++n;
    if (!r.detected_by.empty()) continue;
    r.detected_by = by;
    r.detected_us = t800::sim_now().to_seconds() * 1e6;
  }
  return n;
}

void FaultLog::recovered(const Machine& m, const std::vector<int>& path, const std::string& how) {
  for (FaultRecord& r : records_) {
    // The first recovery counts: a fault that keeps acting (a dead link, a halted processor) is
    // recovered from once the program has worked round it the first time.
    if (r.detected_by.empty() || !r.recovered_how.empty() || !on_path(m, r, path)) continue;
    r.recovered_how = how;
    r.recovered_us = t800::sim_now().to_seconds() * 1e6;
  }
}

void arm_faults(Machine& m) {
  FaultLog& log = m.faults();
  for (std::size_t i = 0; i < log.records().size(); ++i) {
    const FaultSpec& f = log.records()[i].spec;
    const sc_core::sc_time at(f.at_us, sc_core::SC_US);
    auto hit = [&log, i](const std::string& what) { log.fired(i, what); };
    switch (f.kind) {
      case FaultSpec::Kind::drop: {
        const auto [link, end] = link_of(m, f);
        link->drop_byte(end, at, hit);
        break;
      }
      case FaultSpec::Kind::corrupt: {
        const auto [link, end] = link_of(m, f);
        link->corrupt_byte(end, at, std::uint8_t(f.xor_mask), hit);
        break;
      }
      case FaultSpec::Kind::dead_link: {
        t800::Link* link = link_of(m, f).first;
        for (int e = 0; e < 2; ++e) {
          link->stop_wire(e, at, hit);
          link->deafen_end(e, at, hit);
        }
        break;
      }
      case FaultSpec::Kind::halt: {
        const int node = node_of(m, f.processor);
        m.transputer(node).cpu().halt_at(
            at, [hit](const std::string& process) { hit("process " + process + " stopped"); });
        for (const Machine::LinkInfo& l : m.links())
          for (int e = 0; e < 2; ++e)
            if (l.node[e] == node) {
              l.link->stop_wire(e, at, hit);
              l.link->deafen_end(e, at, hit);
            }
        break;
      }
    }
  }
}

int stranding_fault(const Machine& m, const Process& p) {
  const std::vector<FaultRecord>& records = m.faults().records();
  for (std::size_t i = 0; i < records.size(); ++i) {
    const FaultRecord& r = records[i];
    if (!r.fired) continue;
    if (r.spec.kind == FaultSpec::Kind::halt && p.node() == m.topology().find(r.spec.processor))
      return int(i);
    // At an end of a faulted link: its partners gave it up.
    if (r.spec.kind != FaultSpec::Kind::halt &&
        (p.node() == m.topology().find(r.spec.from) || p.node() == m.topology().find(r.spec.to)) &&
        p.channel())
      return int(i);
    if (const Channel* c = p.channel()) {
      const std::vector<int>& path = c->path;
      const bool crosses =
          r.spec.kind == FaultSpec::Kind::halt
              ? std::find(path.begin(), path.end(), m.topology().find(r.spec.processor)) !=
                    path.end()
              : adjacent_in(path, m.topology().find(r.spec.from), m.topology().find(r.spec.to));
      if (crosses) return int(i);
    }
  }
  // A PAR whose unfinished branches are all stranded is stranded by the first one's fault.
  int fault = -1;
  for (const Process* branch : p.branches()) {
    if (branch->ended()) continue;
    const int f = stranding_fault(m, *branch);
    if (f < 0) return -1;
    if (fault < 0) fault = f;
  }
  return fault;
}

}  // namespace network
