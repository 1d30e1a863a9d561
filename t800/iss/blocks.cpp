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

BlockCache::BlockCache(DecodeCache& decoded, const Memory& memory, const ProcessorModel& processor,
                       int access_cycles)
    : decoded_(decoded),
      memory_(memory),
      table_(*processor.timing),
      access_cycles_(access_cycles),
      slots_(kSlots) {}

// The instructions whose effects stay inside the processor's registers and memory: they neither
// move control (but the last: call, cj, gcall, ret), nor switch processes, nor touch the links, the
// timers or the clock. Whether their time depends on their operands is the table's to say.
bool BlockCache::replayable(Op op, bool& last) const {
  last = false;
  const InstructionTiming& row = table_[op];
  if (!row.defined || row.per_param != 0 || row.data_words_per_param != 0) return false;
  switch (op) {
    case Op::cj:
    case Op::call:
    case Op::gcall:
    case Op::ret:
      last = true;
      return op == Op::cj || row.when_set == 0;  // cj's taken figure is a variant
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
      return row.when_set == 0;
    default:
      // The FPU's operations, but fpentry itself (its operation is a run-time value).
      return op >= Op::fpldnlsn && op <= Op::fpudivby2 && op != Op::fpentry && row.when_set == 0;
  }
}

// The most cycles an instruction can add to a block, whatever waits before it: its prefixes and its
// slowest figure, as much again for an FPU operation the next may wait for, and every bus access it
// or its code may need.
std::int64_t BlockCache::bound_of(const Decoded& d) const {
  const InstructionTiming& row = table_[d.op];
  const std::int64_t slowest = std::max({row.cycles, row.cycles_double, row.when_set});
  const std::int64_t fpu = row.unit == Unit::integer ? 0 : slowest;
  const std::int64_t accesses = row.data_words + d.bytes / 4 + 2;
  return d.prefix_cycles + slowest + fpu + accesses * access_cycles_;
}

Block& BlockCache::decode(Slot& slot, Word iptr) {
  if (!slot.block) slot.block = std::make_unique<Block>();
  slot.start = iptr;
  slot.generation = decoded_.generation();
  Block& b = *slot.block;
  ++counts_.decoded;
  b.start = iptr;
  b.generation = decoded_.generation();
  b.size = 0;
  b.bound = 2 * std::int64_t(access_cycles_);
  b.timings = {};
  b.next_timing = 0;
  try {
    b.code_external = memory_.external(iptr);
    Word at = iptr;
    while (b.size < Block::kMaxInstructions && memory_.external(at) == b.code_external) {
      const Decoded& d = decoded_.at(at);
      bool last = false;
      if (!d.defined || !replayable(d.op, last)) break;
      b.instructions[std::size_t(b.size++)] = {d, std::uint16_t(at - iptr)};
      b.bound += bound_of(d);
      at += d.bytes;
      if (last) break;
    }
  } catch (const MemoryFault&) {
    // Past the installed memory (strict addressing): the block ends before it; stepping the
    // instruction there reports the fault.
  }
  // Decoding may have written the decode cache's slots but never memory: the generation stands.
  return b;
}

}  // namespace t800::iss
