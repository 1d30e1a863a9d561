// A transputer of the network running real machine code: the instruction-set simulator's core
// (t800/iss/core.hpp) driven by a SystemC thread, its link engines on the link model (LinkPort).
//
// At reset it waits on every link, as the chip does: a first byte 0 pokes a word, 1 peeks one, and
// n >= 2 loads the n bytes that follow at MemStart and runs them (t800-iss.md, "Booting from a
// link").
//
// Time: the core runs ahead on its own clock and stops where the world outside matters: when it
// starts a link transfer (which starts at the core's cycle), when it has nothing to run, while a
// transfer of its own is in flight at the next instant anything else in the simulation is due (so
// a transfer's end is seen at the first instruction boundary after it, as the chip sees it), and
// while an input or an ALT's guard waits on a link nothing is coming on, one data packet ahead
// (what a neighbour starts from now on arrives no sooner). With nothing outstanding nothing
// outside can change what it does, and it runs ahead in slices of simulated time that only let
// SystemC's clock keep up.
// In the last case but one it may instead run a whole slice ahead from a checkpoint, and go back
// if a block starts towards it meanwhile (iss_node.cpp, "running ahead").
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "network/machine.hpp"
#include "t800/iss/core.hpp"
#include "workloads/boot/boot_session.hpp"
#include "workloads/boot/link_port.hpp"

namespace workloads::boot {

struct IssNodeOptions {
  std::int64_t installed_bytes = 2 << 20;  // from MostNeg, on-chip RAM included
  t800::iss::AddressPolicy policy = t800::iss::AddressPolicy::wrap;
  std::int64_t max_instructions = 0;  // per processor; 0: no limit
  double slice_us = 1000;             // the run-ahead slice with nothing outstanding
  // Where only an arrival could change what the core does, run on to the slice's end from a
  // checkpoint and go back if one comes (iss_node.cpp, "running ahead"); false: never further than
  // the look-ahead. Only where DMA stalls are charged can differ (docs/iss.md, "Running ahead").
  bool run_ahead = true;
  bool profile = false;  // tally instructions and waits (IssNode::profile)
};

// What a profiled processor did (IssNodeOptions::profile): its instructions by operation and by
// block of code, and the simulated time it was idle waiting for each thing -- a link's input or
// output (the host's link named so), an ALT's link guard, its timer queue. Time idle while several
// are awaited counts under each.
struct NodeProfile {
  t800::iss::InstructionProfile instructions;
  std::map<std::string, double> waiting_us;
  double idle_us = 0;
};

class IssNode : public t800::iss::LinkEngine {
 public:
  IssNode(network::Machine& machine, int node, BootSession& session, const IssNodeOptions& options);

  // The body of the node's process.
  void run(network::Process& p);

  void start_output(int link, std::vector<std::uint8_t> bytes) override;
  void start_input(int link, t800::iss::Word count) override;
  bool input_pending(int link) const override;
  void watch_input(int link, bool on) override;
  void reset(int link, bool output) override;

  const t800::iss::Core& core() const { return core_; }
  const NodeProfile& profile() const { return profile_; }
  // What the processor is doing now, for a run stopped before its end: running (at which Iptr),
  // halted, or its waiting processes; and the link transfers in flight.
  std::string state() const;
  // A run stopped (a host-time limit, an interrupt) while this core was ahead of the stop: it is
  // brought back to the stop's instant, so that what it reports ran before the stop.
  void settle();

 private:
  struct LinkEvent {
    enum class Kind { output_done, input_done, arrived } kind;
    int link = 0;
    Bytes bytes;
  };

  bool boot(network::Process& p);
  Bytes read_boot_block(int link, std::int64_t count);
  void execute(network::Process& p);
  void deliver_link_events();
  void deliver_arrivals();
  std::optional<std::int64_t> lookahead_bound(std::int64_t now) const;
  // Running ahead of the look-ahead (iss_node.cpp, "Running ahead").
  bool may_run_ahead() const;
  t800::iss::StopReason run_core(std::int64_t now, std::int64_t bound, std::int64_t slice_end);
  bool run_ahead_stands(std::int64_t end_cycle);
  void undo_run_ahead();
  void defer(std::function<void()> port_change);
  std::int64_t instruction_budget() const;
  std::int64_t cycle_of(const sc_core::sc_time& t) const;
  void start_requested_transfers();
  void charge_dma();
  std::int64_t dma_moved() const;  // bytes the link engines have moved at this processor's ends
  void account();
  void wait_until_cycle(std::int64_t cycle);
  void wait_for_link_or(const sc_core::sc_time* timeout);
  std::int64_t now_cycle() const;
  sc_core::sc_time time_of(std::int64_t cycle) const;
  void post(LinkEvent e);

  network::Machine& machine_;
  int node_;
  BootSession& session_;
  IssNodeOptions options_;
  t800::iss::Core core_;
  double cycle_ns_;
  double tick_cycles_;  // the kernel's time resolution, in cycles
  std::array<std::unique_ptr<LinkPort>, 4> ports_;
  std::array<std::int64_t, 4> packet_cycles_{};  // one data packet on each link, in cycles
  std::vector<LinkEvent> inbox_;
  sc_core::sc_event inbox_event_;
  std::vector<std::function<void()>> requested_;  // transfers to start at the core's cycle
  // While running ahead: the ports' watches and resets the core made, done once the run stands
  // (its end is the first instant anything could see them), forgotten if it is undone.
  std::vector<std::function<void()>> deferred_;
  bool ahead_ = false;  // the core is running, or has run, ahead from a checkpoint not yet settled
  // At the checkpoint: the link flags below, and which links had a block already waiting.
  struct AheadFrom {
    std::int64_t cycle = 0;
    std::array<bool, 4> output_busy{}, input_busy{}, watching{}, block_waiting{};
  } ahead_from_;
  // Transfers and link watches under way, by link: while any is, outside events are due.
  std::array<bool, 4> output_busy_{}, input_busy_{}, watching_{};
  bool outstanding() const;
  std::string describe_waiting() const;
  std::string describe_links() const;
  std::vector<std::string> awaited() const;  // what an idle processor waits for (NodeProfile)
  NodeProfile profile_;
  int host_link_ = -1;  // this processor's link wired to the host, if one is
  std::int64_t dma_seen_ = 0;
};

}  // namespace workloads::boot
