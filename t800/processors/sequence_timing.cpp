#include "t800/processors/sequence_timing.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace t800 {

using isa::Encoding;
using isa::Instruction;

bool MemoryView::external(const isa::MemoryRef& ref) const {
  switch (ref.region) {
    case isa::Region::none:
      return false;
    case isa::Region::workspace:
      return workspace_external;
    case isa::Region::code:
      return code_external;
    case isa::Region::library:
      return library_external;
    case isa::Region::array:
      return ref.array >= 0 && std::size_t(ref.array) < array_external.size() &&
             array_external[std::size_t(ref.array)];
  }
  return false;
}

bool MemoryView::operator==(const MemoryView& o) const {
  return workspace_external == o.workspace_external && code_external == o.code_external &&
         library_external == o.library_external && array_external == o.array_external &&
         external_cycles == o.external_cycles;
}

SequenceTime& SequenceTime::operator+=(const SequenceTime& o) {
  cycles += o.cycles;
  iu_busy += o.iu_busy;
  fpu_busy += o.fpu_busy;
  fpu_waits += o.fpu_waits;
  fetch_waits += o.fetch_waits;
  memory_cycles += o.memory_cycles;
  bytes += o.bytes;
  instructions += o.instructions;
  return *this;
}

SequenceTime SequenceTime::repeated(std::int64_t times) const {
  SequenceTime t;
  t.cycles = cycles * times;
  t.iu_busy = iu_busy * times;
  t.fpu_busy = fpu_busy * times;
  t.fpu_waits = fpu_waits * times;
  t.fetch_waits = fetch_waits * times;
  t.memory_cycles = memory_cycles * times;
  t.bytes = bytes * times;
  t.instructions = instructions * times;
  return t;
}

namespace {

// The one external memory bus, shared by instruction fetches and data accesses.
struct Bus {
  std::int64_t free_at = 0;
  int access_cycles;
  // `words` accesses requested at `at`, one after the other; returns when the last is done.
  std::int64_t access(std::int64_t at, int words) {
    for (int k = 0; k < words; ++k) {
      free_at = std::max(at, free_at) + access_cycles;
      at = free_at;
    }
    return at;
  }
};

// Code in external memory, fetched a word at a time, one word ahead of execution.
class Fetcher {
 public:
  Fetcher(bool external, Bus& bus) : external_(external), bus_(bus) {}

  // The instruction whose last byte is at `end - 1` may start at `at`; returns when its code is in.
  std::int64_t ready(std::int64_t end, std::int64_t at) {
    if (!external_) return at;
    const std::int64_t last = (end - 1) / 4;
    while (std::int64_t(ready_.size()) <= last) ready_.push_back(bus_.access(at, 1));
    return std::max(at, ready_[std::size_t(last)]);
  }
  // The instruction starting a new word began at `at`: the word after it may now be fetched.
  void started(std::int64_t begin, std::int64_t at) {
    if (!external_ || begin % 4 != 0) return;
    const std::int64_t next = begin / 4 + 1;
    if (std::int64_t(ready_.size()) == next) ready_.push_back(bus_.access(at, 1));
  }

 private:
  bool external_;
  Bus& bus_;
  std::vector<std::int64_t> ready_;  // when each code word is in the processor
};

// Cycles of the bytes in front of the instruction proper, one per byte: prefixes (an operand's, or
// those forming an operation code >= 16); for an FPU operation selected through fpentry, the
// `ldc code` (with its prefixes) and fpentry's own pfix. The tables quote the basic operation
// only (docs/t800-timing.md, "Instructions").
int prefix_cycles(const Instruction& in) {
  const isa::OpInfo& info = isa::info(in.op);
  switch (info.encoding) {
    case Encoding::direct:
      return isa::prefix_bytes(in.operand);
    case Encoding::operate:
      return isa::prefix_bytes(info.code);
    case Encoding::fpu_entry:
      return 1 + isa::prefix_bytes(info.code) + isa::prefix_bytes(isa::info(isa::Op::fpentry).code);
  }
  return 0;
}

}  // namespace

SequenceTime time_sequence(const isa::Sequence& code, const ProcessorModel& processor,
                           const MemoryView& memory, isa::Region code_region,
                           std::vector<InstructionTime>* trace) {
  const InstructionTimingTable& table = *processor.timing;
  Bus bus{0, memory.external_cycles};
  Fetcher fetcher(memory.external({code_region, -1}), bus);
  SequenceTime total;
  std::int64_t iu = 0, fpu = 0, position = 0;
  if (trace) trace->clear();

  for (const Instruction& in : code) {
    const InstructionTiming& t = table[in.op];
    if (!t.defined)
      throw std::logic_error("time_sequence: the " + std::string(table.family) + " has no " +
                             std::string(isa::mnemonic(in.op)) + " instruction");
    const int bytes = in.bytes();
    const int prefix = prefix_cycles(in);
    const int cycles = t.cycles_for(in.param, in.real64);
    const bool uses_fpu = t.unit != Unit::integer;

    // The instruction proper starts once its prefixes ran, its code is in, and (FPU instructions)
    // the FPU is free.
    const std::int64_t issue = iu + prefix;
    const std::int64_t code_ready = fetcher.ready(position + bytes, issue);
    const std::int64_t start = std::max(code_ready, uses_fpu ? fpu : 0);
    fetcher.started(position, start);

    // External data accesses take the bus from the start; the table counts one cycle for each.
    const int words = memory.external(in.data) ? t.words_for(in.param) : 0;
    const int extra = words ? int(bus.access(start, words) - start) - words : 0;

    std::int64_t iu_end = start, fpu_end = start;
    switch (t.unit) {
      case Unit::integer:
        iu_end = start + cycles + extra;
        break;
      case Unit::fp_load:
      case Unit::fp_store:
      case Unit::fp_result:
        iu_end = fpu_end = start + cycles + extra;
        break;
      case Unit::fp_arithmetic:
        iu_end = start + t.iu_part;
        fpu_end = start + cycles;
        break;
      case Unit::fp_load_arithmetic:
        iu_end = start + t.iu_part + extra;
        fpu_end = start + cycles + extra;
        break;
    }

    total.iu_busy += prefix + (iu_end - start);
    if (uses_fpu) total.fpu_busy += fpu_end - start;
    total.fetch_waits += std::max<std::int64_t>(0, code_ready - issue);
    total.fpu_waits += std::max<std::int64_t>(0, start - code_ready);
    total.memory_cycles += extra;
    total.bytes += bytes;
    ++total.instructions;
    if (trace)
      trace->push_back({start, iu_end, uses_fpu ? fpu_end : start, int(start - issue), extra});
    iu = iu_end;
    if (uses_fpu) fpu = fpu_end;
    position += bytes;
  }
  total.cycles = std::max(iu, fpu);
  return total;
}

}  // namespace t800
