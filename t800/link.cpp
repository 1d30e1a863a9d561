#include "t800/link.hpp"

#include <algorithm>
#include <functional>
#include <string>

#include "t800/link_timing.hpp"
#include "t800/payload_bytes.hpp"

namespace t800 {

using sc_core::SC_NS;
using sc_core::sc_time;
using sc_core::SC_ZERO_TIME;

namespace {

// "wire0", "detect1", ...: unique within the link.
std::string role(const char* what, int d) {
  return what + std::to_string(d);
}

void spawn_method(const std::function<void()>& body, sc_core::sc_event& trigger, const char* what,
                  int d) {
  sc_core::sc_spawn_options options;
  options.spawn_method();
  options.dont_initialize();
  options.set_sensitivity(&trigger);
  sc_core::sc_spawn(body, role(what, d).c_str(), &options);
}

}  // namespace

Link::Link(const sc_core::sc_module_name& name, const LinkConfig& config, ProcessorActivity* end0,
           ProcessorActivity* end1, LinkFidelity fidelity)
    : sc_module(name), config_(config), fidelity_(fidelity), end_{end0, end1} {
  const LinkTiming t(config);
  bit_ = sc_time(t.bit_ns, SC_NS);
  data_packet_ = sc_time(t.data_packet_ns, SC_NS);
  ack_packet_ = sc_time(t.ack_packet_ns, SC_NS);
  detect_delay_ = sc_time(t.ack_detect_ns, SC_NS);
  process_delay_ = sc_time(t.ack_process_ns, SC_NS);
  // The same sum the packet level makes, in the kernel's time units, so both levels agree to the
  // tick.
  byte_period_ = std::max(data_packet_, detect_delay_ + ack_packet_ + process_delay_);
  tick_ = sc_core::sc_get_time_resolution();

  for (int d = 0; d < 2; ++d) {
    dir_[d].activity.merge_gaps_below(
        data_packet_);  // a trace shows a streaming message as one interval
    spawn_method([this, d] { on_wire(d); }, dir_[d].wire_wake, "wire", d);
    spawn_method([this, d] { on_detect(d); }, dir_[d].detect_event, "detect", d);
    spawn_method([this, d] { on_ack_processed(d); }, dir_[d].process_event, "ackproc", d);
    spawn_method([this, d] { on_closed_form(d); }, dir_[d].closed_form.milestone, "closedform", d);
  }
}

Link::ClosedForm::ClosedForm(int d) : milestone(role("milestone", d).c_str()) {}

Link::Direction::Direction(int d)
    : closed_form(d),
      sent_event(role("sent", d).c_str()),
      submitted_event(role("submitted", d).c_str()),
      delivered_event(role("delivered", d).c_str()),
      wire_wake(role("wire_wake", d).c_str()),
      detect_event(role("detect_event", d).c_str()),
      process_event(role("process_event", d).c_str()) {}

std::int64_t Link::submit(int from, Message message) {
  Direction& d = dir_[from];
  const std::int64_t ticket = ++d.submitted;
  d.queue.push_back(std::move(message));
  d.wire_wake.notify(SC_ZERO_TIME);
  d.submitted_event.notify(SC_ZERO_TIME);
  return ticket;
}

void Link::transmit(int from, Message message) {
  Direction& d = dir_[from];
  const std::int64_t ticket = submit(from, std::move(message));
  while (d.completed < ticket) sc_core::wait(d.sent_event);
}

bool Link::quiet() const {
  for (const Direction& d : dir_)
    if (!d.queue.empty() || !d.may_send || d.receiving || d.ack_owed || d.acks_pending > 0 ||
        d.accepted_before_detect || !d.delivered.empty() || d.in_flight.active ||
        d.closed_form.active)
      return false;
  return true;
}

Message Link::receive(int to, std::int64_t at_most) {
  // Messages to end `to` travel in direction 1 - to.
  const int di = 1 - to;
  Direction& d = dir_[di];
  arm_input(di, std::max<std::int64_t>(at_most, 1));
  while (d.delivered.empty()) sc_core::wait(d.delivered_event);
  return take_delivered(di);
}

Message Link::take_delivered(int di) {
  Direction& d = dir_[di];
  Piece piece = std::move(d.delivered.front());
  d.delivered.pop_front();
  if (piece.last) ++d.taken;
  return std::move(piece.message);
}

void Link::arm_input(int di, std::int64_t at_most) {
  Direction& d = dir_[di];
  d.armed = true;
  d.want = at_most;
  if (at_most != kWholeMessage) d.taken_in_pieces = true;
  // A closed form acknowledges every byte of its message: an input that takes only some of them
  // is served at the packet level, which holds the sender after the last it takes.
  if (d.closed_form.active && !d.closed_form.armed && at_most < d.closed_form.bytes) hand_over(di);
  if (d.receiving) count_receiver(di);
  if (d.closed_form.active) {
    if (!d.closed_form.armed) {  // the schedule is known from now on
      d.closed_form.armed = true;
      d.closed_form.armed_at = sim_now();
      d.closed_form.milestone.notify(SC_ZERO_TIME);
    }
  } else {
    if (d.ack_owed) {  // a byte is waiting in the link's buffer: acknowledge it now
      d.ack_owed = false;
      queue_ack(di);
    }
    if (input_satisfied(di)) complete_receive(di);
  }
}

bool Link::input_pending(int to) const {
  const Direction& d = dir_[1 - to];
  return d.submitted > d.taken;
}

// n adds of one byte at strictly increasing times, the last at `last`, all but the last before the
// current instant: the earlier ones change only the total (the last sets the latest instant).
void Link::DmaCount::add_increasing(std::int64_t n, const sc_time& last) {
  total += n - 1;
  add(1, last);
}

void Link::DmaCount::add(std::int64_t n, const sc_time& at, bool counted_first) {
  if (!counted_first && queried && at == query_at && at == sim_now()) late += n;
  total += n;
  if (at > latest_at) {
    latest_at = at;
    latest = n;
  } else if (at == latest_at) {
    latest += n;
  }
}

std::int64_t Link::dma_bytes(int e, const sc_time& now, bool including_now) const {
  const Direction& out = dir_[e];     // its data leaves through end e
  const Direction& in = dir_[1 - e];  // its data arrives at end e
  if (including_now) {
    out.dma_sent.query(now);
    in.dma_received.query(now);
  }
  std::int64_t n = including_now ? out.dma_sent.total + in.dma_received.total
                                 : out.dma_sent.before(now) + in.dma_received.before(now);
  if (now == SC_ZERO_TIME && !including_now) return n;
  // Closed forms and a settled packet's byte: the bytes started (sent) or arrived (received) by
  // now, or strictly before now.
  const sc_time until = including_now ? now : now - tick_;
  if (in.arrival_pending && in.arrival_at <= until) ++n;
  if (out.closed_form.active && !out.closed_form.sender_done)
    n += bytes_started_by(out.closed_form, out.closed_form.bytes, until);
  if (in.closed_form.active && !in.closed_form.delivered && until >= data_packet_)
    n += bytes_started_by(in.closed_form, in.closed_form.bytes, until - data_packet_);
  return n;
}

std::int64_t Link::dma_before_less_late(int e, const sc_time& now, const sc_time& t0) const {
  return dma_bytes(e, now, false) - dir_[e].dma_sent.late_at(t0) -
         dir_[1 - e].dma_received.late_at(t0);
}

// ---- packet level ----

void Link::on_wire(int w) {
  const Direction& own = dir_[w];
  if (own.carrying != WirePacket::none && sim_now() < own.wire_busy_until) {
    // a packet started by start_at_once, and a wire_wake came before its end
    return sc_core::next_trigger(own.wire_busy_until - sim_now());
  }
  finish_packet(w);
  if (start_packet(w)) sc_core::next_trigger(dir_[w].wire_busy_until - sim_now());
  // else: asleep until its wire_wake (the method's static sensitivity)
}

// The packet the wire was carrying has ended (the method was woken by its end).
void Link::finish_packet(int w) {
  Direction& own = dir_[w];
  const WirePacket packet = own.carrying;
  own.carrying = WirePacket::none;
  switch (packet) {
    case WirePacket::none:
    case WirePacket::data_settled:
    case WirePacket::ack_settled:
      return;
    case WirePacket::data:
      return finish_data_packet(w, own.packet_start);
    case WirePacket::ack:
      return finish_ack_packet(w, own.packet_start);
    case WirePacket::in_flight:
      return finish_in_flight(w);
  }
}

// What the wire does next, in order of precedence; true when it now carries a packet.
bool Link::start_packet(int w) {
  Direction& own = dir_[w];
  for (;;) {
    if (own.wire_stop.now()) {  // a dead wire carries nothing more
      if (!own.queue.empty() && own.wire_stop.hit)
        own.wire_stop.hit("message '" + own.queue.front().label + "' not sent");
      return false;
    }
    const bool data_waiting = !own.queue.empty() && own.may_send && !own.closed_form.active &&
                              own.sent < own.queue.front().bytes;
    if (own.in_flight.active) {
      const InFlight& packet = own.in_flight;
      const sc_time end = packet.start + (packet.data ? data_packet_ : ack_packet_);
      if (end > sim_now()) {
        carry(w, WirePacket::in_flight, packet.start, end - packet.start);
        return true;
      }
      finish_in_flight(w);
    } else if (own.acks_pending > 0) {
      return send_ack_packet(w);
    } else if (data_waiting && own.sent == 0 && dir_[1 - w].closed_form.active &&
               fidelity_ != LinkFidelity::message) {
      hand_over(1 - w);  // this direction starts: the other's closed form no longer holds
    } else if (data_waiting && own.sent == 0 && closed_form_allowed(w)) {
      start_closed_form(w);
    } else if (data_waiting) {
      return send_data_packet(w);
    } else {
      return false;
    }
  }
}

// The wire's method, woken by wire_wake, would decide in the next delta at this instant. Deciding
// now gives the same packet at the same time when nothing can change the decision in between: no
// fault (a stop, a halted end), no resetch by a deadline, no packet handed over. The method is then
// woken at the packet's end by a timed wire_wake (or earlier by another, and sleeps on).
bool Link::start_at_once(int w) {
  Direction& own = dir_[w];
  if ((own.carrying == WirePacket::data_settled || own.carrying == WirePacket::ack_settled) &&
      sim_now() >= own.wire_busy_until)
    own.carrying = WirePacket::none;  // it has ended: nothing was left to do at its end
  if (faulted_ || deadline_waits_ > 0 || own.carrying != WirePacket::none || own.in_flight.active ||
      dir_[1 - w].in_flight.active)
    return false;
  if (start_packet(w)) own.wire_wake.notify(own.wire_busy_until - sim_now());
  return true;
}

void Link::carry(int w, WirePacket packet, const sc_time& start, const sc_time& length) {
  Direction& own = dir_[w];
  own.carrying = packet;
  own.packet_start = start;
  own.wire_busy_until = start + length;
}

// A data packet's end is an event only where another party can act on it; see
// data_end_settled_now.
bool Link::send_data_packet(int di) {
  Direction& d = dir_[di];
  const sc_time start = sim_now();
  settle_arrival(di);
  if (d.sent == 0) {  // the first byte of a message: both ends are now communicating
    d.receiving = true;
    begin_incoming(di);
    d.received = 0;
    if (end(di)) end(di)->transfer_begin();
    if (d.armed) count_receiver(di);
  }
  ++d.sent;
  d.dma_sent.add(1, start);
  d.may_send = false;
  apply_byte_fault(di);
  if (!d.byte_lost) d.detect_event.notify(detect_delay_);
  if (!data_end_settled_now(di)) {
    carry(di, WirePacket::data, start, data_packet_);
    return true;
  }
  carry(di, WirePacket::data_settled, start, data_packet_);
  d.activity.packet(start, data_packet_, true);  // nothing else is recorded on this wire meanwhile
  d.arrival_pending = true;
  d.arrival_at = start + data_packet_;
  return false;
}

// The arrival of a byte that is not its message's last changes only counts: the bytes received
// (read at the last) and the DMA cycles (dma_bytes counts a pending arrival from its time). Not
// with a fault (a byte may be lost), a deadline (resetch), a hand-over, or a T414 (its
// acknowledge depends on the input being armed when the byte has arrived), nor where inputs take
// messages piece by piece (the byte may be a piece's last).
bool Link::data_end_settled_now(int di) const {
  const Direction& d = dir_[di];
  const Direction& other = dir_[1 - di];
  return !faulted_ && deadline_waits_ == 0 && detect_delay_ < data_packet_ &&
         d.sent < d.incoming.bytes && !d.taken_in_pieces && !d.closed_form.active &&
         !other.closed_form.active && !d.in_flight.active && !other.in_flight.active;
}

// The byte of a settled data packet arrives: what finish_data_packet would have done at its end,
// which was at the start of that instant, before anything else then.
void Link::settle_arrival(int di) {
  Direction& d = dir_[di];
  if (!d.arrival_pending) return;
  d.arrival_pending = false;
  ++d.received;
  d.dma_received.add(1, d.arrival_at, true);
}

void Link::finish_data_packet(int di, const sc_time& start) {
  dir_[di].activity.packet(start, data_packet_, true);
  if (dir_[di].byte_lost) {
    dir_[di].byte_lost = false;
    return;
  }
  if (lost_on_wire(di, start, data_packet_) || deaf_at(di)) return;
  on_byte_arrived(di);
}

// An acknowledge's end is an event only where another party can act on it. It is settled when it
// starts -- recorded, counted, and its processing scheduled -- when that end changes nothing
// anyone else can see: it is not the message's last (whose end lets the sender go on), and the
// wire's own direction is silent (nothing of its own recorded or labelled meanwhile). The wire
// sleeps on; a wire_wake before the end finds it busy until then.
bool Link::send_ack_packet(int w) {
  --dir_[w].acks_pending;
  const sc_time start = sim_now();
  if (!ack_end_settled_now(w)) {
    carry(w, WirePacket::ack, start, ack_packet_);
    return true;
  }
  carry(w, WirePacket::ack_settled, start, ack_packet_);
  dir_[w].activity.packet(start, ack_packet_, false);
  Direction& d = dir_[1 - w];
  ++d.acked;
  d.process_event.notify(ack_packet_ + process_delay_);
  return false;
}

bool Link::ack_end_settled_now(int w) const {
  const Direction& own = dir_[w];
  const Direction& d = dir_[1 - w];
  return !faulted_ && deadline_waits_ == 0 && own.queue.empty() && !own.closed_form.active &&
         !d.closed_form.active && !own.in_flight.active && !d.in_flight.active &&
         !d.queue.empty() && d.acked + 1 < d.queue.front().bytes;
}

void Link::finish_ack_packet(int w, const sc_time& start) {
  dir_[w].activity.packet(start, ack_packet_, false);
  const int acked_direction = 1 - w;
  if (lost_on_wire(w, start, ack_packet_) || deaf_at(w)) return;
  Direction& d = dir_[acked_direction];
  if (d.queue.empty()) return;  // its message was abandoned (reset_output)
  ++d.acked;
  if (d.acked ==
      d.queue.front().bytes) {  // the whole message is acknowledged: the sender may go on
    d.activity.message_done(d.acked, d.queue.front().label);
    take_payload(acked_direction);
    d.queue.pop_front();
    d.sent = d.acked = 0;
    ++d.completed;
    d.sent_event.notify(SC_ZERO_TIME);
    if (end(acked_direction)) end(acked_direction)->transfer_end();
  }
  d.process_event.notify(process_delay_);
}

// A packet that was on the wire when its message was handed over: it ends as if sent at this level.
void Link::finish_in_flight(int w) {
  Direction& own = dir_[w];
  const InFlight packet = own.in_flight;
  own.in_flight.active = false;
  if (!packet.data) return finish_ack_packet(w, packet.start);
  if (!packet.recorded) own.activity.packet(packet.start, data_packet_, true);
  on_byte_arrived(w);
}

void Link::on_detect(int di) {
  Direction& d = dir_[di];
  if (deaf_at(di)) return;  // a halted or dead receiver acknowledges nothing
  if (d.armed || d.accepted_before_detect) {
    d.accepted_before_detect = false;
    queue_ack(di);
  } else {
    d.ack_owed = true;  // flow control: no input waiting, so no acknowledge yet
  }
}

// An acknowledge goes before its wire's own data, so starting it at once is the decision the wire
// would make in the next delta.
void Link::queue_ack(int di) {
  Direction& reverse = dir_[1 - di];
  ++reverse.acks_pending;
  if (!start_at_once(1 - di)) reverse.wire_wake.notify(SC_ZERO_TIME);
}

// The next byte of the message may go. Its wire also carries the other direction's acknowledges,
// which go first: it is sent at once only when no acknowledge can be queued at this instant (the
// other direction receives nothing, and a T800's acknowledge is detected before its byte has
// arrived) and it is a byte of the same message (a new one may start in closed form).
void Link::on_ack_processed(int di) {
  Direction& d = dir_[di];
  if (d.wire_stop.now()) return;
  d.may_send = true;
  const Direction& other = dir_[1 - di];
  const bool no_ack_can_come = !other.receiving && !other.closed_form.active &&
                               !d.closed_form.active && detect_delay_ < data_packet_;
  if (!(d.sent > 0 && no_ack_can_come && start_at_once(di))) d.wire_wake.notify(SC_ZERO_TIME);
}

void Link::on_byte_arrived(int di) {
  Direction& d = dir_[di];
  settle_arrival(di);
  ++d.received;
  d.dma_received.add(1, sim_now());
  // A T414 acknowledges after the whole packet: a byte taken by a waiting input is owed its
  // acknowledge even if that input completes (and disarms) before the acknowledge goes out.
  if (d.armed && config_.protocol == LinkProtocol::t414) d.accepted_before_detect = true;
  if (d.armed && input_satisfied(di)) complete_receive(di);
}

// The receiver's copy of the message now starting: its length, label and route header. Its payload
// stays in the sender's queue -- copying it would cost an allocation or two per message -- until
// the sender is done with the message or the receiver has it, whichever comes first (take_payload).
void Link::begin_incoming(int di) {
  Direction& d = dir_[di];
  const Message& m = d.queue.front();
  d.incoming.bytes = m.bytes;
  d.incoming.label = m.label;
  d.incoming.route = m.route;
  d.incoming.payload.reset();
  d.payload_with_sender = true;
}

// Called before the sender's message leaves its queue, and when the receiver takes it.
void Link::take_payload(int di) {
  Direction& d = dir_[di];
  if (!d.payload_with_sender) return;
  d.incoming.payload = std::move(d.queue.front().payload);
  d.payload_with_sender = false;
}

// The armed input has what it asked for: the rest of the message, or its `want` bytes.
bool Link::input_satisfied(int di) const {
  const Direction& d = dir_[di];
  return d.receiving && (d.received == d.incoming.bytes || d.received - d.given >= d.want);
}

void Link::complete_receive(int di) {
  Direction& d = dir_[di];
  take_payload(di);
  Piece piece;
  piece.last = d.received == d.incoming.bytes;
  if (piece.last) {
    piece.message = std::move(d.incoming);
    piece.message.bytes -= d.given;
    if (d.given > 0) piece.message.payload.reset();  // the first piece had it
    d.receiving = false;
    d.received = d.given = 0;
  } else {
    piece.message.bytes = d.received - d.given;
    piece.message.label = d.incoming.label;
    piece.message.route = d.incoming.route;
    if (d.given == 0) piece.message.payload = d.incoming.payload;
    d.given = d.received;
  }
  d.armed = false;
  d.want = kWholeMessage;
  d.delivered.push_back(std::move(piece));
  d.delivered_event.notify(SC_ZERO_TIME);
  if (d.receiver_counted && end(1 - di)) end(1 - di)->transfer_end();
  d.receiver_counted = false;
}

// The receiving processor communicates from when its input is armed and the message has begun to
// arrive.
void Link::count_receiver(int di) {
  Direction& d = dir_[di];
  if (d.receiver_counted) return;
  d.receiver_counted = true;
  if (end(1 - di)) end(1 - di)->transfer_begin();
}

// ---- closed form ----
//
// With the other direction silent, byte k's data packet starts at s_k and its acknowledge at a_k:
//   s_1 = start;  a_1 = max(s_1 + detect, armed_at)       (flow control: no acknowledge before the
//   input is armed) s_2 = max(a_1 + ack + process, s_1 + data);  s_k = s_2 + (k - 2) * period;  a_k
//   = s_k + detect  (k >= 2)
// with period = max(data, detect + ack + process): exactly the packet level's sequence
// (LinkTiming). The sender goes on when the last acknowledge ends; the receiver has the message
// when the last byte has arrived and its input is armed.

// At `packet` a closed form is a run: the packets of a message nothing can interleave with,
// planned from one event (and again when its input is armed: arm_input). No fault or deadline may
// be in play (they act on packets), and the other direction must be silent, as at `automatic`;
// when that direction starts, or a resetch comes, hand_over puts the packet level's state in place
// at that instant. A message of fewer than 3 bytes saves nothing. Its last byte goes packet by
// packet (on_closed_form), so the message's end -- the sender released, the message delivered --
// comes from the same events as without the run: two processes released at one instant are then
// queued in the same order.
bool Link::closed_form_allowed(int di) const {
  const Direction& d = dir_[di];
  if (d.armed && d.want < d.queue.front().bytes) return false;  // see arm_input
  switch (fidelity_) {
    case LinkFidelity::packet:
      if (!packet_runs_ || faulted_ || deadline_waits_ > 0 || dir_[di].queue.front().bytes < 3)
        return false;
      break;
    case LinkFidelity::message:
      return true;
    case LinkFidelity::automatic:
      break;
  }
  // The other direction must be silent: nothing to send, nothing of its own on either wire.
  const Direction& other = dir_[1 - di];
  return other.queue.empty() && !other.closed_form.active && !other.in_flight.active &&
         !dir_[di].in_flight.active && other.acks_pending == 0 && dir_[di].acks_pending == 0 &&
         sim_now() >= other.wire_busy_until;
}

void Link::start_closed_form(int di) {
  Direction& d = dir_[di];
  ClosedForm& cf = d.closed_form;
  cf.active = true;
  cf.bytes = d.queue.front().bytes;
  cf.start = sim_now();
  cf.armed = d.armed;
  cf.armed_at = cf.start;
  cf.sender_done = cf.delivered = false;
  d.receiving = true;
  begin_incoming(di);
  d.received = 0;
  ++closed_form_messages_;
  if (end(di)) end(di)->transfer_begin();
  if (d.armed) count_receiver(di);
  if (cf.armed) cf.milestone.notify(SC_ZERO_TIME);
}

sc_time Link::byte_start(const ClosedForm& cf, std::int64_t k) const {
  if (k == 1) return cf.start;
  const sc_time second =
      std::max(ack_start(cf, 1) + ack_packet_ + process_delay_, cf.start + data_packet_);
  return second + byte_period_ * double(k - 2);
}

sc_time Link::ack_start(const ClosedForm& cf, std::int64_t k) const {
  if (k == 1) return std::max(cf.start + detect_delay_, cf.armed_at);
  return byte_start(cf, k) + detect_delay_;
}

sc_time Link::sender_done_time(int di) const {
  const ClosedForm& cf = dir_[di].closed_form;
  return ack_start(cf, cf.bytes) + ack_packet_;
}

sc_time Link::delivery_time(int di) const {
  const ClosedForm& cf = dir_[di].closed_form;
  return std::max(byte_start(cf, cf.bytes) + data_packet_, cf.armed_at);
}

std::int64_t Link::bytes_started_by(const ClosedForm& cf, std::int64_t bytes,
                                    const sc_time& t) const {
  if (t < cf.start) return 0;
  if (!cf.armed || bytes == 1) return 1;
  const sc_time second = byte_start(cf, 2);
  if (t < second) return 1;
  const auto later = std::int64_t((t - second) / byte_period_);
  return std::min(bytes, 2 + later);
}

void Link::on_closed_form(int di) {
  Direction& d = dir_[di];
  ClosedForm& cf = d.closed_form;
  if (!cf.active || !cf.armed) return;
  const sc_time now = sim_now();
  if (fidelity_ == LinkFidelity::packet) {  // a run: handed to the packet level at its last byte
    const sc_time last = byte_start(cf, cf.bytes);
    if (now >= last) return hand_over(di);
    return cf.milestone.notify(last - now);
  }
  const sc_time done = sender_done_time(di), delivered = delivery_time(di);
  if (!cf.sender_done && now >= done) closed_form_sender_done(di);
  if (!cf.delivered && now >= delivered) {
    cf.delivered = true;
    d.dma_received.add(cf.bytes - 1, cf.start);
    d.dma_received.add(1, byte_start(cf, cf.bytes) + data_packet_);
    d.received = cf.bytes;
    complete_receive(di);
  }
  if (cf.sender_done && cf.delivered) {
    cf.active = false;
    d.wire_wake.notify(SC_ZERO_TIME);  // its wire is free for the next message
    return;
  }
  const sc_time next = cf.sender_done ? delivered : cf.delivered ? done : std::min(done, delivered);
  cf.milestone.notify(next - now);
}

// The last acknowledge is in: what the packet level does at that moment, with the message's packets
// entered in the activity record.
void Link::closed_form_sender_done(int di) {
  Direction& d = dir_[di];
  const std::int64_t bytes = d.closed_form.bytes;
  d.closed_form.sender_done = true;
  record_closed_form_packets(di, bytes, bytes);
  d.dma_sent.add(bytes, d.closed_form.start);
  d.activity.message_done(bytes, d.queue.front().label);
  take_payload(di);
  d.queue.pop_front();
  d.sent = d.acked = 0;
  ++d.completed;
  d.sent_event.notify(SC_ZERO_TIME);
  if (end(di)) end(di)->transfer_end();
  d.may_send = false;
  d.process_event.notify(process_delay_);
}

// Busy time is a sum over the packets, whatever their times; only a trace needs each packet placed.
void Link::record_closed_form_packets(int di, std::int64_t data_packets, std::int64_t ack_packets) {
  const ClosedForm& cf = dir_[di].closed_form;
  LinkActivity& data = dir_[di].activity;
  LinkActivity& acks = dir_[1 - di].activity;
  if (!data.keeps_intervals())
    data.packets(data_packets, data_packet_);
  else
    for (std::int64_t k = 1; k <= data_packets; ++k)
      data.packet(byte_start(cf, k), data_packet_, true);
  if (!acks.keeps_intervals())
    acks.packets(ack_packets, ack_packet_);
  else
    for (std::int64_t k = 1; k <= ack_packets; ++k)
      acks.packet(ack_start(cf, k), ack_packet_, false);
}

// Bytes 1..n of the closed form whose data packet, acknowledge and acknowledge processing have all
// ended by `now`: the whole of hand_over's walk for each (see there).
std::int64_t Link::bytes_done_by(const ClosedForm& cf, const sc_time& now) const {
  if (!cf.armed) return 0;  // the first acknowledge is still owed
  auto done = [&](std::int64_t k) {
    const sc_time s = byte_start(cf, k);
    return s + data_packet_ <= now && s + detect_delay_ <= now &&
           ack_start(cf, k) + ack_packet_ + process_delay_ <= now;
  };
  // done(k) implies done(j) for every j < k. A run is handed over at its last byte (at packet
  // fidelity, most of the time): the answer is then one of the last few, so look there first.
  std::int64_t hi = cf.bytes;
  for (const std::int64_t last = std::max<std::int64_t>(0, hi - 3); hi > last; --hi)
    if (done(hi)) return hi;
  std::int64_t lo = 0;  // done(lo) (0: trivially); the answer is in [lo, hi]
  while (lo < hi) {
    const std::int64_t mid = lo + (hi - lo + 1) / 2;
    if (done(mid))
      lo = mid;
    else
      hi = mid - 1;
  }
  return lo;
}

// The other direction has started: the state the packet level would be in now, worked out from the
// closed form, byte by byte. Events still to come (a detect, an acknowledge's processing, packets
// on the wires) are scheduled at their times, so the packet level carries on exactly.
void Link::hand_over(int di) {
  Direction& d = dir_[di];
  Direction& back = dir_[1 - di];  // its wire carries this direction's acknowledges
  ClosedForm& cf = d.closed_form;
  cf.active = false;
  cf.milestone.cancel();
  ++handovers_;
  const sc_time now = sim_now();
  const std::int64_t bytes = cf.bytes;
  const bool sender_side = !cf.sender_done;  // else the acknowledges are all in and recorded
  // Bytes whose packets, acknowledges and processing are all over by now leave nothing pending;
  // they form a prefix (every one of those times grows with k), found by bisection, so a long
  // message is handed over in O(log bytes), not byte by byte.
  const std::int64_t done = bytes_done_by(cf, now);
  std::int64_t sent = done, acked = done, received = done, recorded_data = done,
               recorded_acks = done;
  bool may_send = done > 0;
  if (done > 0 && !cf.delivered)
    d.dma_received.add_increasing(done, byte_start(cf, done) + data_packet_);
  for (std::int64_t k = done + 1; k <= bytes; ++k) {
    if (k >= 2 && !cf.armed) break;  // the sender waits for the first acknowledge
    const sc_time s = byte_start(cf, k);
    if (s >= now) {
      may_send = true;  // byte k is due now: the packet level sends it
      break;
    }
    sent = k;
    may_send = false;  // until its acknowledge has been processed
    if (s + data_packet_ <= now) {
      received = k;
      if (!cf.delivered) d.dma_received.add(1, s + data_packet_);
      recorded_data = k;
    } else {
      d.in_flight = {true, true, !sender_side, s};
    }
    const sc_time detect = s + detect_delay_;
    if (detect > now) {
      d.detect_event.notify(detect - now);
      if (config_.protocol == LinkProtocol::t414 && received == k && cf.armed &&
          cf.armed_at <= s + data_packet_)
        d.accepted_before_detect = true;
      break;
    }
    if (!cf.armed) {
      d.ack_owed = true;
      break;
    }
    const sc_time a = ack_start(cf, k);
    if (a >= now) {
      ++back.acks_pending;
      break;
    }
    if (a + ack_packet_ > now) {
      if (sender_side) back.in_flight = {true, false, false, a};
      break;
    }
    acked = k;
    recorded_acks = k;
    const sc_time processed = a + ack_packet_ + process_delay_;
    if (processed > now) {
      if (sender_side) d.process_event.notify(processed - now);
      break;
    }
    may_send = true;
  }
  if (sender_side && acked == bytes) {  // its last acknowledge ended just now
    d.in_flight.recorded = true;
    closed_form_sender_done(di);
  } else if (sender_side) {
    record_closed_form_packets(di, recorded_data, recorded_acks);
    d.sent = sent;
    d.acked = acked;
    d.may_send = may_send;
    if (sent > 0) d.dma_sent.add(sent, cf.start);
  }
  if (!cf.delivered) {
    d.received = received;
    if (received == bytes && cf.armed) complete_receive(di);
  }
  d.wire_wake.notify(SC_ZERO_TIME);
  back.wire_wake.notify(SC_ZERO_TIME);
}

// ---- faults ----

void Link::arm_fault() {
  faulted_ = true;
  fidelity_ = LinkFidelity::packet;  // faults act on packets
  for (int d = 0; d < 2; ++d)
    if (dir_[d].closed_form.active) hand_over(d);  // a run planned before the fault was known
}

void Link::drop_byte(int d, const sc_time& at, FaultHit hit) {
  arm_fault();
  dir_[d].byte_fault = {true, false, 0, at, std::move(hit)};
}

void Link::corrupt_byte(int d, const sc_time& at, std::uint8_t mask, FaultHit hit) {
  arm_fault();
  dir_[d].byte_fault = {true, true, mask, at, std::move(hit)};
}

void Link::stop_wire(int w, const sc_time& at, FaultHit hit) {
  arm_fault();
  Stop& s = dir_[w].wire_stop;
  if (s.armed && s.at <= at) return;
  s = {true, at, std::move(hit)};
  dir_[w].wire_wake.notify(SC_ZERO_TIME);
}

void Link::deafen_end(int e, const sc_time& at, FaultHit hit) {
  arm_fault();
  Stop& s = dir_[1 - e].deaf;  // what arrives at end e travels in direction 1 - e
  if (s.armed && s.at <= at) return;
  s = {true, at, std::move(hit)};
}

// A packet on a wire that stopped before the packet ended never arrives.
bool Link::lost_on_wire(int w, const sc_time& start, const sc_time& length) {
  const Stop& s = dir_[w].wire_stop;
  if (!s.armed || start + length <= s.at) return false;
  if (s.hit) s.hit("a packet on the wire");
  return true;
}

bool Link::deaf_at(int di) {
  const Stop& s = dir_[di].deaf;
  if (!s.now()) return false;
  if (s.hit) s.hit("a packet arriving at the halted end");
  return true;
}

void Link::apply_byte_fault(int di) {
  Direction& d = dir_[di];
  ByteFault& f = d.byte_fault;
  if (!f.armed || sim_now() < f.at) return;
  f.armed = false;
  const std::string what = "byte " + std::to_string(d.sent) + " of " +
                           std::to_string(d.incoming.bytes) + " of message '" + d.incoming.label +
                           "'";
  if (!f.corrupt) {
    d.byte_lost = true;
    if (f.hit) f.hit(what + " lost");
    return;
  }
  std::any& payload = d.payload_with_sender ? d.queue.front().payload : d.incoming.payload;
  const bool changed = flip_message_byte(payload, d.incoming.route, d.sent - 1, f.mask);
  if (f.hit) f.hit(what + (changed ? " changed" : " changed (its value is not modelled)"));
}

bool Link::transmit(int from, Message message, const sc_time& deadline) {
  Direction& d = dir_[from];
  const std::int64_t ticket = submit(from, std::move(message));
  ++deadline_waits_;
  while (d.completed < ticket) {
    if (sim_now() >= deadline) {
      reset_output(from);
      --deadline_waits_;
      return false;
    }
    sc_core::wait(deadline - sim_now(), d.sent_event);
  }
  --deadline_waits_;
  return true;
}

std::optional<Message> Link::receive(int to, const sc_time& deadline) {
  const int di = 1 - to;
  Direction& d = dir_[di];
  ++deadline_waits_;
  arm_input(di, kWholeMessage);
  while (d.delivered.empty()) {
    if (sim_now() >= deadline) {
      reset_input(di);
      --deadline_waits_;
      return std::nullopt;
    }
    sc_core::wait(deadline - sim_now(), d.delivered_event);
  }
  --deadline_waits_;
  return take_delivered(di);
}

// resetch on the sending end: the engine forgets the message (one channel per link direction: it
// is the only one queued) and what it owed; the receiving end keeps nothing of it either (U: the
// INMOS library resets both ends, Reinitialise).
void Link::reset_output(int di) {
  Direction& d = dir_[di];
  if (d.closed_form.active) hand_over(di);
  if (d.queue.empty()) return;
  const bool started = d.sent > 0 || d.receiving;
  d.payload_with_sender = false;  // abandoned with the message
  d.queue.pop_front();
  ++d.completed;
  ++d.taken;  // no input will take it
  d.sent = d.acked = 0;
  d.may_send = true;
  d.byte_lost = false;
  d.detect_event.cancel();
  d.process_event.cancel();
  dir_[1 - di].acks_pending = 0;  // the reverse wire's acknowledges are all for this direction
  d.ack_owed = d.accepted_before_detect = false;
  if (started && end(di)) end(di)->transfer_end();
  if (d.receiving) {
    d.receiving = false;
    d.received = d.given = 0;
    if (d.receiver_counted && end(1 - di)) end(1 - di)->transfer_end();
    d.receiver_counted = false;
  }
  d.wire_wake.notify(SC_ZERO_TIME);
}

// resetch on the receiving end: the input is disarmed and a message half in is dropped.
void Link::reset_input(int di) {
  Direction& d = dir_[di];
  if (d.closed_form.active) hand_over(di);
  d.armed = false;
  d.want = kWholeMessage;
  d.ack_owed = false;
  if (d.receiver_counted && end(1 - di)) end(1 - di)->transfer_end();
  d.receiver_counted = false;
  if (d.receiving) {
    d.receiving = false;
    d.received = d.given = 0;
  }
}

}  // namespace t800
