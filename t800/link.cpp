// A link's construction and what its users call: transmit and receive, with and without a
// deadline. The packet level, the closed form, the DMA counts, faults and resets are each in a
// file of their own (t800/link_*.cpp).
#include "t800/link.hpp"

#include <algorithm>
#include <functional>
#include <string>

#include "t800/link_timing.hpp"

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

}  // namespace t800
