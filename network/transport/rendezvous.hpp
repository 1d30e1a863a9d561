// An internal channel: both ends on one transputer. The first process to arrive executes its
// instruction and deschedules; the second copies the message (2w+19 cycles) and wakes the first.
// It cannot fail (both ends are on one processor): OutputOrFail and InputOrFail communicate as out
// and in.
#pragma once

#include "network/channel.hpp"
#include "network/lazy_event.hpp"

namespace network {

class Rendezvous final : public Transport {
 public:
  explicit Rendezvous(Channel& channel) : channel_(channel) {}

  void send(Process& writer, t800::Message m) override;
  t800::Message receive(Process& reader) override;
  bool send_or_fail(Process& writer, t800::Message m, double deadline_us) override;
  std::optional<t800::Message> receive_or_fail(Process& reader, double deadline_us) override;
  bool input_ready() const override { return waiting_writer_ != nullptr; }
  void watch(Process& alter, sc_core::sc_event_or_list& events) override;
  void unwatch(Process& alter) override;
  const char* kind_name() const override { return "internal"; }

 private:
  Channel& channel_;
  Process* alting_reader_ = nullptr;  // in an ALT with this channel's guard enabled (occam's enbc)
  Process* waiting_reader_ = nullptr;
  t800::Message* reader_destination_ = nullptr;  // where the waiting reader's message goes
  Process* waiting_writer_ = nullptr;
  t800::Message slot_;  // the waiting writer's message
  LazyEvent handed_over_;
};

}  // namespace network
