// Who waits for whom when a simulation ends with processes blocked. A process in an `in` waits for
// the channel's writer, one in an `out` for its reader (the process that last used the other end,
// or else any live process on the node at the other end), one in a PAR for its unfinished branches.
// Following these waits from the blocked processes either closes a cycle (the deadlock proper: A
// waits for B, which waits for A) or ends at a process that has ended or at nobody (a stage that
// never reads).
#pragma once

#include <string>
#include <vector>

namespace network {

class Machine;
class Process;

// For one blocked process, whom it waits for and how: "reader on P1 (in on channel c)", "nobody: no
// process on P3 inputs from channel c", "worker on P2, which has ended".
std::string waits_for(const Machine& machine, const Process& process);

// The first cycle of waits among the blocked processes, one step per process: "A on P0 waits to
// output on channel c for B on P1", ... back to A. Empty when the waits close no cycle.
std::vector<std::string> wait_cycle(const Machine& machine);

}  // namespace network
