// A process's communication on one end of a link, for the channels whose messages go by link
// (direct_link.hpp, store_and_forward.hpp) and the routers: the instruction only loads the DMA
// engine and deschedules; the process is rescheduled when the engine has finished
// (docs/t800-timing.md sections 3 and 6).
#pragma once

#include "t800/link.hpp"
#include "t800/message.hpp"

namespace network {

class Process;

void link_out(Process& p, t800::Link& link, int end, t800::Message m);
t800::Message link_in(Process& p, t800::Link& link, int end);

}  // namespace network
