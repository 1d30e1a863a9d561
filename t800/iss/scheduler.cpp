// The T800's microcoded scheduler, with its state where the chip keeps it: the two process queues'
// front and back registers, each waiting process's Iptr and queue link in the words below its
// workspace, the timer queues in memory ordered by time, the interrupted low-priority process's
// registers in the save area (CWG; T800 datasheet; t800-iss.md).
#include <algorithm>
#include <cmath>

#include "t800/iss/core.hpp"

namespace t800::iss {

namespace {
constexpr double kTickNs[2] = {1000.0, 64000.0};  // high: 1 us, low: 64 us (T800 datasheet)
Word timer_queue(int priority) {
  return priority == kHigh ? kTimerQueueHigh : kTimerQueueLow;
}
}  // namespace

void Core::enqueue(Word wdesc) {
  const int p = int(wdesc & 1);
  const Word wptr = wdesc & ~3u;
  if (r_.fptr[p] == kNotProcess)
    r_.fptr[p] = wptr;
  else
    memory_.set_word(slot_of(r_.bptr[p], kSlotLink), wptr);
  r_.bptr[p] = wptr;
}

void Core::schedule(Word wdesc) {
  const int p = int(wdesc & 1);
  unblocked(wdesc & ~3u);
  if (running_ && r_.priority == kLow && p == kHigh) {
    // A high-priority process preempts the low-priority one at once, after the interrupt
    // latency (T800 datasheet; docs/t800-timing.md section 7).
    interrupt_low();
    enqueue(wdesc);
    next_process();
    return;
  }
  enqueue(wdesc);
}

void Core::interrupt_low() {
  memory_.set_word(kSaveWdesc, r_.wdesc());
  memory_.set_word(kSaveIptr, r_.iptr);
  memory_.set_word(kSaveA, r_.a);
  memory_.set_word(kSaveB, r_.b);
  memory_.set_word(kSaveC, r_.c);
  memory_.set_word(kSaveStatus, (r_.error ? 1u : 0u) | (r_.halt_on_error ? 2u : 0u));
  saved_low_fpu_ = fpu_;
  low_interrupted_ = true;
  running_ = false;
  stepper_.wait_until(cycle() + interrupt_latency_);
}

void Core::deschedule(const char* what, Word channel) {
  set_ws(kSlotIptr, r_.iptr);
  waiting_[r_.wptr] = {r_.wdesc(), r_.iptr, channel, what};
  running_ = false;
}

bool Core::run_next_from_queue(int p) {
  const Word wptr = r_.fptr[p];
  if (wptr == kNotProcess) return false;
  r_.fptr[p] = wptr == r_.bptr[p] ? kNotProcess : memory_.word(slot_of(wptr, kSlotLink));
  r_.wptr = wptr;
  r_.priority = p;
  r_.iptr = memory_.word(slot_of(wptr, kSlotIptr));
  running_ = true;
  if (p == kLow) slice_start_ = cycle();
  control_moved();
  return true;
}

void Core::next_process() {
  if (run_next_from_queue(kHigh)) return;
  if (low_interrupted_) {
    const Word wdesc = memory_.word(kSaveWdesc);
    r_.wptr = wdesc & ~3u;
    r_.priority = kLow;
    r_.iptr = memory_.word(kSaveIptr);
    r_.a = memory_.word(kSaveA);
    r_.b = memory_.word(kSaveB);
    r_.c = memory_.word(kSaveC);
    fpu_ = saved_low_fpu_;
    memory_.set_word(kSaveWdesc, kNotProcess);
    low_interrupted_ = false;
    running_ = true;
    control_moved();
    return;
  }
  run_next_from_queue(kLow);
}

bool Core::idle() const {
  return !running_ && r_.fptr[kHigh] == kNotProcess && r_.fptr[kLow] == kNotProcess &&
         !low_interrupted_;
}

// A low-priority process is timesliced at a j or lend once two timeslice ticks have passed since
// it was dispatched, if another low-priority process is waiting (NB; docs/t800-timing.md 7).
void Core::timeslice_point() {
  if (r_.priority != kLow || r_.fptr[kLow] == kNotProcess) return;
  const std::int64_t now = cycle() + slice_clock_ahead_;
  if (now / timeslice_cycles_ - slice_start_ / timeslice_cycles_ < 2) return;
  set_ws(kSlotIptr, r_.iptr);
  enqueue(r_.wdesc());
  running_ = false;
}

Word Core::clock(int priority) const {
  if (!timers_running_) return clock_base_[priority];
  const double elapsed = double(cycle()) * processor_.cycle_ns - clock_base_ns_;
  const auto ticks = std::int64_t(std::floor(elapsed / kTickNs[priority] + 1e-9));
  return clock_base_[priority] + Word(std::uint64_t(ticks));
}

// Inserts the running process into its priority's timer queue, ordered by due time: it is due
// when the clock reaches `due` (tin waits for a clock AFTER its time, so it passes time + 1).
void Core::insert_timer(Word due) {
  const int p = r_.priority;
  const Word head = timer_queue(p);
  set_ws(kSlotTime, due);
  Word previous = 0, at = memory_.word(head);
  while (at != kNotProcess && !after(memory_.word(slot_of(at, kSlotTime)), due)) {
    previous = at;
    at = memory_.word(slot_of(at, kSlotTLink));
  }
  set_ws(kSlotTLink, at);
  memory_.set_word(previous ? slot_of(previous, kSlotTLink) : head, r_.wptr);
  refresh_next_timer();
}

void Core::remove_timer(Word wptr, int priority) {
  const Word head = timer_queue(priority);
  Word previous = 0, at = memory_.word(head);
  while (at != kNotProcess) {
    const Word next = memory_.word(slot_of(at, kSlotTLink));
    if (at == wptr) {
      memory_.set_word(previous ? slot_of(previous, kSlotTLink) : head, next);
      refresh_next_timer();
      return;
    }
    previous = at;
    at = next;
  }
}

void Core::fire_timers() {
  for (int p : {kHigh, kLow}) {
    const Word head = timer_queue(p);
    for (Word at = memory_.word(head); at != kNotProcess; at = memory_.word(head)) {
      if (after(memory_.word(slot_of(at, kSlotTime)), clock(p))) break;
      memory_.set_word(head, memory_.word(slot_of(at, kSlotTLink)));
      // A timer ALT waiting: its time guard is now ready.
      if (memory_.word(slot_of(at, kSlotState)) == kWaiting)
        memory_.set_word(slot_of(at, kSlotState), kReady);
      schedule(at | Word(p));
    }
  }
  refresh_next_timer();
}

std::int64_t Core::ns_to_cycle_ceiling(double ns) const {
  return std::int64_t(std::ceil(ns / processor_.cycle_ns - 1e-9));
}

void Core::refresh_next_timer() {
  next_timer_ = std::numeric_limits<std::int64_t>::max();
  if (!timers_running_) return;
  const double now_ns = double(cycle()) * processor_.cycle_ns - clock_base_ns_;
  for (int p : {kHigh, kLow}) {
    const Word at = memory_.word(timer_queue(p));
    if (at == kNotProcess) continue;
    const std::int32_t ahead = std::int32_t(memory_.word(slot_of(at, kSlotTime)) - clock(p));
    if (ahead <= 0) {
      next_timer_ = cycle();
      return;
    }
    const auto ticks_now = std::int64_t(std::floor(now_ns / kTickNs[p] + 1e-9));
    const double due_ns = double(ticks_now + ahead) * kTickNs[p] + clock_base_ns_;
    next_timer_ = std::min(next_timer_, ns_to_cycle_ceiling(due_ns));
  }
}

std::optional<std::int64_t> Core::next_timer_cycle() const {
  if (next_timer_ == std::numeric_limits<std::int64_t>::max()) return std::nullopt;
  return next_timer_;
}

void Core::advance_to(std::int64_t target) {
  if (target > cycle()) stepper_.wait_until(target);
  try {
    if (cycle() >= next_timer_) fire_timers();
  } catch (const MemoryFault& fault) {
    memory_fault(fault, r_.iptr);
  }
}

std::vector<WaitingProcess> Core::waiting() const {
  std::vector<WaitingProcess> all;
  for (const auto& [wptr, w] : waiting_) all.push_back(w);
  std::sort(all.begin(), all.end(),
            [](const WaitingProcess& a, const WaitingProcess& b) { return a.wdesc < b.wdesc; });
  return all;
}

}  // namespace t800::iss
