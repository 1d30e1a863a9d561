// resetch on either end of a link: what an abandoned output or input leaves behind.
#include "t800/link.hpp"

#include <algorithm>
#include <string>

namespace t800 {

using sc_core::SC_NS;
using sc_core::sc_time;
using sc_core::SC_ZERO_TIME;

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

bool Link::abandon_output(int from) {
  if (dir_[from].queue.empty()) return false;
  reset_output(from);
  dir_[from].sent_event.notify(SC_ZERO_TIME);  // its transmit sees it completed
  return true;
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
