#include "network/alt.hpp"

#include <algorithm>
#include <limits>

#include "network/channel.hpp"
#include "network/machine.hpp"
#include "network/process.hpp"

namespace network {

namespace {

using t800::isa::Op;

const t800::isa::MemoryRef kWorkspace{t800::isa::Region::workspace, -1};

bool ready(Process& p, const Guard& g) {
  if (!g.enabled) return false;
  switch (g.kind) {
    case Guard::Kind::input:
      return g.channel->transport->input_ready();
    case Guard::Kind::timer:
      return p.clock() > g.after;
    case Guard::Kind::skip:
      return true;
  }
  return false;
}

// The code occam compiles an ALT's enabling to (CWG): alt (talt with a timer guard), then per
// guard its channel or time, its pre-condition, and enbc / enbt / enbs; altwt or taltwt, which
// deschedules when nothing is ready.
t800::isa::Sequence enabling(Process& p, const std::vector<Guard>& guards, bool waiting) {
  const bool timed = std::any_of(guards.begin(), guards.end(),
                                 [](const Guard& g) { return g.kind == Guard::Kind::timer; });
  t800::isa::Sequence code{{timed ? Op::talt : Op::alt, 0, 0, false, kWorkspace, "ALT"}};
  for (const Guard& g : guards) {
    const bool is_ready = ready(p, g);
    switch (g.kind) {
      case Guard::Kind::input:
        code.push_back({Op::ldl, 1, 0, false, kWorkspace, "channel"});
        code.push_back({Op::ldc, 1, 0, false, {}, "guard"});
        code.push_back({Op::enbc, 0, is_ready, false, kWorkspace, "enable channel"});
        break;
      case Guard::Kind::timer:
        code.push_back({Op::ldl, 1, 0, false, kWorkspace, "time"});
        code.push_back({Op::ldc, 1, 0, false, {}, "guard"});
        code.push_back({Op::enbt, 0, 0, false, kWorkspace, "enable timer"});
        break;
      case Guard::Kind::skip:
        code.push_back({Op::ldc, 1, 0, false, {}, "guard"});
        code.push_back({Op::enbs, 0, 0, false, kWorkspace, "enable skip"});
        break;
    }
  }
  code.push_back({timed ? Op::taltwt : Op::altwt, 0, waiting, false, kWorkspace, "ALT wait"});
  return code;
}

// Disabling, in order (disc / dist / diss with the branch's offset), then altend.
t800::isa::Sequence disabling(const std::vector<Guard>& guards) {
  t800::isa::Sequence code;
  for (const Guard& g : guards) {
    if (g.kind != Guard::Kind::skip) code.push_back({Op::ldl, 1, 0, false, kWorkspace, ""});
    code.push_back({Op::ldc, 1, 0, false, {}, "guard"});
    code.push_back({Op::ldc, 8, 0, false, {}, "branch offset"});
    const Op op = g.kind == Guard::Kind::input   ? Op::disc
                  : g.kind == Guard::Kind::timer ? Op::dist
                                                 : Op::diss;
    code.push_back({op, 0, 0, false, kWorkspace, "disable"});
  }
  code.push_back({Op::altend, 0, 0, false, kWorkspace, "ALT end"});
  return code;
}

int first_ready(Process& p, const std::vector<Guard>& guards) {
  for (std::size_t i = 0; i < guards.size(); ++i)
    if (ready(p, guards[i])) return int(i);
  return -1;
}

// Blocks until a guard is ready: woken by what each enabled input guard's channel watches for
// (Transport::watch), and timing out at the earliest timer guard.
void wait_for_a_guard(Process& p, const std::vector<Guard>& guards) {
  p.set_status("in an ALT");
  p.deschedule();
  while (first_ready(p, guards) < 0) {
    sc_core::sc_event_or_list events;
    events |= p.alt_event();
    std::int64_t earliest = std::numeric_limits<std::int64_t>::max();
    for (const Guard& g : guards) {
      if (!g.enabled) continue;
      if (g.kind == Guard::Kind::timer) earliest = std::min(earliest, g.after);
      if (g.kind == Guard::Kind::input) g.channel->transport->watch(p, events);
    }
    if (earliest == std::numeric_limits<std::int64_t>::max())
      sc_core::wait(events);
    else
      sc_core::wait(p.time_after(earliest) - t800::sim_now(), events);
  }
  for (const Guard& g : guards)
    if (g.kind == Guard::Kind::input) g.channel->transport->unwatch(p);
  p.reschedule();
  p.set_status("running");
}

}  // namespace

int alternate(Process& p, const std::vector<Guard>& guards) {
  const bool waits = first_ready(p, guards) < 0;
  p.run_instructions(enabling(p, guards, waits));
  if (waits) wait_for_a_guard(p, guards);
  p.run_instructions(disabling(guards));
  return first_ready(p, guards);
}

}  // namespace network
