#include "network/transport/direct_link.hpp"

#include "network/reliable.hpp"
#include "network/transport/link_io.hpp"

namespace network {

void DirectLink::send(Process& writer, t800::Message m) {
  link_out(writer, link_, writer_end_, std::move(m));
}

t800::Message DirectLink::receive(Process& reader) {
  return link_in(reader, link_, reader_end());
}

bool DirectLink::send_or_fail(Process& writer, t800::Message m, double deadline_us) {
  return output_or_fail(writer, channel_, link_, writer_end_, std::move(m), deadline_us);
}

std::optional<t800::Message> DirectLink::receive_or_fail(Process& reader, double deadline_us) {
  return input_or_fail(reader, channel_, deadline_us, [this](const sc_core::sc_time& deadline) {
    return link_.receive(reader_end(), deadline);
  });
}

void DirectLink::watch(Process& /*alter*/, sc_core::sc_event_or_list& events) {
  events |= link_.input_pending_event(reader_end());
}

}  // namespace network
