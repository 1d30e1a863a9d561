// Channels between processes, as the occam program would have had them:
//  * internal: both ends on one transputer; a rendezvous, the second process to arrive copies
//  (2w+19 cycles);
//  * direct: the two ends on neighbouring transputers, alone on that link direction; the bytes move
//  by DMA;
//  * routed: anything else (not neighbours, or a link direction shared by several channels):
//  store-and-forward
//    through software router processes on every transputer the message enters (router.cpp).
#pragma once

#include <cstdint>
#include <list>
#include <string>
#include <vector>

#include <systemc>

#include "network/lazy_event.hpp"
#include "t800/link.hpp"
#include "t800/message.hpp"

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
  enum class Kind { internal, direct, routed };

  int id = 0;
  std::string name;
  int from = 0, to = 0;  // node indices (the host is Machine::kHost)
  Kind kind = Kind::internal;
  std::vector<int> path;  // nodes from `from` to `to`, for direct and routed channels
  // The processes that last output and input on it (or are trying to), for deadlock reports.
  LastUser last_writer, last_reader;

  // internal rendezvous; a reader in an ALT with this channel's guard enabled (occam's enbc)
  Process* alting_reader = nullptr;
  Process* waiting_reader = nullptr;
  t800::Message* reader_destination = nullptr;  // where the waiting reader's message goes
  Process* waiting_writer = nullptr;
  t800::Message slot;  // the waiting writer's message
  LazyEvent handed_over;
  // direct: the link and the writer's end of it
  t800::Link* link = nullptr;
  int writer_end = 0;
  // routed: messages delivered at `to` by its router, waiting for the reader (a list: an empty one
  // allocates nothing, t800/link.hpp)
  std::list<t800::Message> mailbox;
  LazyEvent mail;
};

// Header a router needs on every routed message: destination channel and length, two words (U).
constexpr std::int64_t kRouteHeaderBytes = 8;

struct RoutedEnvelope {
  int channel = 0;
  t800::Message inner;
  // Sent with OutputOrFail (network/reliable.hpp): every router on the way forwards it with the
  // same deadline and drops it when the next hop has not taken it by then, so a halted processor
  // past a router blocks neither the router nor the sender. -1: none (forwarded as out).
  double deadline_us = -1;
};

// A message for a routed channel as it leaves its writer: wrapped for the routers, with the route
// header's bytes, on the link to the first hop.
struct FirstHop {
  t800::Link* link = nullptr;
  int end = 0;
  t800::Message wrapped;
};
FirstHop routed_first_hop(Process& p, const Channel& c, t800::Message m, double deadline_us = -1);

void send(Process& p, Channel& c, t800::Message m);
t800::Message receive(Process& p, Channel& c);
// Whether an input on the channel would not wait (an ALT's guard is ready).
bool input_ready(const Channel& c);

// The pieces routers are built from.
void link_out(Process& p, t800::Link& link, int end, t800::Message m);
t800::Message link_in(Process& p, t800::Link& link, int end);
void deliver_to_mailbox(Process& router, Channel& c, t800::Message m);

const char* to_string(Channel::Kind kind);

}  // namespace network
