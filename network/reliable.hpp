// occam's OutputOrFail.t and InputOrFail.t, as in INMOS's reliable-link library: a communication on
// a link that gives up at a deadline, resetting the link channel (resetch) so the process goes on
// and the program can recover (network/faults.hpp). Costed with the instructions the library runs:
// reading the timer for the deadline, and resetch when it gives up.
//
// A program calls them as its channel's Transport::send_or_fail and receive_or_fail; here is the
// library's part, round the communication each kind of channel does (network/transport/). A direct
// channel can give up either way; a routed channel's input can (its message waits in a mailbox),
// its output if the first hop has not taken it by the deadline -- and every router on the way
// forwards it with the same deadline (forward_or_fail), dropping it when its next hop has not
// taken it, so the sender's wait for an answer is what notices a halted processor past a router;
// an internal channel cannot fail and communicates as in / out.
#pragma once

#include <functional>
#include <optional>

#include <systemc>

#include "t800/message.hpp"

namespace t800 {
class Link;
}

namespace network {

class Process;
struct Channel;

// The writer's OutputOrFail.t on channel `c`, whose message goes on `link` from `end`; false: not
// taken by `deadline_us` (simulated us), the channel reset.
bool output_or_fail(Process& writer, Channel& c, t800::Link& link, int end, t800::Message m,
                    double deadline_us);
// The reader's InputOrFail.t on channel `c`: `arrival` waits for the message until the deadline;
// nullopt: nothing arrived by then, the channel reset.
using Arrival = std::function<std::optional<t800::Message>(const sc_core::sc_time& deadline)>;
std::optional<t800::Message> input_or_fail(Process& reader, Channel& c, double deadline_us,
                                           const Arrival& arrival);
// A router's OutputOrFail.t of a message it forwards on `link` from `end`; false: dropped.
bool forward_or_fail(Process& router, t800::Link& link, int end, t800::Message m,
                     double deadline_us);

}  // namespace network
