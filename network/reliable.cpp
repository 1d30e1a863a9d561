#include "network/reliable.hpp"

#include "network/channel.hpp"
#include "network/machine.hpp"
#include "network/process.hpp"

namespace network {

namespace {

using t800::isa::Op;
const t800::isa::MemoryRef kWorkspace{t800::isa::Region::workspace, -1};

sc_core::sc_time at_us(double us) {
  return sc_core::sc_time(us, sc_core::SC_US);
}

// The deadline: TIMER ? now, now PLUS timeout, kept in the workspace.
void set_deadline(Process& p) {
  p.run_instructions({{Op::ldtimer, 0, 0, false, {}, "TIMER ? now"},
                      {Op::ldl, 1, 0, false, kWorkspace, "timeout"},
                      {Op::sum, 0, 0, false, {}, "deadline"},
                      {Op::stl, 1, 0, false, kWorkspace, "deadline"}});
}

void reset_channel(Process& p) {
  p.run_instructions({{Op::ldl, 1, 0, false, kWorkspace, "channel"},
                      {Op::resetch, 0, 0, false, {}, "reset the link channel"}});
}

// The process's status and wait, as Process::out and in keep them, for deadlock reports.
template <class Body>
auto communicating(Process& p, Channel& c, bool output, Body body) {
  p.set_status(output ? "out (or fail) on channel" : "in (or fail) on channel", &c);
  (output ? c.last_writer : c.last_reader).set(p);
  auto result = body();
  p.set_status("running");
  return result;
}

// The output on one link, given up at the deadline.
bool transmit_or_fail(Process& p, t800::Link& link, int end, t800::Message m, double deadline_us) {
  p.communicate(m.bytes, false);
  p.deschedule();
  const bool sent = link.transmit(end, std::move(m), at_us(deadline_us));
  p.reschedule();
  return sent;
}

}  // namespace

bool out_or_fail(Process& p, Channel& c, t800::Message m, double deadline_us) {
  if (c.kind == Channel::Kind::internal) {
    p.out(c, std::move(m));
    return true;
  }
  set_deadline(p);
  const bool done = communicating(p, c, true, [&] {
    if (c.kind == Channel::Kind::direct)
      return transmit_or_fail(p, *c.link, c.writer_end, std::move(m), deadline_us);
    FirstHop hop = routed_first_hop(p, c, std::move(m), deadline_us);
    return transmit_or_fail(p, *hop.link, hop.end, std::move(hop.wrapped), deadline_us);
  });
  if (!done) reset_channel(p);
  return done;
}

bool forward_or_fail(Process& router, t800::Link& link, int end, t800::Message m,
                     double deadline_us) {
  set_deadline(router);
  const bool done = transmit_or_fail(router, link, end, std::move(m), deadline_us);
  if (!done) reset_channel(router);
  return done;
}

std::optional<t800::Message> in_or_fail(Process& p, Channel& c, double deadline_us) {
  if (c.kind == Channel::Kind::internal) return p.in(c);
  set_deadline(p);
  auto received = communicating(p, c, false, [&]() -> std::optional<t800::Message> {
    p.communicate(0, false);
    p.deschedule();
    std::optional<t800::Message> m;
    if (c.kind == Channel::Kind::direct) {
      m = c.link->receive(1 - c.writer_end, at_us(deadline_us));
    } else {
      while (c.mailbox.empty() && t800::sim_now() < at_us(deadline_us))
        sc_core::wait(at_us(deadline_us) - t800::sim_now(), c.mail.get());
      if (!c.mailbox.empty()) {
        m = std::move(c.mailbox.front());
        c.mailbox.pop_front();
      }
    }
    p.reschedule();
    return m;
  });
  if (!received) reset_channel(p);
  return received;
}

}  // namespace network
