#include "t800/cpu.hpp"

#include <algorithm>
#include <cmath>

#include "t800/link.hpp"
#include "t800/timing_table.hpp"

namespace t800 {

using sc_core::SC_NS;
using sc_core::sc_time;
using sc_core::SC_ZERO_TIME;

namespace {
const sc_time kTimeslice(timing::kTimesliceUs, sc_core::SC_US);
}

Cpu::Cpu(double cycle_ns, ProcessorActivity& activity, int interrupt_latency_cycles)
    : cycle_(cycle_ns, SC_NS),
      latency_(cycle_ * double(interrupt_latency_cycles)),
      activity_(activity) {}

void Cpu::make_ready(ProcessDescriptor& p) {
  if (p.priority == Priority::high) {
    ready_high_.push_back(&p);
    if (running_ && running_->priority == Priority::low && !preempt_pending_) {
      // The running low-priority process keeps the CPU for the interrupt latency, then is
      // preempted.
      preempt_pending_ = true;
      preempt_at_ = sim_now() + latency_;
      running_->interrupt.notify(latency_);
      running_->interrupt_due = preempt_at_;
    }
  } else {
    ready_low_.push_back(&p);
    // A lone low-priority process runs unsliced; now that it has company it must watch its
    // timeslice.
    if (running_ && running_->priority == Priority::low) running_->interrupt.notify(SC_ZERO_TIME);
  }
}

void Cpu::dispatch_next() {
  std::deque<ProcessDescriptor*>& queue = !ready_high_.empty() ? ready_high_ : ready_low_;
  if (queue.empty()) {
    running_ = nullptr;
    return;
  }
  running_ = queue.front();
  queue.pop_front();
  if (running_->priority == Priority::high) preempt_pending_ = false;
  running_->dispatched_at = sim_now();
  ++stats_.dispatches;
  running_->wake.notify(SC_ZERO_TIME);
}

void Cpu::acquire(ProcessDescriptor& p) {
  stop_if_halted(p);
  if (running_ == &p) return;
  make_ready(p);
  if (!running_) dispatch_next();
  while (running_ != &p) sc_core::wait(p.wake);
}

void Cpu::halt_at(const sc_time& at, std::function<void(const std::string&)> hit) {
  halt_armed_ = true;
  halt_at_ = at;
  halt_hit_ = std::move(hit);
}

void Cpu::stop_if_halted(ProcessDescriptor& p) {
  if (!halted()) return;
  activity_.set_cpu(ProcessorState::idle);
  if (halt_hit_) halt_hit_(p.name);
  running_ = nullptr;
  for (;;) sc_core::wait(never_);
}

void Cpu::deschedule(ProcessDescriptor& p) {
  if (running_ != &p) return;
  dispatch_next();
}

// A low-priority process is descheduled at the next descheduling point once it has run past the
// second timeslice tick after it was dispatched (so between one and two timeslices), if another one
// is waiting.
sc_time Cpu::slice_end(const ProcessDescriptor& p) const {
  const double ticks = std::floor(p.dispatched_at / kTimeslice);
  return kTimeslice * (ticks + 2.0);
}

bool Cpu::must_yield(const ProcessDescriptor& p, const sc_time& now) const {
  if (p.priority == Priority::high) return false;
  if (preempt_pending_ && now >= preempt_at_) return true;
  return timesliced() && !ready_low_.empty() && now >= slice_end(p);
}

// How long a low-priority process may compute before the scheduler must look again: until a pending
// preemption, and, when another low-priority process waits, until its timeslice ends. At fine
// fidelity it also wakes at every timeslice tick, as the hardware's timer does, whether or not
// anyone waits.
sc_time Cpu::slice_limit(const ProcessDescriptor& p, sc_time limit, const sc_time& now) {
  if (p.priority != Priority::low) return limit;
  if (preempt_pending_) limit = std::min(limit, preempt_at_ - now);
  if (!timesliced()) return limit;
  if (!ready_low_.empty()) {
    // The slice ends between one and two timeslices after dispatch, wherever the clock's ticks
    // fall: work that ends within one timeslice of dispatch cannot meet it at any phase of the
    // clock.
    if (now + limit > p.dispatched_at + kTimeslice) ++stats_.clock_dependent;
    limit = std::min(limit, slice_end(p) - now);
  }
  if (fidelity_ == ComputeFidelity::fine)
    limit = std::min(limit, kTimeslice * (std::floor(now / kTimeslice) + 1.0) - now);
  return limit;
}

// The bytes the link engines have moved by a block's start t0 (counting those at t0), and by its
// end (strictly before it, less those counted at t0 after the start was read).
// An end that was still at the start and is still at the end with its count unchanged moved
// nothing meanwhile: its part of the sum is what it was at the start (most ends, most blocks).
std::int64_t Cpu::dma_at_start(const sc_time& t0) {
  std::int64_t n = 0;
  for (DmaEnd& d : dma_) {
    d.still_at_start = d.link->dma_still(d.end);
    d.at_start = d.link->dma_bytes_including_now(d.end, t0);
    n += d.at_start;
  }
  return n;
}

std::int64_t Cpu::dma_at_end(const sc_time& now, const sc_time& t0) const {
  std::int64_t n = 0;
  for (const DmaEnd& d : dma_) {
    const bool unchanged =
        d.still_at_start && d.link->dma_still(d.end) && d.link->dma_counted(d.end) == d.at_start;
    n += unchanged ? d.at_start : d.link->dma_before_less_late(d.end, now, t0);
  }
  return n;
}

void Cpu::yield(ProcessDescriptor& p, bool preempted) {
  // A preempted process resumes before any other low-priority process (the T800 saves it in a
  // register).
  if (preempted) {
    ready_low_.push_front(&p);
    ++stats_.preemptions;
  } else {
    ready_low_.push_back(&p);
    ++stats_.timeslices;
  }
  dispatch_next();
  while (running_ != &p) sc_core::wait(p.wake);
}

void Cpu::execute(ProcessDescriptor& p, std::int64_t n, ProcessorState kind,
                  const std::string& label) {
  acquire(p);
  const bool stealing = fidelity_ != ComputeFidelity::block && !dma_.empty();
  sc_time remaining = cycles(n);
  while (remaining > SC_ZERO_TIME) {
    const sc_time start = sim_now();
    if (must_yield(p, start)) {
      yield(p, preempt_pending_ && start >= preempt_at_);
      continue;
    }
    sc_time limit = slice_limit(p, remaining, start);
    if (halt_armed_ && halt_at_ > start) limit = std::min(limit, halt_at_ - start);
    const std::int64_t dma_before = stealing ? dma_at_start(start) : 0;
    activity_.set_cpu(kind, label, start);
    if (p.priority == Priority::high)
      sc_core::wait(limit);  // nothing interrupts it (make_ready): the kernel need not watch for it
    else
      sc_core::wait(limit, p.interrupt);
    const sc_time end = sim_now();
    activity_.set_cpu(ProcessorState::idle, {}, end);
    stop_if_halted(p);
    remaining -= end - start;
    if (stealing) {  // every byte the link engines moved meanwhile took a memory cycle: the work
                     // takes longer
      const std::int64_t stolen = std::max<std::int64_t>(0, dma_at_end(end, start) - dma_before) *
                                  timing::kLinkDmaCyclesPerByte;
      stats_.stolen_cycles += stolen;
      remaining += cycles(stolen);
    }
  }
}

}  // namespace t800
