// Who waits for whom when a simulation ends with processes blocked. A process in an `in` waits for
// the channel's writer, one in an `out` for its reader (the process that last used the other end,
// or else any live process on the node at the other end), one in a PAR for its unfinished branches.
// Following these waits from the blocked processes either closes a cycle (the deadlock proper: A
// waits for B, which waits for A) or ends at a process that has ended or at nobody (a stage that
// never reads).
#pragma once

#include <map>
#include <string>
#include <vector>

namespace network {

class Machine;
class Process;

// The waits of a simulation that has ended, built once for its report: the processes in start
// order, and per node the live processes that could take or give a message there, so each question
// costs the processes concerned rather than a search of the whole network (a deadlocked network of
// 1024 transputers has thousands of blocked processes).
class WaitGraph {
 public:
  explicit WaitGraph(const Machine& machine);

  // For one blocked process, whom it waits for and how: "reader on P1 (in on channel c)", "nobody:
  // no process on P3 inputs from channel c", "worker on P2, which has ended".
  std::string waits_for(const Process& process) const;

  // The first cycle of waits among the blocked processes, one step per process: "A on P0 waits to
  // output on channel c for B on P1", ... back to A. Empty when the waits close no cycle.
  std::vector<std::string> cycle() const;

  const std::vector<const Process*>& in_start_order() const { return in_start_order_; }

 private:
  struct Waited {
    const Process* process;
    bool ended;  // a channel's last user may have ended
  };
  std::vector<Waited> waited_for(const Process& p) const;
  std::string who(const Process& p) const;

  const Machine& machine_;
  std::vector<const Process*> in_start_order_;
  // Per node, in start order: the processes neither ended, nor daemons, nor waiting for PAR
  // branches.
  std::map<int, std::vector<const Process*>> live_leaves_;
};

}  // namespace network
