#include "t800/link.hpp"


#include "t800/link_timing.hpp"

namespace t800 {

using sc_core::sc_time;
using sc_core::SC_NS;
using sc_core::SC_ZERO_TIME;

Link::Link(const sc_core::sc_module_name& name, const LinkConfig& config, ProcessorActivity* end0,
           ProcessorActivity* end1)
    : sc_module(name), config_(config), end_{end0, end1} {
  const LinkTiming t(config);
  bit_ = sc_time(t.bit_ns, SC_NS);
  data_packet_ = sc_time(t.data_packet_ns, SC_NS);
  ack_packet_ = sc_time(t.ack_packet_ns, SC_NS);
  detect_delay_ = sc_time(t.ack_detect_ns, SC_NS);
  process_delay_ = sc_time(t.ack_process_ns, SC_NS);

  for (int d = 0; d < 2; ++d) {
    sc_core::sc_spawn([this, d] { wire_thread(d); }, sc_core::sc_gen_unique_name("wire"));
    sc_core::sc_spawn_options detect;
    detect.spawn_method();
    detect.dont_initialize();
    detect.set_sensitivity(&dir_[d].detect_event);
    sc_core::sc_spawn([this, d] { on_detect(d); }, sc_core::sc_gen_unique_name("detect"), &detect);
    sc_core::sc_spawn_options process;
    process.spawn_method();
    process.dont_initialize();
    process.set_sensitivity(&dir_[d].process_event);
    sc_core::sc_spawn([this, d] { on_ack_processed(d); }, sc_core::sc_gen_unique_name("ackproc"),
                      &process);
  }
}

void Link::transmit(int from, Message message) {
  Direction& d = dir_[from];
  const std::int64_t ticket = ++d.submitted;
  d.queue.push_back(std::move(message));
  d.wire_wake.notify(SC_ZERO_TIME);
  while (d.completed < ticket) sc_core::wait(d.sent_event);
}

bool Link::quiet() const {
  for (const Direction& d : dir_)
    if (!d.queue.empty() || !d.may_send || d.receiving || d.ack_owed || d.acks_pending > 0 ||
        d.accepted_before_detect || !d.delivered.empty())
      return false;
  return true;
}

Message Link::receive(int to) {
  // Messages to end `to` travel in direction 1 - to.
  const int di = 1 - to;
  Direction& d = dir_[di];
  d.armed = true;
  if (d.receiving) count_receiver(di);
  if (d.ack_owed) {  // a byte is waiting in the link's buffer: acknowledge it now
    d.ack_owed = false;
    queue_ack(di);
  }
  if (d.receiving && d.received == d.incoming.bytes) complete_receive(di);
  while (d.delivered.empty()) sc_core::wait(d.delivered_event);
  Message m = std::move(d.delivered.front());
  d.delivered.pop_front();
  return m;
}

void Link::wire_thread(int w) {
  Direction& own = dir_[w];
  for (;;) {
    if (own.acks_pending > 0) {
      send_ack_packet(w);
    } else if (!own.queue.empty() && own.may_send && own.sent < own.queue.front().bytes) {
      send_data_packet(w);
    } else {
      sc_core::wait(own.wire_wake);
    }
  }
}

void Link::send_data_packet(int di) {
  Direction& d = dir_[di];
  const sc_time start = sc_core::sc_time_stamp();
  if (d.sent == 0) {  // the first byte of a message: both ends are now communicating
    d.receiving = true;
    d.incoming = d.queue.front();  // the receiver's copy: the sender may finish before the last byte lands
    d.received = 0;
    if (end(di)) end(di)->transfer_begin();
    if (d.armed) count_receiver(di);
  }
  ++d.sent;
  d.may_send = false;
  d.detect_event.notify(detect_delay_);
  sc_core::wait(data_packet_);
  d.activity.packet(start, data_packet_, true);
  on_byte_arrived(di);
}

void Link::send_ack_packet(int w) {
  Direction& wire = dir_[w];
  const int acked_direction = 1 - w;
  --wire.acks_pending;
  const sc_time start = sc_core::sc_time_stamp();
  sc_core::wait(ack_packet_);
  wire.activity.packet(start, ack_packet_, false);

  Direction& d = dir_[acked_direction];
  ++d.acked;
  if (d.acked == d.queue.front().bytes) {  // the whole message is acknowledged: the sender may go on
    d.activity.message_done(d.acked, d.queue.front().label);
    d.queue.pop_front();
    d.sent = d.acked = 0;
    ++d.completed;
    d.sent_event.notify(SC_ZERO_TIME);
    if (end(acked_direction)) end(acked_direction)->transfer_end();
  }
  d.process_event.notify(process_delay_);
}

void Link::on_detect(int di) {
  Direction& d = dir_[di];
  if (d.armed || d.accepted_before_detect) {
    d.accepted_before_detect = false;
    queue_ack(di);
  } else {
    d.ack_owed = true;  // flow control: no input waiting, so no acknowledge yet
  }
}

void Link::queue_ack(int di) {
  Direction& reverse = dir_[1 - di];
  ++reverse.acks_pending;
  reverse.wire_wake.notify(SC_ZERO_TIME);
}

void Link::on_ack_processed(int di) {
  dir_[di].may_send = true;
  dir_[di].wire_wake.notify(SC_ZERO_TIME);
}

void Link::on_byte_arrived(int di) {
  Direction& d = dir_[di];
  ++d.received;
  // A T414 acknowledges after the whole packet: a byte taken by a waiting input is owed its acknowledge even
  // if that input completes (and disarms) before the acknowledge goes out.
  if (d.armed && config_.protocol == LinkProtocol::t414) d.accepted_before_detect = true;
  if (d.armed && d.received == d.incoming.bytes) complete_receive(di);
}

void Link::complete_receive(int di) {
  Direction& d = dir_[di];
  Message m = std::move(d.incoming);
  d.receiving = false;
  d.armed = false;
  d.received = 0;
  d.delivered.push_back(std::move(m));
  d.delivered_event.notify(SC_ZERO_TIME);
  if (d.receiver_counted && end(1 - di)) end(1 - di)->transfer_end();
  d.receiver_counted = false;
}

// The receiving processor communicates from when its input is armed and the message has begun to arrive.
void Link::count_receiver(int di) {
  Direction& d = dir_[di];
  if (d.receiver_counted) return;
  d.receiver_counted = true;
  if (end(1 - di)) end(1 - di)->transfer_begin();
}

}  // namespace t800
