// The host PC at the end of the host link, as `iserver -se -sb FILE` is: it sends the bootable file
// down the link, then serves the program's SP requests (t800/host/sp_server.hpp) until it calls
// SP.EXIT. The host computes for free (its time is not modelled); the link times every byte.
//
// A reply goes out while the server waits for the next request, as iserver's does: a program that
// reads a reply field by field may leave its last byte untaken (the zero iserver pads an odd body
// with, pack.c), and its next request then abandons the rest of the reply, as t4 drops it (its
// server.c starts each reply afresh). The report counts such replies.
#pragma once

#include <memory>
#include <string>

#include <systemc>

#include "network/machine.hpp"
#include "t800/host/sp_server.hpp"
#include "workloads/boot/boot_session.hpp"
#include "workloads/boot/link_port.hpp"

namespace workloads::boot {

class HostServer {
 public:
  // Throws std::invalid_argument when the network has no host link.
  HostServer(network::Machine& machine, BootSession& session, Bytes boot_file,
             std::unique_ptr<t800::host::SpServer> server);

  // The body of the host's process.
  void run(network::Process& p);

  std::int64_t requests() const { return requests_; }
  // Replies the program left unread to their end when it sent its next request.
  std::int64_t replies_cut_short() const { return replies_cut_short_; }

 private:
  network::Machine& machine_;
  BootSession& session_;
  Bytes boot_file_;
  std::unique_ptr<t800::host::SpServer> server_;
  t800::Link* link_ = nullptr;
  int end_ = 0;
  std::int64_t requests_ = 0;
  std::int64_t replies_cut_short_ = 0;

  // The reply under way, sent by a thread of its own (reply_thread) so that the server can take
  // the next request meanwhile.
  void reply_thread();
  void reply(Bytes bytes);
  void wait_for_reply();
  Bytes reply_;
  bool replying_ = false;
  sc_core::sc_event reply_ready_, reply_sent_;
};

}  // namespace workloads::boot
