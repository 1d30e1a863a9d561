// The occam-like process API workloads are written in (docs/architecture.md, "Programs: processes
// and channels"). A process is ordinary sequential C++ running in its own SystemC thread on one
// transputer (or on the host PC, where computing is free):
//   p.compute(mix, "D12");  p.out(ch, message);  Message m = p.in(ch);  p.par({...});
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include <systemc>

#include "network/lazy_event.hpp"
#include "t800/compute_work.hpp"
#include "t800/cpu.hpp"
#include "t800/isa/instruction.hpp"
#include "t800/message.hpp"
#include "t800/operation_mix.hpp"

namespace network {

class Machine;
struct Channel;

class Process {
 public:
  using Body = std::function<void(Process&)>;

  Process(Machine& machine, int node, std::string name, t800::Priority priority);

  // Runs a block of computation on this process's CPU.
  void compute(std::int64_t cycles, const std::string& label = {});
  void compute(const t800::OperationMix& mix, const std::string& label = {});
  // Recorded kernels are timed from their T800 code (fidelity.compute_cost = "instructions"), or
  // by their mix (compute_cost = "mix").
  void compute(const t800::ComputeWork& work, const std::string& label = {});
  // Sends a message and returns when it has been taken (occam's synchronised `!`).
  void out(Channel& channel, t800::Message message);
  // Waits for and returns the next message on the channel (occam's `?`).
  t800::Message in(Channel& channel);
  // occam's STOP, as a run-time error (a subscript out of range) ends a process: it stops for ever,
  // and a deadlock report names it with `why`.
  [[noreturn]] void stop(const std::string& why);
  // Runs the branches as parallel processes on the same processor and returns when all have ended.
  void par(const std::vector<Body>& branches);
  // PRI PAR: the first branch at high priority, the others at low.
  void pri_par(const Body& high, const std::vector<Body>& low);

  // The process's TIMER (occam's `TIMER ? t`): ticks of 1 us at high priority, 64 us at low
  // priority (the T800's two clocks).
  std::int64_t clock() const;
  double tick_us() const;
  // TIMER ? AFTER t: waits until the clock is after t (tin).
  void wait_after(std::int64_t t);
  // When the clock first reads more than t.
  sc_core::sc_time time_after(std::int64_t t) const;
  // Charges a short sequence of process instructions (ALT's, a timer's) to the CPU.
  void run_instructions(const t800::isa::Sequence& code);
  // An ALT waiting on this process's guards is woken by a writer arriving on one of them.
  sc_core::sc_event& alt_event() { return alt_event_.get(); }
  void wake_alt() { alt_event_.notify_delta(); }
  t800::Priority priority() const { return descriptor_.priority; }

  int node() const { return node_; }  // processor index, or Machine::kHost
  const std::string& name() const { return descriptor_.name; }
  bool on_host() const;
  double now_us() const { return t800::sim_now().to_seconds() * 1e6; }
  Machine& machine() { return machine_; }

  // For the channel implementations: CPU work of a communication instruction for a message of
  // `bytes` (copying it when `copies`), giving up and retaking the CPU.
  void communicate(std::int64_t bytes, bool copies);
  void deschedule();
  void reschedule();
  // What the process is doing, for deadlock reports: a phrase and, for a communication, its
  // channel ("in on channel" c reads "in on channel <c's name>"). Kept as pointers: a process
  // changes status at every communication, and the words are wanted only if it deadlocks.
  void set_status(const char* doing, const Channel* about = nullptr) {
    doing_ = doing;
    about_ = about;
  }
  // A status whose words are made at run time (a STOP's reason).
  void set_status_text(std::string text) {
    doing_ = nullptr;
    status_text_ = std::move(text);
  }
  std::string status() const;
  // What it waits on, for the cycle of waits in a deadlock report (network/wait_cycle.hpp): the
  // channel of the `in` or `out` it is in (null otherwise), or the PAR branches it waits for.
  const Channel* channel() const { return channel_; }
  bool outputting() const { return outputting_; }
  const std::vector<Process*>& branches() const { return branches_; }
  // Ends the process's life cycle (called by the machine once the body returns).
  void mark_ended();
  bool ended() const { return ended_; }
  sc_core::sc_event& ended_event() { return ended_event_.get(); }
  bool daemon() const { return daemon_; }  // routers run forever and are not waited for
  void set_daemon() { daemon_ = true; }

  // A PAR branch's record is used again by the next PAR's branch of its index (start_branch,
  // Machine::spawn_again): a PAR in a loop spawns the same branches every time round, and a long
  // run would otherwise keep a record for every branch it ever ran. Which use of the record this
  // is, and when it was spawned (reports list processes in that order).
  std::uint32_t incarnation() const { return incarnation_; }
  std::uint64_t spawned() const { return spawned_; }
  void set_spawned(std::uint64_t n) { spawned_ = n; }
  // Ended, and no notification of the ended process's own is still to come (its join at the next
  // delta, a preemption's timed interrupt): the record can start again without inheriting any.
  bool reusable() const;
  // The record, reusable, becomes a new process of the same name.
  void begin_again(t800::Priority priority, std::uint64_t spawned);

 private:
  Machine& machine_;
  int node_;
  t800::ProcessDescriptor descriptor_;
  const char* doing_ = "not started";
  const Channel* about_ = nullptr;
  std::string status_text_;  // when doing_ is null
  bool ended_ = false;
  bool daemon_ = false;
  const Channel* channel_ = nullptr;
  bool outputting_ = false;
  std::vector<Process*> branches_;
  LazyEvent ended_event_;
  LazyEvent alt_event_;
  // The records of the last PAR's branches, by index, for the next PAR's (start_branch).
  std::vector<Process*> branch_records_;
  Process& start_branch(std::size_t i, t800::Priority priority, const Body& body);
  std::uint32_t incarnation_ = 0;
  std::uint64_t spawned_ = 0;
  std::uint64_t ended_delta_ = 0;  // sc_delta_count() when it ended
};

}  // namespace network
