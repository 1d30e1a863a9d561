#include "t800/processors/timing_stepper.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace t800 {

using isa::Encoding;

int prefix_cycles(isa::Op op, std::int64_t operand) {
  const isa::OpInfo& info = isa::info(op);
  switch (info.encoding) {
    case Encoding::direct:
      return isa::prefix_bytes(operand);
    case Encoding::operate:
      return isa::prefix_bytes(info.code);
    case Encoding::fpu_entry:
      return 1 + isa::prefix_bytes(info.code) + isa::prefix_bytes(isa::info(isa::Op::fpentry).code);
  }
  return 0;
}

StepTotals operator-(StepTotals after, const StepTotals& before) {
  after.iu_busy -= before.iu_busy;
  after.fpu_busy -= before.fpu_busy;
  after.fpu_waits -= before.fpu_waits;
  after.fetch_waits -= before.fetch_waits;
  after.memory_cycles -= before.memory_cycles;
  after.bytes -= before.bytes;
  after.instructions -= before.instructions;
  return after;
}

std::int64_t TimingStepper::Bus::access(std::int64_t at, int words) {
  for (int k = 0; k < words; ++k) {
    free_at = std::max(at, free_at) + access_cycles;
    at = free_at;
  }
  return at;
}

void TimingStepper::Fetcher::Words::push_back(std::int64_t ready) {
  if (size_ == kCapacity)
    throw std::logic_error("timing: an instruction spanning more than 127 code words");
  ring_[(head_ + size_) & kMask] = ready;
  ++size_;
}

std::int64_t TimingStepper::Fetcher::ready_external(std::int64_t begin, std::int64_t end,
                                                    std::int64_t at) {
  const std::int64_t first = begin / 4, last = (end - 1) / 4;
  // Straight-line code never skips a word: an instruction before the buffer or past the word being
  // fetched next was reached by a jump, and its code is fetched from its own address (a forward
  // jump does not fetch the words it jumps over).
  if (words_.empty() || first < first_ || first > first_ + std::int64_t(words_.size())) {
    words_.clear();
    first_ = first;
  }
  // Words before this instruction's first are done with: the buffer holds what is still ahead.
  while (first_ < first && words_.size() > 1) {
    words_.pop_front();
    ++first_;
  }
  while (first_ + std::int64_t(words_.size()) <= last) words_.push_back(bus_->access(at, 1));
  return std::max(at, words_[std::size_t(last - first_)]);
}

void TimingStepper::Fetcher::started_external(std::int64_t begin, std::int64_t at) {
  const std::int64_t next = begin / 4 + 1;
  if (first_ + std::int64_t(words_.size()) == next) words_.push_back(bus_->access(at, 1));
}

TimingStepper::TimingStepper(const InstructionTimingTable& table, int external_cycles,
                             bool code_external)
    : table_(&table), bus_{0, external_cycles}, fetch_(code_external, bus_) {}

TimingStepper::TimingStepper(const TimingStepper& other)
    : table_(other.table_),
      bus_(other.bus_),
      fetch_(other.fetch_),
      iu_(other.iu_),
      fpu_(other.fpu_),
      totals_(other.totals_) {
  fetch_.use_bus(bus_);
}

TimingStepper& TimingStepper::operator=(const TimingStepper& other) {
  table_ = other.table_;
  bus_ = other.bus_;
  fetch_ = other.fetch_;
  fetch_.use_bus(bus_);
  iu_ = other.iu_;
  fpu_ = other.fpu_;
  totals_ = other.totals_;
  return *this;
}

void TimingStepper::wait_until(std::int64_t cycle) {
  iu_ = std::max(iu_, cycle);
  fpu_ = std::max(fpu_, cycle);
  bus_.free_at = std::max(bus_.free_at, cycle);
}

namespace {
// Out of line, so that step() itself builds no strings and keeps a small frame: the ISS calls it
// for every instruction.
[[noreturn, gnu::noinline, gnu::cold]] void no_such_instruction(const char* family, isa::Op op) {
  throw std::logic_error("timing: the " + std::string(family) + " has no " +
                         std::string(isa::mnemonic(op)) + " instruction");
}
}  // namespace

InstructionTime TimingStepper::step(const TimedStep& in) {
  const InstructionTiming& t = (*table_)[in.op];
  if (!t.defined) no_such_instruction(table_->family, in.op);
  const int cycles = t.cycles_for(in.param, in.real64) * int(in.rows);
  const bool uses_fpu = t.unit != Unit::integer;

  // The instruction proper starts once its prefixes ran, its code is in, and (FPU instructions)
  // the FPU is free.
  const std::int64_t issue = iu_ + in.prefix_cycles;
  const std::int64_t code_ready = fetch_.ready(in.address, in.address + in.bytes, issue);
  const std::int64_t start = std::max(code_ready, uses_fpu ? fpu_ : 0);
  fetch_.started(in.address, start);

  // External data accesses take the bus from the start; the table counts one cycle for each.
  const int words = in.data_external ? t.words_for(in.param) * int(in.rows) : 0;
  const int extra = words ? int(bus_.access(start, words) - start) - words : 0;

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

  totals_.iu_busy += in.prefix_cycles + (iu_end - start);
  if (uses_fpu) totals_.fpu_busy += fpu_end - start;
  totals_.fetch_waits += std::max<std::int64_t>(0, code_ready - issue);
  totals_.fpu_waits += std::max<std::int64_t>(0, start - code_ready);
  totals_.memory_cycles += extra;
  totals_.bytes += in.bytes;
  ++totals_.instructions;
  iu_ = iu_end;
  if (uses_fpu) fpu_ = fpu_end;
  return {start, iu_end, uses_fpu ? fpu_end : start, int(start - issue), extra};
}

}  // namespace t800
