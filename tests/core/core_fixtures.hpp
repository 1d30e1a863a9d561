// Small networks and helpers shared by the core tests.
#pragma once

#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cmath>
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

inline network::MachineOptions options(
    double mbps, t800::LinkProtocol protocol = t800::LinkProtocol::overlapped) {
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

inline StreamResult stream(double mbps, bool both_ways, t800::LinkProtocol protocol,
                           std::int64_t bytes = 4096, int messages = 16) {
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
  if (!m.run().empty())
    return {0.0 / 0.0, 0.0 / 0.0};  // deadlocked: no rate (every comparison fails)
  const double total = double(bytes) * messages;
  r.forward_kBps = total / end_us[0] * 1e3;
  if (both_ways) r.backward_kBps = total / end_us[1] * 1e3;
  return r;
}

// SystemC elaborates once per process: runs `simulate` in a forked child and returns what it
// wrote (NaN everywhere if the child failed).
template <std::size_t N>
std::array<double, N> in_child(const std::function<std::array<double, N>()>& simulate) {
  std::array<double, N> v;
  v.fill(std::nan(""));
  int fds[2];
  if (pipe(fds) != 0) return v;
  const pid_t pid = fork();
  if (pid == 0) {
    close(fds[0]);
    const std::array<double, N> got = simulate();
    const ssize_t written = write(fds[1], got.data(), sizeof got);
    _exit(written == ssize_t(sizeof got) ? 0 : 1);
  }
  close(fds[1]);
  std::array<double, N> got;
  const bool read_all = read(fds[0], got.data(), sizeof got) == ssize_t(sizeof got);
  close(fds[0]);
  int status = 0;
  waitpid(pid, &status, 0);
  if (read_all && WIFEXITED(status) && WEXITSTATUS(status) == 0) v = got;
  return v;
}

}  // namespace core_test
