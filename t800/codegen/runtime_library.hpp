// The occam run-time library routines generated code calls, as T800 code: SIN and COS (software on
// every transputer), and, for the T414 which has no FPU, the REAL32 and REAL64 arithmetic. Each is
// an instruction sequence following the library's documented algorithm (docs/compute-model.md,
// "From a kernel to T800 code"); their code occupies memory once per processor that uses them.
#pragma once

#include <string>
#include <vector>

#include "t800/codegen/code_unit.hpp"
#include "t800/codegen/recording.hpp"

namespace t800::codegen {

struct Target;

// The routine computing a node of this kind (sine, cosine; on a T414 also add, sub, mul, div,
// sqrt, abs and the comparisons) at this precision, generated for the target.
const CodeUnit& library_routine(NodeKind kind, bool real64, const Target& target);

}  // namespace t800::codegen
