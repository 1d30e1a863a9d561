// What the processors and the host of one booted run share: whether the session is over (the
// program called SP.EXIT, or a processor hit the instruction limit), and each processor's account.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <systemc>

#include "t800/iss/core.hpp"

namespace workloads::boot {

struct ProcessorAccount {
  std::string name;
  bool booted = false;
  int boot_link = -1;
  std::int64_t boot_bytes = 0;
  // While booting: the link and how many of how many bytes of a block have come.
  int waiting_link = -1;
  std::int64_t block_got = 0, block_expected = 0;
  std::int64_t pokes = 0, peeks = 0;
  std::int64_t instructions = 0;
  std::int64_t cycles = 0;
  std::int64_t synchronisations = 0;  // times the core stopped for SystemC
  // Runs past the look-ahead (IssNode::run_ahead): how many, how many were undone by an arrival,
  // and the cycles those had run (host work done twice).
  std::int64_t runs_ahead = 0, runs_ahead_undone = 0, cycles_undone = 0;
  std::int64_t dma_stall_cycles = 0;
  t800::iss::BlockCounts blocks;  // how the ISS ran its code (t800/iss/blocks.hpp)
  std::optional<t800::iss::HaltReport> halt;
  std::vector<t800::iss::WaitingProcess> waiting;  // at the end
  bool instruction_limit = false;
};

class BootSession {
 public:
  explicit BootSession(std::size_t processors) : accounts_(processors) {}

  void end(const std::string& why) {
    if (over_) return;
    over_ = true;
    why_ = why;
    ended_.notify(sc_core::SC_ZERO_TIME);
  }
  bool over() const { return over_; }
  const std::string& why() const { return why_; }
  sc_core::sc_event& ended_event() { return ended_; }

  ProcessorAccount& account(int node) { return accounts_.at(std::size_t(node)); }
  const std::vector<ProcessorAccount>& accounts() const { return accounts_; }
  std::int64_t instructions() const {
    std::int64_t n = 0;
    for (const auto& a : accounts_) n += a.instructions;
    return n;
  }

  // The host's side: set when the program exits through SP.EXIT.
  std::optional<std::int32_t> exit_status;
  int exit_code = 0;
  std::string host_error;  // the host link's stream was not SP, or the boot file could not go

 private:
  bool over_ = false;
  std::string why_;
  sc_core::sc_event ended_;
  std::vector<ProcessorAccount> accounts_;
};

}  // namespace workloads::boot
