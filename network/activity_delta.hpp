// What a stretch of simulation did to a machine's accounting, and crediting it again later: a
// snapshot of every processor's and link direction's totals (and trace intervals), the delta since
// a snapshot, and a credit that adds a recorded delta as if it had just run. A trajectory uses it
// to reuse a step proven identical to one it simulated (workloads/trajectory,
// fidelity.reuse_steps).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <systemc>

#include "network/machine.hpp"

namespace network {

struct ProcessorDelta {
  double compute_us = 0, communicate_us = 0;
  double first_busy_us =
      -1;  // offset of the processor's first work ever, when it was in this stretch
  double last_busy_us =
      -1;  // offset of the last time it stopped working in this stretch (-1: idle)
  std::vector<t800::Interval> intervals;  // traces only; times from the stretch's start
};

struct LinkDelta {
  std::int64_t bytes = 0, messages = 0;
  double busy_us = 0;
  std::vector<t800::Interval> intervals;
};

struct ActivityDelta {
  sc_core::sc_time duration;
  std::vector<ProcessorDelta> processors;
  std::vector<LinkDelta> links;  // both directions of every link, in Machine::links() order
};

// The accounting at an instant.
struct ActivitySnapshot {
  sc_core::sc_time at;
  std::vector<double> compute_us, communicate_us, first_busy_us, last_busy_us;
  std::vector<std::size_t> processor_intervals;
  std::vector<std::int64_t> bytes, messages;
  std::vector<double> link_busy_us;
  std::vector<std::size_t> link_intervals;
  std::int64_t clock = 0;  // clock_events() then
};

ActivitySnapshot snapshot(Machine& m);
// From `before` to now.
ActivityDelta delta_since(Machine& m, const ActivitySnapshot& before);
// Adds a recorded delta to the accounting as if it had just run from `start`.
void credit(Machine& m, const ActivityDelta& d, const sc_core::sc_time& start);
// Replays a recorded stretch in `p`, the process that drove it: p lets the stretch's duration
// pass, without simulating it (every other process stays as it is, blocked), and the delta is
// credited from when it began. The simulator's service to step reuse (workloads/trajectory/
// step_reuse.hpp), not part of the SDK: a program may not skip simulated time, only the simulator
// may, for a stretch it has proven it would simulate identically.
void replay(Process& p, const ActivityDelta& d);
// Every CPU's clock-dependent slices and timeslice ends, summed: unchanged over a stretch, the
// stretch did not depend on where the timeslice clock's ticks fell
// (t800::CpuStatistics::clock_dependent).
std::int64_t clock_events(Machine& m);
// Empty when nothing is under way: every processor idle (no compute, no link transfer for it) and
// every link quiet, so what happens from here on does not depend on the past; else what was under
// way.
std::string unquiet(Machine& m);

}  // namespace network
