#include "workloads/boot/host_server.hpp"

#include <stdexcept>

#include "t800/host/sp_protocol.hpp"

namespace workloads::boot {

HostServer::HostServer(network::Machine& machine, BootSession& session, Bytes boot_file,
                       std::unique_ptr<t800::host::SpServer> server)
    : machine_(machine),
      session_(session),
      boot_file_(std::move(boot_file)),
      server_(std::move(server)) {
  for (const auto& l : machine.links())
    for (int e = 0; e < 2; ++e)
      if (l.node[e] == network::Machine::kHost) {
        link_ = l.link;
        end_ = e;
      }
  if (!link_)
    throw std::invalid_argument(
        "the network has no host link to boot through (a topology's `host = ...`)");
}

namespace {
void send(t800::Link& link, int end, Bytes bytes, const std::string& label) {
  t800::Message m;
  m.bytes = std::int64_t(bytes.size());
  m.payload.value = std::move(bytes);
  m.label = label;
  link.transmit(end, std::move(m));
}
}  // namespace

void HostServer::run(network::Process& p) {
  p.set_status_text("sending the boot file");
  send(*link_, end_, std::move(boot_file_), "boot file");
  t800::host::SpPacketReassembler packets;
  for (;;) {
    p.set_status_text("waiting for an SP request on the host link");
    const t800::Message m = link_->receive(end_ == 0 ? 0 : 1);
    const auto* bytes = std::any_cast<Bytes>(&m.payload.value);
    if (!bytes) {
      session_.host_error = "the host link carried a message without bytes";
      session_.end(session_.host_error);
      return;
    }
    packets.feed(*bytes);
    while (auto request = packets.next_packet()) {
      ++requests_;
      send(*link_, end_, t800::host::sp_frame(server_->handle(*request)), "SP reply");
      if (server_->exited()) {
        session_.exit_status = server_->exit_status();
        session_.exit_code = server_->exit_code();
        session_.end("the program called SP.EXIT");
        return;
      }
    }
    if (packets.failed()) {
      session_.host_error = "the host link's bytes are not SP requests: " + packets.error();
      session_.end(session_.host_error);
      return;
    }
  }
}

}  // namespace workloads::boot
