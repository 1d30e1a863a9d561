// Generated T800 code for one recorded kernel (an occam PROC): what it executes, in order, and
// what it occupies in memory.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "t800/codegen/recording.hpp"
#include "t800/isa/instruction.hpp"

namespace t800::codegen {

// A straight-line stretch of code and how many times in a row it runs (the iterations of a loop
// whose code is the same each time are one run).
struct CodeRun {
  std::string label;  // "SEQ k, iterations 0..98"
  isa::Sequence code;
  std::int64_t times = 1;
  bool library = false;  // the run-time library's code (fetched from its memory, not the unit's)
  // >= 0: the run ends with a SEQ's set-up (its control block, its count's test), and the SEQ
  // runs this many iterations, whose runs follow.
  std::int64_t seq_iterations = -1;
};

struct CodeUnit {
  std::string name;
  bool real64 = false;
  std::vector<CodeRun> runs;      // the execution, in order (library routines it calls inline)
  std::vector<ArrayDecl> arrays;  // the arrays its Region::array accesses index
  int code_bytes = 0;             // its code in memory, every piece once (a loop's body once)
  int constant_bytes = 0;         // its table of REAL constants
  std::vector<double> constants;  // that table's values, in order (REAL32 ones are floats)
  int workspace_words = 0;        // its frame: locals, temporaries, loop control, call linkage
  std::vector<const CodeUnit*> routines;  // library routines it calls (their code is the library's)

  std::int64_t executed_instructions() const;
};

}  // namespace t800::codegen
