#include "tools/trace_vcd.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <stdexcept>
#include <tuple>

#include <systemc>

namespace tools {

namespace {

// One change of a traced variable: at `ps`, variable `index` takes `value`.
struct Change {
  std::int64_t ps;
  int order;  // ends (0) before starts (1) at one instant, so back-to-back intervals stay high
  std::size_t index;
  unsigned value;
  bool operator<(const Change& o) const {
    return std::tie(ps, order, index) < std::tie(o.ps, o.order, o.index);
  }
};

unsigned state_code(const TraceRow& r) {
  if (r.kind == "link") return 1;
  if (r.state == "compute") return 1;
  if (r.state == "communicate") return 2;
  return 0;
}

class Replay : public sc_core::sc_module {
 public:
  Replay(const sc_core::sc_module_name& name, const std::vector<TraceRow>& rows) : sc_module(name) {
    std::map<std::string, std::size_t> index;
    for (const TraceRow& r : rows) {
      const std::string key = r.kind + "/" + r.name;
      if (!index.count(key)) {
        index[key] = names_.size();
        names_.push_back((r.kind == "processor" ? "processors." : "links.") + vcd_name(r.name));
        widths_.push_back(r.kind == "processor" ? 2 : 1);
      }
      const std::size_t i = index[key];
      changes_.push_back({std::llround(r.start_us * 1e6), 1, i, state_code(r)});
      changes_.push_back({std::llround(r.end_us * 1e6), 0, i, 0});
    }
    std::sort(changes_.begin(), changes_.end());
    values_.assign(names_.size(), 0);
    busy_ = std::make_unique<bool[]>(names_.size());
    SC_THREAD(run);
  }

  // Before sc_start: SystemC's VCD writer samples these variables at the end of every time step.
  void trace(sc_core::sc_trace_file* tf) {
    for (std::size_t i = 0; i < names_.size(); ++i)
      if (widths_[i] == 2)
        sc_core::sc_trace(tf, values_[i], names_[i], 2);
      else
        sc_core::sc_trace(tf, busy_[i], names_[i]);
  }

 private:
  SC_HAS_PROCESS(Replay);

  void run() {
    std::int64_t now = 0;
    for (const Change& c : changes_) {
      if (c.ps > now) sc_core::wait(sc_core::sc_time(double(c.ps - now), sc_core::SC_PS));
      now = c.ps;
      values_[c.index] = c.value;
      busy_[c.index] = c.value != 0;
    }
    // The writer records a time step's values when the next one begins: one more picosecond keeps
    // the last.
    sc_core::wait(sc_core::sc_time(1, sc_core::SC_PS));
  }

  std::vector<std::string> names_;
  std::vector<int> widths_;
  std::vector<Change> changes_;
  std::vector<unsigned> values_;
  std::unique_ptr<bool[]> busy_;
};

}  // namespace

std::string vcd_name(const std::string& name) {
  std::string out;
  for (std::size_t i = 0; i < name.size(); ++i) {
    if (name.compare(i, 2, "->") == 0) {
      out += "_to_";
      ++i;
    } else if (std::isalnum(static_cast<unsigned char>(name[i]))) {
      out += name[i];
    } else if (!out.empty() && out.back() != '_') {
      out += '_';
    }
  }
  while (!out.empty() && out.back() == '_') out.pop_back();
  return out.empty() ? "unnamed" : out;
}

void write_vcd(const std::vector<TraceRow>& rows, const std::string& path) {
  // SystemC appends ".vcd" to the name it is given.
  const bool has_extension = path.size() > 4 && path.compare(path.size() - 4, 4, ".vcd") == 0;
  const std::string base = has_extension ? path.substr(0, path.size() - 4) : path;
  sc_core::sc_report_handler::set_actions(sc_core::SC_INFO,
                                          sc_core::SC_DO_NOTHING);  // timescale notes
  Replay replay("trace", rows);
  sc_core::sc_trace_file* tf = sc_core::sc_create_vcd_trace_file(base.c_str());
  tf->set_time_unit(1, sc_core::SC_PS);  // the simulator's resolution: every recorded time is exact
  replay.trace(tf);
  sc_core::sc_start();
  sc_core::sc_close_vcd_trace_file(tf);
  if (!has_extension && std::rename((base + ".vcd").c_str(), path.c_str()) != 0)
    throw std::invalid_argument("cannot write " + path);
}

}  // namespace tools
