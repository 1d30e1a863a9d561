#include "t800/iss/core.hpp"

#include <fmt/format.h>

#include "t800/iss/execute.hpp"
#include "t800/timing_table.hpp"

namespace t800::iss {

using isa::Op;

Core::Core(const CoreConfig& config)
    : processor_(*config.processor),
      memory_(config.processor->on_chip_bytes, config.installed_bytes, config.policy),
      decoded_(memory_),
      stepper_(*config.processor->timing,
               config.processor->external_access_cycles + config.wait_states, false),
      blocks_(decoded_, memory_, *config.processor,
              config.processor->external_access_cycles + config.wait_states),
      blocks_on_(config.blocks),
      timeslice_cycles_(
          std::int64_t(timing::kTimesliceUs * 1000.0 / config.processor->cycle_ns + 0.5)),
      interrupt_latency_(timing::kInterruptLatencyTypical) {
  // Reset: the link and event channels, the timer queues and the save area hold NotProcess.p (the
  // primary bootstrap writes them again, t800-iss.md).
  for (Word a = kLinkOutput0; a <= kTimerQueueLow; a += 4) memory_.set_word(a, kNotProcess);
  memory_.set_word(kSaveWdesc, kNotProcess);
}

void Core::start_process(Word iptr, Word wptr, int priority) {
  memory_.set_word(slot_of(wptr, kSlotIptr), iptr);
  schedule(wptr | Word(priority));
  if (!running_) next_process();
}

void Core::start_boot_program(Word length, int boot_link) {
  // The workspace starts just above the loaded code, word aligned (t4 main.c does the same).
  const Word code_end = mem_start() + length;
  const Word wptr = (code_end + 3) & ~3u;
  r_.wptr = wptr;
  r_.priority = kLow;
  r_.iptr = mem_start();
  r_.c = kLinkInput0 + Word(4 * boot_link);
  r_.b = r_.a = 0;
  running_ = true;
  slice_start_ = cycle();
  control_moved();
}

StopReason Core::run(std::int64_t until, std::int64_t max_instructions) {
  const std::int64_t last = instructions_ + max_instructions;
  // Under strict addressing the scheduler's own accesses (a queue's front, a timer's workspace)
  // and the instruction fetch may fault too, not only an instruction's operands.
  while (!halt_) {
    try {
      if (cycle() >= next_timer_) fire_timers();
      if (!running_) {
        next_process();
        if (!running_) return StopReason::idle;
      }
      if (cycle() >= until) return StopReason::running;
      if (instructions_ >= last) return StopReason::limit;
      // Inside a block being stepped a block starting here would be decoded for nothing (and, in
      // short slices, one at every instruction).
      const bool inside_stepped = r_.iptr > stepping_from_ && r_.iptr < stepping_to_;
      if (inside_stepped || !run_block(std::min(until, next_timer_), last))
        step(decoded_.at(r_.iptr));
    } catch (const MemoryFault& fault) {
      memory_fault(fault, r_.iptr);
    }
    if (sync_requested_) {
      sync_requested_ = false;
      if (!halt_) return StopReason::sync;
    }
  }
  return StopReason::halted;
}

void Core::step(const Decoded& d) {
  const Word at = r_.iptr;
  if (!d.defined || !processor_.timing->has(d.op)) [[unlikely]] {
    refuse(d);
    return;
  }
  TimedStep t;
  t.op = d.op;
  t.prefix_cycles = d.prefix_cycles;
  t.bytes = d.bytes;
  t.address = at;
  stepper_.set_code_external(memory_.external(at));
  r_.iptr = at + d.bytes;
  stepping_ = true;
  try {
    execute(d, t);
  } catch (const MemoryFault& fault) {
    stepping_ = moved_ = false;
    r_.iptr = at;
    memory_fault(fault, at);
    return;
  }
  stepping_ = false;
  ++instructions_;
  const std::int64_t issued = stepper_.iu_free();
  stepper_.step(t);
  if (profile_) [[unlikely]]
    profile_->record(d.op, at, stepper_.iu_free() - issued);
  if (moved_) {
    moved_ = false;
    stepper_.restart_fetch();
    stepping_to_ = 0;  // wherever control went, a block may start there
  }
  if (r_.error && r_.halt_on_error && !halt_) [[unlikely]]
    halt("HaltOnError: Error set by " + error_by_, at);
}

// Out of line (it formats messages): step() runs for every instruction.
void Core::refuse(const Decoded& d) {
  if (!d.defined)
    undefined(d, d.op == Op::pfix || d.op == Op::nfix
                     ? fmt::format("a prefix chain of {} bytes or more", kMaxInstructionBytes)
                     : fmt::format("undefined operation #{:X}", d.operand));
  else
    undefined(d, fmt::format("{} is not an instruction of the {}", isa::mnemonic(d.op),
                             processor_.timing->family));
}

void Core::undefined(const Decoded&, const std::string& what) {
  halt(what, r_.iptr);
}

void Core::memory_fault(const MemoryFault& fault, Word iptr) {
  halt(fmt::format("memory fault: {} (strict addressing)", fault.what()), iptr);
}

bool Core::block_fits(Word count, std::string_view what) {
  if (std::int64_t(count) <= memory_.installed_bytes()) return true;
  halt(fmt::format("{} of {} bytes, more than the {} bytes of installed memory", what, count,
                   memory_.installed_bytes()),
       r_.iptr - 1);
  return false;
}

void Core::halt(const std::string& reason, Word iptr) {
  HaltReport h;
  h.reason = reason;
  h.iptr = iptr;
  try {  // the instruction's bytes, as far as they can be read (strict: maybe not at all)
    const Decoded d = decode(memory_, iptr);
    for (int k = 0; k < std::max<int>(1, d.bytes); ++k)
      h.bytes.push_back(memory_.byte(iptr + Word(k)));
  } catch (const MemoryFault&) {
  }
  h.registers = r_;
  h.registers.iptr = iptr;
  halt_ = h;
  running_ = false;
  blocks_.stop_running_block();
}

void Core::set_error(const char* by) {
  r_.error = true;
  error_by_ = by;
  if (r_.halt_on_error) blocks_.stop_running_block();
}

}  // namespace t800::iss
