#include "network/transport/store_and_forward.hpp"

#include <algorithm>

#include "network/process.hpp"
#include "network/reliable.hpp"
#include "network/transport/link_io.hpp"
#include "t800/sim_now.hpp"

namespace network {

// deadline_us < 0: sent with out, and forwarded so.
t800::Message StoreAndForward::with_header(t800::Message m, double deadline_us) const {
  m.bytes += kRouteHeaderBytes;
  m.route = {kRouteHeaderBytes, channel_.id, deadline_us};
  return m;
}

void StoreAndForward::send(Process& writer, t800::Message m) {
  const Hop& first = hops_.front();
  link_out(writer, *first.link, first.end, with_header(std::move(m), -1));
}

bool StoreAndForward::send_or_fail(Process& writer, t800::Message m, double deadline_us) {
  const Hop& first = hops_.front();
  return output_or_fail(writer, channel_, *first.link, first.end,
                        with_header(std::move(m), deadline_us), deadline_us);
}

t800::Message StoreAndForward::take_mail() {
  t800::Message m = std::move(mailbox_.front());
  mailbox_.pop_front();
  return m;
}

t800::Message StoreAndForward::receive(Process& reader) {
  reader.communicate(0, false);
  if (mailbox_.empty()) {
    reader.deschedule();
    while (mailbox_.empty()) sc_core::wait(mail_.get());
    reader.reschedule();
  }
  return take_mail();
}

std::optional<t800::Message> StoreAndForward::mail_by(const sc_core::sc_time& deadline) {
  while (mailbox_.empty() && t800::sim_now() < deadline)
    sc_core::wait(deadline - t800::sim_now(), mail_.get());
  if (mailbox_.empty()) return std::nullopt;
  return take_mail();
}

std::optional<t800::Message> StoreAndForward::receive_or_fail(Process& reader, double deadline_us) {
  return input_or_fail(reader, channel_, deadline_us,
                       [this](const sc_core::sc_time& deadline) { return mail_by(deadline); });
}

void StoreAndForward::watch(Process& /*alter*/, sc_core::sc_event_or_list& events) {
  events |= mail_.get();
}

// The router hands a message to its reader through a buffer, so a slow reader does not stall the
// link (U).
void StoreAndForward::deliver(Process& router, t800::Message m) {
  m.bytes -= m.route.bytes;
  m.route = {};
  router.communicate(m.bytes, true);
  mailbox_.push_back(std::move(m));
  mail_.notify_delta();
}

void StoreAndForward::pass_on(Process& router, int node, t800::Message m) {
  if (node == channel_.to) return deliver(router, std::move(m));
  const auto here = std::find(channel_.path.begin(), channel_.path.end(), node);
  const Hop& next = hops_[std::size_t(here - channel_.path.begin())];
  const double deadline_us = m.route.deadline_us;
  if (deadline_us < 0)
    link_out(router, *next.link, next.end, std::move(m));
  else if (!forward_or_fail(router, *next.link, next.end, std::move(m), deadline_us))
    router.set_status_text("router dropped a message for " + channel_.name + " at its deadline");
}

}  // namespace network
