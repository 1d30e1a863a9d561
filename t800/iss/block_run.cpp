// Running a block (blocks.hpp): every instruction executed as step() executes it, the timing
// replayed when the block ran this way before, stepped and remembered when not.
#include <algorithm>
#include <optional>

#include "t800/iss/core.hpp"
#include "t800/iss/execute.hpp"

namespace t800::iss {

[[gnu::always_inline]] inline bool Core::execute_block(const Block& b, int to, std::uint64_t stops,
                                                       int& done, std::uint64_t& variants,
                                                       TimedStep& t) {
  while (done < to) {
    const BlockInstruction& in = b.instructions[std::size_t(done)];
    r_.iptr = b.start + in.offset + in.decoded.bytes;
    t.param = 0;
    t.data_external = t.real64 = false;
    execute(in.decoded, t);
    variants |= Block::variant(done, t.data_external, t.real64);
    ++done;
    // Stop where step() would see a difference: a halt, Error set under HaltOnError, code
    // written (the rest is decoded afresh).
    if (blocks_.stops() != stops) [[unlikely]]
      return false;
  }
  return true;
}

[[gnu::always_inline]] inline bool Core::run_one_block(std::int64_t before, std::int64_t last) {
  Block& b = blocks_.at(r_.iptr);
  if (b.size == 0) return false;
  // Declined: its instructions are stepped, and none of them starts a block of its own.
  const auto decline = [&] {
    stepping_from_ = b.start;
    stepping_to_ = b.start + b.span;
    return false;
  };
  const std::int64_t entry = cycle();
  // The check below, before taking a context for nothing.
  if (entry + b.bound >= before) return decline();
  stepper_.set_code_external(b.code_external);
  TimingContext context;
  const bool captured = stepper_.context(b.origin_word(), context);
  // Every instruction of the block must start before `before` (the cycle bound, the next timer),
  // as step() would have been asked to stop there, and within the instruction budget.
  const std::int32_t code_wait =
      *std::max_element(context.code_ready.begin(), context.code_ready.end());
  if (!captured || instructions_ + b.size > last ||
      entry + b.bound + context.fpu + context.bus + code_wait >= before)
    return decline();

  const std::uint64_t stops = blocks_.stops();
  std::uint64_t variants = 0;
  int done = 0;
  int timed = 0;                     // instructions already stepped through the timing rule
  std::optional<StepTotals> totals;  // the stepper's, before it stepped them
  TimedStep t;
  stepping_ = true;
  try {
    const int before_last = b.size - int(b.ends_at_timeslice_point);
    if (execute_block(b, before_last, stops, done, variants, t) && done < b.size) {
      // A timeslice point reads the clock: when it starts is remembered, or stepped to.
      if (const BlockTiming* known = b.timing_before_last(context, variants)) {
        slice_clock_ahead_ = known->last_start;
      } else {
        totals = stepper_.totals();
        time_block(b, 0, before_last, variants, 0);
        timed = before_last;
      }
      execute_block(b, b.size, stops, done, variants, t);
      slice_clock_ahead_ = 0;
    }
  } catch (const MemoryFault& fault) {
    // As step(): the faulting instruction neither counts nor is timed.
    stepping_ = moved_ = false;
    slice_clock_ahead_ = 0;
    const Word at = b.start + b.instructions[std::size_t(done)].offset;
    instructions_ += done;
    time_block(b, timed, done, variants, 0);
    r_.iptr = at;
    memory_fault(fault, at);
    return true;
  }
  stepping_ = false;
  instructions_ += done;
  blocks_.counts().instructions += done;
  const std::int64_t last_param = done == b.size ? t.param : 0;

  const BlockTiming* known =
      done == b.size && timed == 0 ? b.timing(context, variants, last_param) : nullptr;
  if (known) {
    stepper_.resume(known->exit, entry + known->cycles, b.origin_word(), known->added);
    moved_ = false;
    ++blocks_.counts().replayed;
  } else {
    ++blocks_.counts().timed;
    if (!totals) totals = stepper_.totals();
    time_block(b, timed, std::min(done, b.size - 1), variants, 0);
    const std::int64_t last_start = cycle() - entry;
    time_block(b, std::max(timed, b.size - 1), done, variants, last_param);
    if (moved_) {
      moved_ = false;
      stepper_.restart_fetch();
    }
    if (done == b.size) {
      BlockTiming& remembered = b.new_timing();
      remembered.variants = variants;
      remembered.last_param = last_param;
      remembered.entry = context;
      remembered.cycles = cycle() - entry;
      remembered.last_start = last_start;
      remembered.added = stepper_.totals() - *totals;
      remembered.valid = stepper_.context(b.origin_word(), remembered.exit);
    }
  }
  if (r_.error && r_.halt_on_error && !halt_) [[unlikely]]
    halt("HaltOnError: Error set by " + error_by_,
         b.start + b.instructions[std::size_t(done - 1)].offset);
  return true;
}

bool Core::run_block(std::int64_t before, std::int64_t last) {
  // A profile wants every instruction's own cycles.
  if (!blocks_on_ || profile_) return false;
  // From one block straight to the next while nothing the run loop looks at between instructions
  // has changed (a process switch, a halt, a synchronisation asked for).
  bool ran = false;
  while (run_one_block(before, last)) {
    ran = true;
    if (!running_ || halt_ || sync_requested_) break;
  }
  return ran;
}

void Core::time_block(const Block& b, int from, int to, std::uint64_t variants,
                      std::int64_t last_param) {
  for (int i = from; i < to; ++i) {
    const BlockInstruction& in = b.instructions[std::size_t(i)];
    TimedStep t;
    t.op = in.decoded.op;
    t.prefix_cycles = in.decoded.prefix_cycles;
    t.bytes = in.decoded.bytes;
    t.address = b.start + in.offset;
    t.data_external = (variants >> (2 * i)) & 1;
    t.real64 = (variants >> (2 * i + 1)) & 1;
    if (i == b.size - 1) t.param = last_param;
    stepper_.step(t);
  }
}

}  // namespace t800::iss
