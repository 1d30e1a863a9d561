// The current simulated time, read from the running simulation context. sc_time_stamp() is an
// out-of-line library call; the CPU and link models ask for the time at every compute block and
// packet (some 15,000 times per RK4 step of the finest trajectory), so they read it inline.
#pragma once

#include <systemc>

namespace t800 {

inline const sc_core::sc_time& sim_now() {
  // No context yet (nothing of SystemC built): the library call makes one, as it always has.
  if (!sc_core::sc_curr_simcontext) return sc_core::sc_time_stamp();
  return sc_core::sc_curr_simcontext->time_stamp();
}

}  // namespace t800
