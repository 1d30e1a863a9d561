// The host PC at the end of the host link, as `iserver -se -sb FILE` is: it sends the bootable file
// down the link, then serves the program's SP requests (t800/host/sp_server.hpp) until it calls
// SP.EXIT. The host computes for free (its time is not modelled); the link times every byte.
#pragma once

#include <memory>
#include <string>

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

 private:
  network::Machine& machine_;
  BootSession& session_;
  Bytes boot_file_;
  std::unique_ptr<t800::host::SpServer> server_;
  t800::Link* link_ = nullptr;
  int end_ = 0;
  std::int64_t requests_ = 0;
};

}  // namespace workloads::boot
