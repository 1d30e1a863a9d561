// occam's OutputOrFail.t and InputOrFail.t, as in INMOS's reliable-link library: a communication on
// a link that gives up at a deadline, resetting the link channel (resetch) so the process goes on
// and the program can recover (network/faults.hpp). Costed with the instructions the library runs:
// reading the timer for the deadline, and resetch when it gives up.
//
// On a direct (link) channel both can give up; a routed channel's input can (its message waits in
// a mailbox), its output if the first hop has not taken it by the deadline -- and every router on
// the way forwards it with the same deadline (forward_or_fail), dropping it when its next hop has
// not taken it, so the sender's wait for an answer is what notices a halted processor past a
// router; an internal channel cannot fail (both ends are on one processor) and communicates as
// in / out.
#pragma once

#include <optional>

#include "t800/message.hpp"

namespace t800 {
class Link;
}

namespace network {

class Process;
struct Channel;

// false: not taken by `deadline_us` (simulated us), the channel reset.
bool out_or_fail(Process& p, Channel& c, t800::Message m, double deadline_us);
// nullopt: nothing arrived by `deadline_us`, the channel reset.
std::optional<t800::Message> in_or_fail(Process& p, Channel& c, double deadline_us);
// A router's OutputOrFail.t of a message it forwards on `link` from `end`; false: dropped.
bool forward_or_fail(Process& router, t800::Link& link, int end, t800::Message m,
                     double deadline_us);

}  // namespace network
