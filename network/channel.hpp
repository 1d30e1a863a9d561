// A channel between processes, as the occam program would have had it: its name, its ends, the
// nodes it crosses, and who used it last (for deadlock reports), common to every kind; how its
// messages travel is its transport (network/transport/transport.hpp).
//
// A process holds its channel from the declaration on (Machine::channel), but its kind is known
// only once every channel is declared, so the channel owns its transport rather than being one.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "network/transport/transport.hpp"

namespace network {

class Process;

// The process that last output (or input) on a channel, for deadlock reports. A PAR branch's
// record is used again by the next PAR's branch of its index (Process::start_branch), so the use is
// remembered with it: a record now running a later incarnation means the one that used the channel
// has ended.
struct LastUser {
  Process* process = nullptr;
  std::uint32_t incarnation = 0;
  void set(Process& p);
  bool is(const Process& p) const;  // p, in its present incarnation
  bool ended() const;
};

struct Channel {
  int id = 0;
  std::string name;
  int from = 0, to = 0;   // node indices (the host is Machine::kHost)
  std::vector<int> path;  // nodes from `from` to `to`, both included
  // The processes that last output and input on it (or are trying to), for deadlock reports.
  LastUser last_writer, last_reader;
  // Set by the machine when it prepares the run.
  std::unique_ptr<Transport> transport;
};

}  // namespace network
