// The T800's CPU and its microcoded scheduler: one processor shared by the processes placed on it.
// High priority processes run until they deschedule and preempt low priority ones (after the
// interrupt latency); low priority processes are round-robin and timesliced (docs/t800-timing.md
// section 7).
//
// Every call is made from the SystemC thread of the process concerned. A process holds the CPU from
// the moment it is dispatched until it deschedules (communication, end), exactly as on the
// hardware.
#pragma once

#include <cstdint>
#include <deque>
#include <functional>
#include <string>
#include <vector>

#include <systemc>

#include "t800/activity.hpp"
#include "t800/fidelity.hpp"
#include "t800/sim_now.hpp"

namespace t800 {

class Link;

enum class Priority { high, low };

// The scheduler's view of one process (the T800's process descriptor: workspace and priority).
struct ProcessDescriptor {
  std::string name;
  Priority priority = Priority::low;
  sc_core::sc_event wake;       // dispatched
  sc_core::sc_event interrupt;  // a running compute block must look at the queues again
  sc_core::sc_time dispatched_at;
  // When the last preemption notified `interrupt` for (a timed notification still pending until
  // then, even if the process has stopped running): a record used again must not inherit it.
  sc_core::sc_time interrupt_due;
};

struct CpuStatistics {
  std::int64_t dispatches = 0;
  std::int64_t preemptions = 0;
  std::int64_t timeslices = 0;
  // Compute slices whose end the timeslice clock could set: another low-priority process waits and
  // the work runs past one timeslice from dispatch. The clock ticks at absolute times, so only
  // while this stays unchanged is a stretch of simulation translation-invariant: the same work
  // started later takes as long.
  std::int64_t clock_dependent = 0;
  std::int64_t stolen_cycles =
      0;  // memory cycles link DMA took from compute (fine and auto fidelity)
};

class Cpu {
 public:
  Cpu(double cycle_ns, ProcessorActivity& activity, int interrupt_latency_cycles);

  void set_fidelity(ComputeFidelity fidelity) { fidelity_ = fidelity; }
  ComputeFidelity fidelity() const { return fidelity_; }
  // A link end of this transputer: its DMA engine takes memory cycles from whatever the CPU is
  // running.
  void attach_dma(const Link& link, int end) { dma_.push_back({&link, end}); }

  // Runs `cycles` of work for p, waiting for the CPU first if p does not hold it. p still holds the
  // CPU after.
  void execute(ProcessDescriptor& p, std::int64_t cycles, ProcessorState kind,
               const std::string& label);
  // p stops using the CPU (blocks on communication or ends); the next ready process is dispatched.
  void deschedule(ProcessDescriptor& p);
  // p becomes ready and waits until it is dispatched.
  void acquire(ProcessDescriptor& p);

  bool holds(const ProcessDescriptor& p) const { return running_ == &p; }
  // A fault (network/faults.hpp): from `at` the processor has halted. Checked whenever a process
  // would run, so it adds no event: a compute block running at `at` stops there, and no process
  // runs again (each stays where it was, for ever). `hit` is called with the process stopped.
  void halt_at(const sc_core::sc_time& at, std::function<void(const std::string&)> hit);
  bool halted() const { return halt_armed_ && sim_now() >= halt_at_; }
  sc_core::sc_time cycles(std::int64_t n) const { return cycle_ * double(n); }
  const CpuStatistics& statistics() const { return stats_; }

 private:
  void make_ready(ProcessDescriptor& p);
  void dispatch_next();
  void yield(ProcessDescriptor& p, bool to_front);
  sc_core::sc_time slice_end(const ProcessDescriptor& p) const;
  bool must_yield(const ProcessDescriptor& p, const sc_core::sc_time& now) const;
  bool timesliced() const { return fidelity_ != ComputeFidelity::block; }
  sc_core::sc_time slice_limit(const ProcessDescriptor& p, sc_core::sc_time limit,
                               const sc_core::sc_time& now);
  std::int64_t dma_at_start(const sc_core::sc_time& t0);  // marks each end (DmaEnd)
  std::int64_t dma_at_end(const sc_core::sc_time& now, const sc_core::sc_time& t0) const;
  void stop_if_halted(ProcessDescriptor& p);

  sc_core::sc_time cycle_;
  sc_core::sc_time latency_;
  ProcessorActivity& activity_;
  ProcessDescriptor* running_ = nullptr;
  std::deque<ProcessDescriptor*> ready_high_, ready_low_;
  bool preempt_pending_ = false;
  sc_core::sc_time preempt_at_;
  CpuStatistics stats_;
  ComputeFidelity fidelity_ = ComputeFidelity::automatic;
  struct DmaEnd {
    const Link* link;
    int end;
    // Read at the start of the block now running: the end's count, and whether it was still then
    // (Link::dma_still).
    std::int64_t at_start = 0;
    bool still_at_start = false;
  };
  std::vector<DmaEnd> dma_;
  bool halt_armed_ = false;
  sc_core::sc_time halt_at_;
  std::function<void(const std::string&)> halt_hit_;
  sc_core::sc_event never_;  // what a halted processor's processes wait for
};

}  // namespace t800
