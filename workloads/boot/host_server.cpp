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
  m.payload = std::make_shared<Bytes>(std::move(bytes));
  m.label = label;
  link.transmit(end, std::move(m));
}
}  // namespace

void HostServer::reply_thread() {
  for (;;) {
    while (!replying_) sc_core::wait(reply_ready_);
    send(*link_, end_, reply_, "SP reply");  // returns early when abandoned
    replying_ = false;
    reply_sent_.notify(sc_core::SC_ZERO_TIME);
  }
}

void HostServer::reply(Bytes bytes) {
  if (replying_) {
    // The program asks again before it took the whole reply: what it left is dropped.
    link_->abandon_output(end_);
    ++replies_cut_short_;
    wait_for_reply();
  }
  reply_ = std::move(bytes);
  replying_ = true;
  reply_ready_.notify(sc_core::SC_ZERO_TIME);
}

void HostServer::wait_for_reply() {
  while (replying_) sc_core::wait(reply_sent_);
}

void HostServer::run(network::Process& p) {
  p.set_status_text("sending the boot file");
  send(*link_, end_, std::move(boot_file_), "boot file");
  sc_core::sc_spawn([this] { reply_thread(); }, "iserver_reply");
  t800::host::SpPacketReassembler packets;
  for (;;) {
    p.set_status_text("waiting for an SP request on the host link");
    const t800::Message m = link_->receive(end_ == 0 ? 0 : 1);
    const auto* bytes = std::any_cast<SharedBytes>(&m.payload);
    if (!bytes || !*bytes) {
      session_.host_error = "the host link carried a message without bytes";
      session_.end(session_.host_error);
      return;
    }
    packets.feed(**bytes);
    while (auto request = packets.next_packet()) {
      ++requests_;
      reply(t800::host::sp_frame(server_->handle(*request)));
      if (server_->exited()) {
        wait_for_reply();  // the program reads SP.EXIT's reply before the run ends
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
