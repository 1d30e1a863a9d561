#include "network/reliable.hpp"

#include "network/channel.hpp"
#include "network/process.hpp"
#include "t800/link.hpp"

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

bool output_or_fail(Process& writer, Channel& c, t800::Link& link, int end, t800::Message m,
                    double deadline_us) {
  set_deadline(writer);
  const bool done = communicating(writer, c, true, [&] {
    return transmit_or_fail(writer, link, end, std::move(m), deadline_us);
  });
  if (!done) reset_channel(writer);
  return done;
}

bool forward_or_fail(Process& router, t800::Link& link, int end, t800::Message m,
                     double deadline_us) {
  set_deadline(router);
  const bool done = transmit_or_fail(router, link, end, std::move(m), deadline_us);
  if (!done) reset_channel(router);
  return done;
}

std::optional<t800::Message> input_or_fail(Process& reader, Channel& c, double deadline_us,
                                           const Arrival& arrival) {
  set_deadline(reader);
  auto received = communicating(reader, c, false, [&] {
    reader.communicate(0, false);
    reader.deschedule();
    std::optional<t800::Message> m = arrival(at_us(deadline_us));
    reader.reschedule();
    return m;
  });
  if (!received) reset_channel(reader);
  return received;
}

}  // namespace network
