// A request from outside the simulation to stop the run and report what ran: SIGINT or SIGTERM,
// once the command has asked for them. The run stops at its next look (Machine::heartbeat, or
// between the slices of a limited run), writes its report as after a limit, and the command exits
// 128 + the signal's number as a shell would report it. A second signal ends the process at once,
// as the signal's default would.
#pragma once

namespace network {

// SIGINT and SIGTERM become stop requests from now on.
void catch_stop_signals();
bool stop_signals_caught();
// The signal that asked for a stop, 0 if none has.
int stop_requested();
// For tests: as if `signal` had arrived.
void request_stop(int signal);

}  // namespace network
