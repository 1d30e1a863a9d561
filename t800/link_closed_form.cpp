// The closed form: a message nothing can interleave with, timed from one event, and its hand-over
// to the packet level when something starts to interleave (t800/link.hpp).
#include "t800/link.hpp"

#include <algorithm>
#include <string>

namespace t800 {

using sc_core::SC_NS;
using sc_core::sc_time;
using sc_core::SC_ZERO_TIME;

// With the other direction silent, byte k's data packet starts at s_k and its acknowledge at a_k:
//   s_1 = start,  a_1 = max(s_1 + detect, armed_at)  (no acknowledge before the input is armed),
//   s_2 = max(a_1 + ack + process, s_1 + data),
//   s_k = s_2 + (k - 2) * period,  a_k = s_k + detect  (k >= 2),
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
  release_sender(di);
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

}  // namespace t800
