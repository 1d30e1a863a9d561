// The instruction-level timing rule, one instruction at a time: the integer unit (IU) and the FPU
// run concurrently by the rules of instruction_timing.hpp's Unit, every data access is priced by
// where it lives and code in external memory is fetched a word ahead (sequence_timing.hpp says
// how). The one source of this rule: the static model (time_sequence) steps through a generated
// sequence with it, and the instruction-set simulator (t800/iss) steps through the instructions it
// executes, so the two agree cycle for cycle on the same code.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>

#include "t800/processors/instruction_timing.hpp"

namespace t800 {

// One instruction as the timing rule sees it.
struct TimedStep {
  isa::Op op = isa::Op::ldc;
  int prefix_cycles = 0;       // bytes in front of the instruction proper (prefix_cycles())
  int bytes = 1;               // its code bytes, prefixes included
  std::int64_t address = 0;    // of its first byte: where its code words are
  std::int64_t param = 0;      // what its timing depends on (Instruction::param)
  std::int64_t rows = 1;       // 2D block moves: the figure is per row
  bool real64 = false;         // FPU arithmetic on REAL64 operands
  bool data_external = false;  // its data accesses go to external memory
};

// When one instruction ran (cycles from the stepper's start).
struct InstructionTime {
  std::int64_t start = 0;    // it began (after waiting for the FPU, its code or the bus)
  std::int64_t iu_end = 0;   // the IU may issue the next instruction
  std::int64_t fpu_end = 0;  // the FPU is free again (= start when the FPU is not involved)
  int waited = 0;            // cycles it waited for the FPU, its code or the bus
  int memory_extra = 0;      // cycles its external data accesses added
};

// Totals over the instructions stepped.
struct StepTotals {
  std::int64_t iu_busy = 0;        // cycles the IU executed (waits excluded)
  std::int64_t fpu_busy = 0;       // cycles the FPU executed
  std::int64_t fpu_waits = 0;      // IU cycles spent waiting for the FPU
  std::int64_t fetch_waits = 0;    // cycles spent waiting for code from external memory
  std::int64_t memory_cycles = 0;  // cycles external data accesses added
  std::int64_t bytes = 0;          // code bytes executed
  std::int64_t instructions = 0;

  StepTotals& operator+=(const StepTotals& more) {
    iu_busy += more.iu_busy;
    fpu_busy += more.fpu_busy;
    fpu_waits += more.fpu_waits;
    fetch_waits += more.fetch_waits;
    memory_cycles += more.memory_cycles;
    bytes += more.bytes;
    instructions += more.instructions;
    return *this;
  }
};
StepTotals operator-(StepTotals after, const StepTotals& before);

// The stepper's state as the instructions after it see it, relative to the IU's cycle and to a code
// word (the origin): two runs of the same instructions from equal contexts take the same cycles,
// which lets the instruction-set simulator time a run of straight-line code once and replay it
// (t800/iss/blocks.hpp). A time already past counts as now: nothing after starts before the IU.
struct TimingContext {
  static constexpr int kCodeWords = 4;  // code words buffered; more and there is no context
  std::int32_t fpu = 0;                 // cycles after the IU's until the FPU is free
  std::int32_t bus = 0;                 // ... until the external memory bus is
  std::int32_t code_first = 0;          // the first buffered code word, from the origin
  std::int32_t code_words = 0;
  std::array<std::int32_t, kCodeWords> code_ready{};  // when each buffered word is in, as above
};
inline bool operator==(const TimingContext& a, const TimingContext& b) {
  bool same = a.fpu == b.fpu && a.bus == b.bus && a.code_first == b.code_first &&
              a.code_words == b.code_words;
  for (int k = 0; k < TimingContext::kCodeWords; ++k) same &= a.code_ready[k] == b.code_ready[k];
  return same;
}

class TimingStepper {
 public:
  // `external_cycles`: one external access, wait states included; `code_external`: where the
  // instructions are fetched from (the ISS says so per instruction through set_code_external).
  TimingStepper(const InstructionTimingTable& table, int external_cycles, bool code_external);
  // A copy is a saved state to go back to (the ISS undoes a run that ran ahead too far).
  TimingStepper(const TimingStepper& other);
  TimingStepper& operator=(const TimingStepper& other);

  // Times `step` after the instructions before it; throws std::logic_error if the family has no
  // such instruction.
  InstructionTime step(const TimedStep& step);
  // Control went elsewhere (a jump taken, a call, a process switch): the prefetch buffer is empty
  // and the next instruction's code is fetched from its own address, as at a sequence's start.
  void restart_fetch() { fetch_.restart(); }
  void set_code_external(bool external) { fetch_.set_external(external); }
  // Neither unit starts anything before `cycle` (the processor waited, idle or descheduled).
  void wait_until(std::int64_t cycle);
  // The state now, code words counted from `origin_word` (an address / 4); false if the prefetch
  // buffer holds more than a context does or a time is too far ahead to say.
  bool context(std::int64_t origin_word, TimingContext& out) const;
  // Continues from `context` with the IU at cycle `iu`, as if the instructions that led there from
  // another run's equal context had been stepped again: their totals are `added`.
  void resume(const TimingContext& context, std::int64_t iu, std::int64_t origin_word,
              const StepTotals& added);

  std::int64_t iu_free() const { return iu_; }
  std::int64_t fpu_free() const { return fpu_; }
  // Until both units are idle.
  std::int64_t end() const { return iu_ > fpu_ ? iu_ : fpu_; }
  const StepTotals& totals() const { return totals_; }

