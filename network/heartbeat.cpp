// How a run that will not end is stopped: the wall-time limit and a stop request, read between the
// slices of a limited run (machine.cpp) and at heartbeats; a livelock, seen only at heartbeats,
// because while work is handed back and forth at one instant no slice ever ends.
#include <systemc>

#include "network/machine.hpp"
#include "network/stop_request.hpp"
#include "t800/sim_now.hpp"

namespace network {

void Machine::stop(Limit why) {
  if (limit_ != Limit::none) return;
  limit_ = why;
  if (why == Limit::interrupted) stop_signal_ = stop_requested();
  sc_core::sc_pause();  // sc_start returns at the end of this delta cycle
}

bool Machine::should_stop_now(double wall_s) {
  if (stop_requested()) {
    stop(Limit::interrupted);
  } else if (options_.max_wall_s > 0 && wall_s >= options_.max_wall_s) {
    stop(Limit::wall_time);
  }
  return limit_ != Limit::none;
}

void Machine::heartbeat() {
  if (limit_ != Limit::none) return;
  Heartbeats& h = heartbeats_;
  const double now_s = t800::sim_now().to_seconds();
  if (now_s != h.instant_s) {
    h.instant_s = now_s;
    h.at_this_instant = 0;
  }
  if (++h.at_this_instant >= options_.livelock_heartbeats) {
    stop(Limit::livelock);
    return;
  }
  if (++h.count % 1024) return;
  should_stop_now(
      std::chrono::duration<double>(std::chrono::steady_clock::now() - h.started).count());
}

}  // namespace network
