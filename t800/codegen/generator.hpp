// Turns a recording into the T800 code the INMOS occam compiler would emit for it, following the
// code shapes of "Transputer instruction set: a compiler writer's guide" (INMOS, 1988); the rules
// are listed in docs/compute-model.md, "From a kernel to T800 code":
//   * each statement is compiled on its own: its expression evaluated on the three-deep FP stack,
//     then stored; values live in memory between statements (occam keeps nothing in registers);
//   * an intermediate result used more than once, or in another block (a later iteration), is a
//     local variable: stored to a workspace word, loaded where used;
//   * operands come from memory through fpldnlsn/fpldnldb, the combined fpldnladd/fpldnlmul forms
//     where the operation allows; a binary operation evaluates the operand needing more registers
//     first, and a spill to a workspace temporary happens only when both need all three;
//   * array elements: the base pointer from the workspace (ldl), a constant subscript by ldnlp, a
//     loop-indexed one by ldl of the loop's index (adc for an offset), csub0 against the bound
//     when range checks are on, then wsub (wsubdb for REAL64);
//   * REAL constants from the code's constant table (ldc, ldpi); 0.0 by fpldzero;
//   * a replicated SEQ keeps its index and count in a two-word control block and ends each
//     iteration with ldlp, ldc, lend;
//   * SIN and COS are calls of the library's routines;
//   * the kernel is a PROC: its caller passes the arrays' addresses and calls it; it sets up its
//     frame (ajw) and its constant table's pointer (ldc, ldpi, stl), and returns (ajw, ret).
#pragma once

#include "t800/codegen/code_unit.hpp"
#include "t800/codegen/recording.hpp"

namespace t800::codegen {

struct Target {
  // false: a T414 -- REAL arithmetic by calls of the software floating-point library.
  bool fpu = true;
  // occam's default run-time checks: computed subscripts against their bound (csub0; constant
  // ones are checked when compiled) and the FPU's error flag before every REAL store (fpchkerr).
  // false is the compiler's "no run-time error checking" option.
  bool checked = true;
  // Each instruction's note for listings (the source it was generated from). The code and its
  // timing do not depend on them; without them an instruction's note is empty and compiling
  // costs about a tenth less.
  bool notes = true;
};

CodeUnit generate(const Recording& recording, const Target& target);

}  // namespace t800::codegen
