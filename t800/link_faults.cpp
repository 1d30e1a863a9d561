// Faults on a link (network/faults.hpp): a byte lost or changed, a wire stopped, an end deafened;
// each checked when the link would act, so an armed fault costs no event.
#include "t800/link.hpp"

#include <algorithm>
#include <string>

#include "t800/payload_bytes.hpp"

namespace t800 {

using sc_core::SC_NS;
using sc_core::sc_time;
using sc_core::SC_ZERO_TIME;

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

}  // namespace t800
