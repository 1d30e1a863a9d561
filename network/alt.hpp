// occam's ALT and PRI ALT (and the timer guards they may hold), on the simulated transputers: the
// process enables each guard, waits (altwt / taltwt) if none is ready, disables them, and takes
// the first ready guard in their order -- the T800 disables the guards in order and selects the
// first it finds ready, so ALT and PRI ALT choose alike (CWG: ALT is implemented as PRI ALT). Each
// step is costed with its instructions (alt, enbc, enbt, enbs, altwt, taltwt, disc, dist, diss,
// altend) from the processor's table; the input of the chosen guard is the caller's.
#pragma once

#include <cstdint>
#include <vector>

namespace network {

class Process;
struct Channel;

struct Guard {
  enum class Kind { input, timer, skip };
  Kind kind = Kind::skip;
  Channel* channel = nullptr;  // input
  std::int64_t after = 0;      // timer: ready once the process's clock is AFTER this value
  bool enabled = true;         // the guard's boolean pre-condition
};

// The index of the chosen guard. With no guard enabled the ALT waits for ever, as occam's does
// (a deadlock report names it).
int alternate(Process& p, const std::vector<Guard>& guards);

}  // namespace network
