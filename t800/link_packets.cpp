// The packet level: each wire a method process carrying data packets and acknowledges one at a
// time, the receiver's flow control, and a message's delivery (t800/link.hpp).
#include "t800/link.hpp"

#include <algorithm>
#include <string>

namespace t800 {

using sc_core::SC_NS;
using sc_core::sc_time;
using sc_core::SC_ZERO_TIME;

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
  // the whole message is acknowledged: the sender may go on
  if (d.acked == d.queue.front().bytes) release_sender(acked_direction);
  d.process_event.notify(process_delay_);
}

// The sender's message is all acknowledged: it leaves the queue and its process goes on.
void Link::release_sender(int di) {
  Direction& d = dir_[di];
  d.activity.message_done(d.queue.front().bytes, d.queue.front().label);
  take_payload(di);
  d.queue.pop_front();
  d.sent = d.acked = 0;
  ++d.completed;
  d.sent_event.notify(SC_ZERO_TIME);
  if (end(di)) end(di)->transfer_end();
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

}  // namespace t800