 private:
  // The one external memory bus, shared by instruction fetches and data accesses.
  struct Bus {
    std::int64_t free_at = 0;
    int access_cycles = 3;
    // `words` accesses requested at `at`, one after the other; returns when the last is done.
    std::int64_t access(std::int64_t at, int words);
  };
  // Code in external memory, fetched a word at a time, one word ahead of execution.
  class Fetcher {
   public:
    Fetcher(bool external, Bus& bus) : external_(external), bus_(&bus) {}
    // A copy's fetches go to its own stepper's bus.
    void use_bus(Bus& bus) { bus_ = &bus; }
    // The instruction in [begin, end) may start at `at`; when its code is in.
    // (Code on chip, the common case, is decided inline: the ISS asks for every instruction.)
    std::int64_t ready(std::int64_t begin, std::int64_t end, std::int64_t at) {
      return external_ ? ready_external(begin, end, at) : at;
    }
    // The instruction starting at `begin` began at `at`: if it starts a new word, the word after
    // it may now be fetched.
    void started(std::int64_t begin, std::int64_t at) {
      if (external_ && begin % 4 == 0) started_external(begin, at);
    }
    void restart() { words_.clear(); }
    void set_external(bool external) {
      if (external != external_) restart();
      external_ = external;
    }
    bool save(std::int64_t origin_word, std::int64_t now, TimingContext& out) const;
    void load(const TimingContext& context, std::int64_t origin_word, std::int64_t now);

   private:
    std::int64_t ready_external(std::int64_t begin, std::int64_t end, std::int64_t at);
    void started_external(std::int64_t begin, std::int64_t at);
    bool external_;
    Bus* bus_;
    // When each code word from first_ on is in the processor: the words an instruction spans
    // and the one fetched ahead, so a few (an instruction is at most 255 bytes, 65 words).
    class Words {
     public:
      void clear() { size_ = 0; }
      bool empty() const { return size_ == 0; }
      std::size_t size() const { return size_; }
      void pop_front() {
        head_ = (head_ + 1) & kMask;
        --size_;
      }
      void push_back(std::int64_t ready);
      std::int64_t operator[](std::size_t i) const { return ring_[(head_ + i) & kMask]; }

     private:
      static constexpr std::size_t kCapacity = 128, kMask = kCapacity - 1;
      std::array<std::int64_t, kCapacity> ring_;  // only [head_, head_ + size_) is read
      std::size_t head_ = 0, size_ = 0;
    };
    std::int64_t first_ = 0;  // the code word words_[0] is for
    Words words_;
  };

  const InstructionTimingTable* table_;
  Bus bus_;
  Fetcher fetch_;
  std::int64_t iu_ = 0, fpu_ = 0;
  StepTotals totals_;
};

// Cycles of the bytes in front of an instruction proper, one per byte (prefixes of a direct
// function's operand, the pfix forming an operation code >= 16, and for an FPU operation selected
// through fpentry the `ldc code` with its prefixes and fpentry's own pfix): the tables quote the
// basic operation only (docs/t800-timing.md, "Instructions").
int prefix_cycles(isa::Op op, std::int64_t operand);

// Inline: the instruction-set simulator takes and resumes a context for every block it runs.
namespace timing_detail {
// `at` as a context holds it: cycles after `now`, a time already past as now.
inline bool relative(std::int64_t at, std::int64_t now, std::int32_t& out) {
  const std::int64_t ahead = std::max<std::int64_t>(0, at - now);
  if (ahead > std::numeric_limits<std::int32_t>::max()) return false;
  out = std::int32_t(ahead);
  return true;
}
}  // namespace timing_detail

inline bool TimingStepper::Fetcher::save(std::int64_t origin_word, std::int64_t now,
                                         TimingContext& out) const {
  if (words_.size() > std::size_t(TimingContext::kCodeWords)) return false;
  out.code_words = std::int32_t(words_.size());
  if (words_.empty()) return true;
  const std::int64_t first = first_ - origin_word;
  if (first < std::numeric_limits<std::int32_t>::min() ||
      first > std::numeric_limits<std::int32_t>::max())
    return false;
  out.code_first = std::int32_t(first);
  for (std::size_t k = 0; k < words_.size(); ++k)
    if (!timing_detail::relative(words_[k], now, out.code_ready[k])) return false;
  return true;
}

inline void TimingStepper::Fetcher::load(const TimingContext& context, std::int64_t origin_word,
                                         std::int64_t now) {
  words_.clear();
  first_ = origin_word + context.code_first;
  for (int k = 0; k < context.code_words; ++k) words_.push_back(now + context.code_ready[k]);
}

inline bool TimingStepper::context(std::int64_t origin_word, TimingContext& out) const {
  out = TimingContext{};
  return timing_detail::relative(fpu_, iu_, out.fpu) &&
         timing_detail::relative(bus_.free_at, iu_, out.bus) && fetch_.save(origin_word, iu_, out);
}

inline void TimingStepper::resume(const TimingContext& context, std::int64_t iu,
                                  std::int64_t origin_word, const StepTotals& added) {
  iu_ = iu;
  fpu_ = iu + context.fpu;
  bus_.free_at = iu + context.bus;
  fetch_.load(context, origin_word, iu);
  totals_ += added;
}

}  // namespace t800
