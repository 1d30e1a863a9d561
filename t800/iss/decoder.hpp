// Instruction decoding: a pfix/nfix chain and the byte it prefixes are one instruction (CWG,
// "prefixing"), an `opr` selects an operation by the operand so built, and `ldc code; fpentry` is
// one FPU-entry operation, as the static timing model counts it (timing_stepper.hpp's
// prefix_cycles). Decoded instructions are cached by address and dropped when their code is
// written (memory.hpp).
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "t800/isa/opcode.hpp"
#include "t800/iss/memory.hpp"

namespace t800::iss {

// A prefix chain may be as long as a program likes (each pfix 0 shifts in zeros, and INMOS's
// loaders pad code with them: rayshade's has 26): one decoded instruction holds up to this many
// bytes, prefixes included. A longer chain is taken for a program run into what is not code
// (memory full of pfix bytes) and halts it.
inline constexpr int kMaxInstructionBytes = 255;

struct Decoded {
  isa::Op op = isa::Op::ldc;
  bool defined = false;    // false: an operation code the instruction set does not have
  std::uint8_t bytes = 0;  // prefixes included
  std::uint8_t prefix_cycles = 0;
  std::int32_t operand = 0;  // direct functions; for an undefined operation, its code
};

// The operation with this `opr` code or fpentry selector, if the instruction set has one.
std::optional<isa::Op> operation_of(std::int64_t code);
std::optional<isa::Op> fpu_entry_of(std::int64_t selector);

// Decodes without a cache (error reports, the disassembly of a halted processor).
Decoded decode(const Memory& memory, Word iptr);

class DecodeCache {
 public:
  explicit DecodeCache(Memory& memory);
  const Decoded& at(Word iptr) {
    Slot& s = slots_[iptr & kMask];
    if (s.valid && s.iptr == iptr) return s.decoded;
    return fill(s, iptr);
  }
  void clear();
  // The 16-byte line at `line_offset` (from MostNeg) was written: its instructions are decoded
  // again when they next run. Memory calls it (the cache registers itself; blocks.hpp chains on).
  void invalidate_line(std::uint32_t line_offset);
  std::int64_t misses() const { return misses_; }

 private:
  static constexpr std::uint32_t kSlots = 1u << 16, kMask = kSlots - 1;
  struct Slot {
    Word iptr = 0;
    bool valid = false;
    Decoded decoded;
  };
  const Decoded& fill(Slot& s, Word iptr);

  Memory& memory_;
  std::vector<Slot> slots_;
  std::int64_t misses_ = 0;
};

}  // namespace t800::iss
