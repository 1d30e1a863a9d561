// Straight-line code, decoded once and timed once for each way it runs. A block is the run of
// instructions from an address up to the first that may leave it (a process switch, a link or timer
// instruction); a jump, a loop end, a call, a return, a conditional jump, or an instruction whose
// time depends on its operands (a shift, prod, move) may end it. The core still executes every
// instruction of a block (their effects are the program's); what it saves is the timing. The timing
// rule is deterministic: the same instructions, started from equal timing contexts
// (timing_stepper.hpp) with their data in the same places and their operands of the same precision,
// take the same cycles. So a block remembers the outcome of the last few ways it ran and replays
// one when it recurs, cycle for cycle what stepping every instruction gives
// (tests/iss/block_engine_test.cpp holds the two together).
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "t800/iss/decoder.hpp"
#include "t800/processors/processor_model.hpp"
#include "t800/processors/timing_stepper.hpp"

namespace t800::iss {

struct BlockInstruction {
  Decoded decoded;
  std::uint16_t offset = 0;  // of its first byte, from the block's start
};

// One way a block ran, timed: the context it began in, its instructions' variants (see Block) and
// its last one's timing parameter (a cj taken, places shifted, words moved), the IU's cycles from
// its start to its end, the context it left and the totals it added.
struct BlockTiming {
  bool valid = false;
  std::uint64_t variants = 0;
  std::int64_t last_param = 0;
  TimingContext entry, exit;
  std::int64_t cycles = 0;
  std::int64_t last_start = 0;  // from the block's start to its last instruction's
  StepTotals added;
};

struct Block {
  static constexpr int kMaxInstructions = 24;
  static constexpr int kTimings = 4;
  // Variants: instruction i's data in external memory is bit 2i, REAL64 operands bit 2i + 1.
  static std::uint64_t variant(int index, bool data_external, bool real64) {
    return std::uint64_t(int(data_external) | int(real64) << 1) << (2 * index);
  }

  Word start = 0;
  std::uint32_t span = 0;  // its code's bytes
  bool code_external = false;
  int size = 0;  // 0: the code at `start` is not straight-line (the core steps it)
  // Its last instruction is a timeslice point (j, lend): it reads the clock when it starts, so it
  // executes once the cycle it starts at is known.
  bool ends_at_timeslice_point = false;
  // The cycles from the block's start to its last instruction's are at most this plus the entry
  // context's waits (the FPU's, the bus's, the buffered code's): each cycle is the IU working, or
  // waiting for the FPU (at most the FPU's work before it), or for the bus (at most every access
  // it makes). The last instruction's own time does not count: stepping stops before an
  // instruction, not inside one.
  std::int64_t bound = 0;
  std::array<BlockInstruction, kMaxInstructions> instructions;
  std::array<BlockTiming, kTimings> timings;
  int next_timing = 0;

  std::int64_t origin_word() const { return std::int64_t(start) / 4; }
  const BlockTiming* timing(const TimingContext& entry, std::uint64_t variants,
                            std::int64_t last_param) const {
    for (const BlockTiming& t : timings)
      if (t.valid && t.variants == variants && t.last_param == last_param && t.entry == entry)
        return &t;
    return nullptr;
  }
  // A remembered timing from `entry` whose instructions before the last ran as `variants` says:
  // the last starts as it did then (an instruction's timing depends only on those before it).
  const BlockTiming* timing_before_last(const TimingContext& entry, std::uint64_t variants) const {
    const std::uint64_t before_last = (std::uint64_t(1) << (2 * (size - 1))) - 1;
    for (const BlockTiming& t : timings)
      if (t.valid && (t.variants & before_last) == variants && t.entry == entry) return &t;
    return nullptr;
  }
  // The slot for a new way of running it (the oldest is forgotten).
  BlockTiming& new_timing();
};

// How many blocks ran replayed and how many were timed instruction by instruction.
struct BlockCounts {
  std::int64_t decoded = 0;       // blocks decoded (again, after their code was written)
  std::int64_t replayed = 0;      // runs whose timing was a remembered one
  std::int64_t timed = 0;         // runs stepped through the timing rule (new ways, cut short)
  std::int64_t instructions = 0;  // executed in blocks (the rest were stepped one by one)
};

class BlockCache {
 public:
  // `access_cycles`: one external memory access, wait states included. The cache takes over
  // `memory`'s code-written hook and passes each line on to `decoded` too.
  BlockCache(DecodeCache& decoded, Memory& memory, const ProcessorModel& processor,
             int access_cycles);
  BlockCache(const BlockCache&) = delete;
  BlockCache& operator=(const BlockCache&) = delete;

  // The block starting at `iptr`, decoded if it is not cached or its code was written since.
  Block& at(Word iptr) {
    Slot& slot = slots_[iptr & kMask];
    if (slot.live && slot.start == iptr) return *slot.block;
    return decode(slot, iptr);
  }
  // Counts what ends a running block after its current instruction (it checks the count after
  // each): a block forgotten because its code was written, a halt, Error set under HaltOnError.
  std::uint64_t stops() const { return stops_; }
  void stop_running_block() { ++stops_; }
  BlockCounts& counts() { return counts_; }
  const BlockCounts& counts() const { return counts_; }

 private:
  static constexpr std::uint32_t kSlots = 1u << 12, kMask = kSlots - 1;
  // The tag beside the pointer, so that a hit reads one cache line.
  struct Slot {
    Word start = 0;
    bool live = false;
    std::unique_ptr<Block> block;
  };
  Block& decode(Slot& slot, Word iptr);
  // The line at `line_offset` was written: every block with code in it is forgotten.
  void invalidate_line(std::uint32_t line_offset);
  // Whether `op` may be a block's instruction (`last`: may end one).
  bool replayable(isa::Op op, bool& last) const;
  std::int64_t bound_of(const Decoded& d) const;

  DecodeCache& decoded_;
  const Memory& memory_;
  const InstructionTimingTable& table_;
  int access_cycles_;
  std::vector<Slot> slots_;
  std::uint32_t longest_span_ = 0;  // of any block decoded: how far before a line to look
  std::uint64_t stops_ = 0;
  BlockCounts counts_;
};

}  // namespace t800::iss
