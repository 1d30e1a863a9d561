// Instruction timing as data: for each instruction a processor family executes, its cycles (on-chip
// memory, typical figures of the INMOS tables), which unit does the work, and the memory words it
// touches. One table per family (instruction_tables.cpp); docs/t800-timing.md, sections
// "Instructions" and "FPU", gives their sources.
#pragma once

#include <array>
#include <cstdint>
#include <optional>

#include "t800/isa/opcode.hpp"

namespace t800 {

// How an instruction shares the processor between the integer unit (IU) and the FPU, which run
// concurrently (docs/t800-timing.md, "FPU overlap"):
//   integer            the IU alone;
//   fp_load            waits until the FPU is free, then IU and FPU move the operand together;
//   fp_store           waits until the FPU's result is ready, then stores it;
//   fp_arithmetic      waits until the FPU is free; the IU is busy for `iu_part` cycles to issue
//                      it, the FPU for the whole figure; the IU goes on meanwhile;
//   fp_load_arithmetic fpldnladd/fpldnlmul: the load part (`iu_part`) on the IU, then the FPU
//                      executes; the IU goes on;
//   fp_result          the result goes to the integer stack (comparisons, error tests): the IU
//                      waits for the FPU to finish.
enum class Unit : std::uint8_t {
  integer,
  fp_load,
  fp_store,
  fp_arithmetic,
  fp_load_arithmetic,
  fp_result
};

struct InstructionTiming {
  bool defined = false;  // false: the family does not have this instruction
  Unit unit = Unit::integer;
  int cycles = 0;         // typical cycles (REAL32 operands for the FPU's arithmetic)
  int cycles_double = 0;  // REAL64 operands, where the FPU's time differs; 0 = same as cycles
  int per_param = 0;      // cycles per unit of the instruction's parameter (words, shift places)
  // For instructions with two figures: the cycles when the parameter is non-zero (cj taken, lend
  // looping, enbc/altwt ready, tin/taltwt time in the future, testerr error set); 0 = no choice.
  int when_set = 0;
  int iu_part = 0;     // fp_arithmetic / fp_load_arithmetic: the IU's share (see Unit)
  int data_words = 0;  // memory words read or written, besides instruction fetch
  int data_words_per_param = 0;

  // The cycles for a given parameter and operand precision.
  // Inline: the instruction-set simulator asks once per instruction it executes.
  int cycles_for(std::int64_t param, bool real64) const {
    const int base = (real64 && cycles_double) ? cycles_double : cycles;
    if (when_set) return param ? when_set : base;
    return base + per_param * static_cast<int>(param);
  }
  int words_for(std::int64_t param) const { return data_words + data_words_per_param * int(param); }
};

struct InstructionTimingTable {
  const char* family;  // "T800", "T805", "T414"
  // The figures are for the basic operation only: every prefix byte in front of an instruction
  // (an operand's, or the pfix forming an operation code >= 16, as fpadd = pfix 8; opr 7) adds
  // one cycle (IMS T400/T805 datasheet, "Instruction set summary", notation; docs/t800-timing.md).
  std::array<InstructionTiming, isa::kOpCount> rows{};

  const InstructionTiming& operator[](isa::Op op) const {
    return rows[static_cast<std::size_t>(op)];
  }
  bool has(isa::Op op) const { return (*this)[op].defined; }
};

const InstructionTimingTable& t800_timing();
const InstructionTimingTable& t805_timing();
const InstructionTimingTable& t414_timing();

}  // namespace t800
