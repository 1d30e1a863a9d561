// How a channel's messages travel between its ends (network/channel.hpp), one implementation per
// kind of channel:
//  * internal (rendezvous.hpp): both ends on one transputer; the second process to arrive copies;
//  * direct (direct_link.hpp): neighbours alone on a link direction; DMA moves the bytes;
//  * routed (store_and_forward.hpp): any other pair; software routers on the way store and forward.
// The machine chooses one for each channel once every channel is declared (Machine::prepare):
// whether a channel has a link direction to itself depends on all the others.
#pragma once

#include <optional>

#include <systemc>

#include "t800/message.hpp"

namespace network {

class Process;

class Transport {
 public:
  virtual ~Transport() = default;

  // occam's `!` and `?` (Process::out, in): the writer returns when the message has been taken, the
  // reader with the message.
  virtual void send(Process& writer, t800::Message m) = 0;
  virtual t800::Message receive(Process& reader) = 0;
  // OutputOrFail.t and InputOrFail.t (network/reliable.hpp): false, or nullopt, when given up at
  // `deadline_us` (simulated us), the channel reset.
  virtual bool send_or_fail(Process& writer, t800::Message m, double deadline_us) = 0;
  virtual std::optional<t800::Message> receive_or_fail(Process& reader, double deadline_us) = 0;

  // For an ALT (network/alt.hpp): whether an input would not wait (its guard is ready); and, while
  // `alter` waits with the guard enabled, what wakes it when the guard may have become ready:
  // watch adds the events to wait on, or has a writer's arrival wake it (Process::wake_alt) until
  // unwatch.
  virtual bool input_ready() const = 0;
  virtual void watch(Process& alter, sc_core::sc_event_or_list& events) = 0;
  virtual void unwatch(Process& alter) = 0;

  // "internal", "direct" or "routed", for reports.
  virtual const char* kind_name() const = 0;
};

}  // namespace network
