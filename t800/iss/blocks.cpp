#include "t800/iss/blocks.hpp"

#include <algorithm>

namespace t800::iss {

using isa::Op;

BlockTiming& Block::new_timing() {
  BlockTiming& t = timings[std::size_t(next_timing)];
  next_timing = (next_timing + 1) % kTimings;
  t = BlockTiming{};
  return t;
}

BlockCache::BlockCache(DecodeCache& decoded, Memory& memory, const ProcessorModel& processor,
                       int access_cycles)
    : decoded_(decoded),
      memory_(memory),
      table_(*processor.timing),
      access_cycles_(access_cycles),
      slots_(kSlots) {
  memory.on_code_written([this](std::uint32_t line) {
    decoded_.invalidate_line(line);
    invalidate_line(line);
  });
}

// Only the blocks with code in the line, not all: programs write data that shares a line with
// code (a workspace just above it), and forgetting every block at each such write would decode
// them all again and again. A block starts at most longest_span_ bytes before the line; the
// slots are indexed by address, and their tags say whether the block there is one of them.
void BlockCache::invalidate_line(std::uint32_t line_offset) {
  constexpr std::uint32_t line_bytes = 1u << Memory::kLineShift;
  const std::uint32_t look = std::min(longest_span_ + line_bytes, kSlots);
  const Word first = kMostNeg + line_offset - Word(longest_span_);
  for (std::uint32_t k = 0; k < look; ++k) {
    Slot& s = slots_[(first + k) & kMask];
    // A block of no code (its start past the installed memory) has no line to be written.
    if (!s.live || s.block->span == 0) continue;
    const std::uint32_t start = memory_.offset(s.start);
    if (start < line_offset + line_bytes && start + s.block->span > line_offset) {
      s.live = false;
      ++stops_;
    }
  }
}

// The instructions whose effects stay inside the processor's registers and memory: they neither
// move control nor switch processes (but the last: call, cj, gcall, ret, and j and lend, where a
// timeslice may be taken), nor touch the links, the timers or the clock. One whose time depends on
// its operands (the table says so: cycles per place shifted or word moved, a second figure for a
// branch taken) may be the last too, its parameter part of the timing's key.
bool BlockCache::replayable(Op op, bool& last) const {
  const InstructionTiming& row = table_[op];
  if (!row.defined) return false;
  last = row.per_param != 0 || row.data_words_per_param != 0 || row.when_set != 0;
  switch (op) {
    case Op::j:
    case Op::lend:
    case Op::cj:
    case Op::call:
    case Op::gcall:
    case Op::ret:
    case Op::move:
      last = true;
      return true;
    case Op::ldlp:
    case Op::ldnl:
    case Op::ldc:
    case Op::ldnlp:
    case Op::ldl:
    case Op::adc:
    case Op::ajw:
    case Op::eqc:
    case Op::stl:
    case Op::stnl:
    case Op::rev:
    case Op::lb:
    case Op::sb:
    case Op::bsub:
    case Op::wsub:
    case Op::wsubdb:
    case Op::bcnt:
    case Op::wcnt:
    case Op::diff:
    case Op::sum:
    case Op::prod:
    case Op::add:
    case Op::sub:
    case Op::mul:
    case Op::div:
    case Op::rem:
    case Op::fmul:
    case Op::gt:
    case Op::and_:
    case Op::or_:
    case Op::xor_:
    case Op::not_:
    case Op::shl:
    case Op::shr:
    case Op::mint:
    case Op::dup:
    case Op::pop:
    case Op::xdble:
    case Op::xword:
    case Op::cword:
    case Op::csngl:
    case Op::csub0:
    case Op::ccnt1:
    case Op::ladd:
    case Op::lsub:
    case Op::lsum:
    case Op::ldiff:
    case Op::lmul:
    case Op::ldiv:
    case Op::bitcnt:
    case Op::bitrevword:
    case Op::ldpi:
    case Op::ldpri:
    case Op::seterr:
    case Op::ldmemstartval:
      return true;
    default:
      // The FPU's operations, but fpentry itself (its operation is a run-time value).
      return op >= Op::fpldnlsn && op <= Op::fpudivby2 && op != Op::fpentry;
  }
}

// The most cycles an instruction can add to a block, whatever waits before it, its code's fetch
// aside: its prefixes and its slowest figure, as much again for an FPU operation the next may wait
// for, and a bus access for each data word (in external memory or not).
std::int64_t BlockCache::bound_of(const Decoded& d) const {
  const InstructionTiming& row = table_[d.op];
  const std::int64_t slowest = std::max({row.cycles, row.cycles_double, row.when_set});
  const std::int64_t fpu = row.unit == Unit::integer ? 0 : slowest;
  return d.prefix_cycles + slowest + fpu + std::int64_t(row.data_words) * access_cycles_;
}

Block& BlockCache::decode(Slot& slot, Word iptr) {
  if (!slot.block) slot.block = std::make_unique<Block>();
  slot.start = iptr;
  slot.live = true;
  Block& b = *slot.block;
  ++counts_.decoded;
  b.start = iptr;
  b.size = 0;
  b.span = 0;
  b.bound = 0;
  b.ends_at_timeslice_point = false;
  b.timings = {};
  b.next_timing = 0;
  std::int64_t last_bound = 0;
  try {
    b.code_external = memory_.external(iptr);
    Word at = iptr;
    while (b.size < Block::kMaxInstructions && memory_.external(at) == b.code_external) {
      const Decoded& d = decoded_.at(at);
      bool last = false;
      if (!d.defined || !replayable(d.op, last)) {
        // Not straight-line code (yet): forgotten too if it is written.
        if (b.size == 0) b.span = std::max<std::uint32_t>(1, d.bytes);
        break;
      }
      b.instructions[std::size_t(b.size++)] = {d, std::uint16_t(at - iptr)};
      last_bound = bound_of(d);
      b.bound += last_bound;
      at += d.bytes;
      b.span = at - iptr;
      if (last) {
        b.ends_at_timeslice_point = d.op == Op::j || d.op == Op::lend;
        break;
      }
    }
  } catch (const MemoryFault&) {
    // Past the installed memory (strict addressing): the block ends before it; stepping the
    // instruction there reports the fault.
  }
  b.bound -= last_bound;  // the last instruction need only start in time (Block::bound)
  // Straight-line code fetches each of its words once (the first and last may be partial).
  if (b.code_external) b.bound += (std::int64_t(b.span) / 4 + 2) * access_cycles_;
  longest_span_ = std::max(longest_span_, b.span);
  return b;
}

}  // namespace t800::iss
