// Small networks and helpers shared by the core tests.
#pragma once

#include <functional>
#include <string>

#include "network/families.hpp"
#include "network/machine.hpp"
#include "t800/timing_table.hpp"

namespace core_test {

inline network::Topology chain(int workers) {
  return network::generate(network::Family::chain, workers, {}, {"test", 0, 0});
}

inline network::Topology tree(int workers) {
  return network::generate(network::Family::tree, workers, {}, {"test", 0, 0});
}

inline network::MachineOptions options(double mbps, t800::LinkProtocol protocol = t800::LinkProtocol::overlapped) {
  network::MachineOptions o;
  o.link.speed_mbps = mbps;
  o.link.protocol = protocol;
  return o;
}

// Streams `messages` messages of `bytes` from P0 to P1 (and back too when both_ways); returns KB/s
// (1000 bytes) per direction, measured to the arrival of the last message.
struct StreamResult {
  double forward_kBps = 0, backward_kBps = 0;
};

inline StreamResult stream(double mbps, bool both_ways, t800::LinkProtocol protocol, std::int64_t bytes = 4096,
                           int messages = 16) {
  network::Machine m(chain(1), options(mbps, protocol));
  double end_us[2] = {0, 0};
  auto add = [&](int from, int to, int d) {
    auto& c = m.channel("stream" + std::to_string(d), from, to);
    m.spawn(from, "src", t800::Priority::low, [&c, bytes, messages](network::Process& p) {
      for (int i = 0; i < messages; ++i) p.out(c, {bytes, {}, "block"});
    });
    m.spawn(to, "sink", t800::Priority::low, [&c, &end_us, d, messages](network::Process& p) {
      for (int i = 0; i < messages; ++i) p.in(c);
      end_us[d] = p.now_us();
    });
  };
  add(0, 1, 0);
  if (both_ways) add(1, 0, 1);
  StreamResult r;
  if (!m.run().empty()) return {0.0 / 0.0, 0.0 / 0.0};  // deadlocked: no rate (every comparison fails)
  const double total = double(bytes) * messages;
  r.forward_kBps = total / end_us[0] * 1e3;
  if (both_ways) r.backward_kBps = total / end_us[1] * 1e3;
  return r;
}

}  // namespace core_test
