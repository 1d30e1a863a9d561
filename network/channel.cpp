#include "network/channel.hpp"

#include <stdexcept>

#include "network/machine.hpp"
#include "network/process.hpp"
#include "t800/cost_model.hpp"
#include "t800/timing_table.hpp"

namespace network {

void LastUser::set(Process& p) {
  process = &p;
  incarnation = p.incarnation();
}

bool LastUser::is(const Process& p) const {
  return process == &p && incarnation == p.incarnation();
}

bool LastUser::ended() const {
  return process->incarnation() != incarnation || process->ended();
}

namespace {

// Rendezvous on one transputer: the first to arrive executes its instruction and deschedules; the
// second copies the message (2w+19) and wakes the first. The first marks the channel word as it
// starts its instruction, as the T800 does within the instruction: the other end arriving while it
// is still being charged finds it there (a reader taking a protocol's next item at once, say).
void internal_out(Process& p, Channel& c, t800::Message m) {
  if (c.waiting_writer) throw std::logic_error("two writers on channel " + c.name);
  if (c.waiting_reader) {
    p.communicate(m.bytes, true);
    *c.reader_destination = std::move(m);
    c.waiting_reader = nullptr;
    c.handed_over.notify_delta();
    return;
  }
  const std::int64_t bytes = m.bytes;
  c.slot = std::move(m);
  c.waiting_writer = &p;
  if (c.alting_reader) c.alting_reader->wake_alt();  // the ALT's guard is ready now
  p.communicate(bytes, false);
  p.deschedule();
  while (c.waiting_writer == &p) sc_core::wait(c.handed_over.get());
  p.reschedule();
}

t800::Message internal_in(Process& p, Channel& c) {
  if (c.waiting_reader) throw std::logic_error("two readers on channel " + c.name);
  if (c.waiting_writer) {
    p.communicate(c.slot.bytes, true);
    c.waiting_writer = nullptr;
    c.handed_over.notify_delta();
    return std::move(c.slot);
  }
  // The writer copies straight into the reader's variable: the slot may hold the writer's next
  // message before this process runs again.
  t800::Message received;
  c.waiting_reader = &p;
  c.reader_destination = &received;
  p.communicate(0, false);  // the reader's length is not known here until the message is (U)
  p.deschedule();
  while (c.waiting_reader == &p) sc_core::wait(c.handed_over.get());
  p.reschedule();
  return received;
}

}  // namespace

bool input_ready(const Channel& c) {
  switch (c.kind) {
    case Channel::Kind::internal:
      return c.waiting_writer != nullptr;
    case Channel::Kind::direct:
      return c.link->input_pending(1 - c.writer_end);
    case Channel::Kind::routed:
      return !c.mailbox.empty();
  }
  return false;
}

const char* to_string(Channel::Kind kind) {
  switch (kind) {
    case Channel::Kind::internal:
      return "internal";
    case Channel::Kind::direct:
      return "direct";
    case Channel::Kind::routed:
      return "routed";
  }
  return "?";
}

// On a link the instruction only loads the DMA engine and deschedules; the process is rescheduled
// when the engine has finished (docs/t800-timing.md sections 3 and 6).
void link_out(Process& p, t800::Link& link, int end, t800::Message m) {
  p.communicate(m.bytes, false);
  p.deschedule();
  link.transmit(end, std::move(m));
  p.reschedule();
}

t800::Message link_in(Process& p, t800::Link& link, int end) {
  p.communicate(0, false);
  p.deschedule();
  t800::Message m = link.receive(end);
  p.reschedule();
  return m;
}

// A router hands a message to its reader through a buffer, so a slow reader does not stall the link
// (U).
void deliver_to_mailbox(Process& router, Channel& c, t800::Message m) {
  router.communicate(m.bytes, true);
  c.mailbox.push_back(std::move(m));
  c.mail.notify_delta();
}

FirstHop routed_first_hop(Process& p, const Channel& c, t800::Message m, double deadline_us) {
  auto hop = p.machine().link_between(c.from, c.path.at(1));
  FirstHop first{hop->first, hop->second, {}};
  first.wrapped.bytes = m.bytes + kRouteHeaderBytes;
  first.wrapped.label = m.label;
  first.wrapped.payload = RoutedEnvelope{c.id, std::move(m), deadline_us};
  return first;
}

void send(Process& p, Channel& c, t800::Message m) {
  switch (c.kind) {
    case Channel::Kind::internal:
      return internal_out(p, c, std::move(m));
    case Channel::Kind::direct:
      return link_out(p, *c.link, c.writer_end, std::move(m));
    case Channel::Kind::routed: {
      FirstHop hop = routed_first_hop(p, c, std::move(m));
      return link_out(p, *hop.link, hop.end, std::move(hop.wrapped));
    }
  }
}

t800::Message receive(Process& p, Channel& c) {
  switch (c.kind) {
    case Channel::Kind::internal:
      return internal_in(p, c);
    case Channel::Kind::direct:
      return link_in(p, *c.link, 1 - c.writer_end);
    case Channel::Kind::routed: {
      p.communicate(0, false);
      if (c.mailbox.empty()) {
        p.deschedule();
        while (c.mailbox.empty()) sc_core::wait(c.mail.get());
        p.reschedule();
      }
      t800::Message m = std::move(c.mailbox.front());
      c.mailbox.pop_front();
      return m;
    }
  }
  throw std::logic_error("unknown channel kind");
}

}  // namespace network
