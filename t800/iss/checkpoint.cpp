// Core::checkpoint: the state a run changes, kept to go back to. Memory keeps its own undo log
// (memory.hpp); the decode and block caches follow memory (an undone write to cached code
// invalidates it as any write does), and their counts are kept here so that undone work is not
// reported as done.
#include "t800/iss/core.hpp"

namespace t800::iss {

// The one list of what a checkpoint keeps: `keep(member, kept)` for each.
template <class Keep>
void Core::each_kept(Checkpoint& c, Keep keep) {
  keep(stepper_, c.stepper);
  keep(blocks_.counts(), c.block_counts);
  keep(stepping_from_, c.stepping_from);
  keep(stepping_to_, c.stepping_to);
  keep(r_, c.registers);
  keep(fpu_, c.fpu);
  keep(saved_low_fpu_, c.saved_low_fpu);
  keep(instructions_, c.instructions);
  keep(running_, c.running);
  keep(low_interrupted_, c.low_interrupted);
  keep(timers_running_, c.timers_running);
  keep(j0_break_, c.j0_break);
  keep(clock_base_[0], c.clock_base[0]);
  keep(clock_base_[1], c.clock_base[1]);
  keep(clock_base_ns_, c.clock_base_ns);
  keep(next_timer_, c.next_timer);
  keep(slice_start_, c.slice_start);
  keep(slice_clock_ahead_, c.slice_clock_ahead);
  keep(move2d_length_, c.move2d_length);
  keep(move2d_dest_stride_, c.move2d_dest_stride);
  keep(move2d_source_stride_, c.move2d_source_stride);
  keep(waiting_, c.waiting);
  keep(halt_, c.halt);
  keep(error_by_, c.error_by);
}

void Core::checkpoint() {
  checkpoint_ = std::make_unique<Checkpoint>(stepper_);
  each_kept(*checkpoint_, [](const auto& member, auto& kept) { kept = member; });
  memory_.start_undo_log();
}

void Core::rollback() {
  if (!checkpoint_) return;
  memory_.undo();
  each_kept(*checkpoint_, [](auto& member, auto& kept) { member = std::move(kept); });
  sync_requested_ = stepping_ = moved_ = false;
  checkpoint_.reset();
}

void Core::commit() {
  memory_.drop_undo_log();
  checkpoint_.reset();
}

}  // namespace t800::iss
