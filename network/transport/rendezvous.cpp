#include "network/transport/rendezvous.hpp"

#include <stdexcept>

#include "network/process.hpp"

namespace network {

// The first to arrive marks the channel word as it starts its instruction, as the T800 does within
// the instruction: the other end arriving while it is still being charged finds it there (a reader
// taking a protocol's next item at once, say).
void Rendezvous::send(Process& writer, t800::Message m) {
  if (waiting_writer_) throw std::logic_error("two writers on channel " + channel_.name);
  if (waiting_reader_) {
    writer.communicate(m.bytes, true);
    *reader_destination_ = std::move(m);
    waiting_reader_ = nullptr;
    handed_over_.notify_delta();
    return;
  }
  const std::int64_t bytes = m.bytes;
  slot_ = std::move(m);
  waiting_writer_ = &writer;
  if (alting_reader_) alting_reader_->wake_alt();  // the ALT's guard is ready now
  writer.communicate(bytes, false);
  writer.deschedule();
  while (waiting_writer_ == &writer) sc_core::wait(handed_over_.get());
  writer.reschedule();
}

t800::Message Rendezvous::receive(Process& reader) {
  if (waiting_reader_) throw std::logic_error("two readers on channel " + channel_.name);
  if (waiting_writer_) {
    reader.communicate(slot_.bytes, true);
    waiting_writer_ = nullptr;
    handed_over_.notify_delta();
    return std::move(slot_);
  }
  // The writer copies straight into the reader's variable: the slot may hold the writer's next
  // message before this process runs again.
  t800::Message received;
  waiting_reader_ = &reader;
  reader_destination_ = &received;
  reader.communicate(0, false);  // the reader's length is not known here until the message is (U)
  reader.deschedule();
  while (waiting_reader_ == &reader) sc_core::wait(handed_over_.get());
  reader.reschedule();
  return received;
}

bool Rendezvous::send_or_fail(Process& writer, t800::Message m, double /*deadline_us*/) {
  writer.out(channel_, std::move(m));
  return true;
}

std::optional<t800::Message> Rendezvous::receive_or_fail(Process& reader, double /*deadline_us*/) {
  return reader.in(channel_);
}

// A writer arriving wakes the ALT: there is no event of the channel's own to wait on.
void Rendezvous::watch(Process& alter, sc_core::sc_event_or_list& /*events*/) {
  alting_reader_ = &alter;
}

void Rendezvous::unwatch(Process& alter) {
  if (alting_reader_ == &alter) alting_reader_ = nullptr;
}

}  // namespace network
