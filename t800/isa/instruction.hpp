// One instruction of generated T800 code: the operation, its operand, the parameter its timing
// depends on, and the memory its data accesses touch, so that a timing model can price it and a
// listing can show it.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "t800/isa/opcode.hpp"

namespace t800::isa {

// The memory an access touches, as the code sees it: the running process's workspace (locals,
// temporaries, the loop control blocks, call frames), the code unit's own code (its instructions
// and constant table), one of the unit's arrays (by index into the unit's array list), or the
// run-time library's code and constants.
enum class Region : std::uint8_t { none, workspace, code, array, library };

struct MemoryRef {
  Region region = Region::none;
  int array = -1;  // Region::array only
  bool operator==(const MemoryRef& o) const { return region == o.region && array == o.array; }
};

struct Instruction {
  Op op = Op::ldc;
  std::int64_t operand = 0;  // direct functions (ldl 3, ldc 100, cj +12, ...)
  // What the timing depends on: words moved (in, out, move), places shifted, bit of prod, or, for
  // instructions with two figures, whether the costly case happens (cj taken, lend looping, ...).
  std::int64_t param = 0;
  bool real64 = false;  // FPU arithmetic on REAL64 operands
  MemoryRef data;       // where its data accesses go
  std::string note;     // the source it was generated from, for listings

  int bytes() const { return encoded_bytes(op, operand); }
};

using Sequence = std::vector<Instruction>;

// "ldc 100", "fpldnlmulsn", "lend" (with its operand where it has one).
std::string assembly(const Instruction& instruction);

}  // namespace t800::isa
