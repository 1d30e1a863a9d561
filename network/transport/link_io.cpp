#include "network/transport/link_io.hpp"

#include "network/process.hpp"

namespace network {

void link_out(Process& p, t800::Link& link, int end, t800::Message m) {
  p.communicate(m.bytes, false);
  p.deschedule();
  link.transmit(end, std::move(m));
  p.reschedule();
}

t800::Message link_in(Process& p, t800::Link& link, int end) {
  p.communicate(0, false);
  p.deschedule();
  t800::Message m = link.receive(end);
  p.reschedule();
  return m;
}

}  // namespace network
