// Counted elimination work -> the T800 operation mix the cost model prices (t800::CostModel).
// The mapping of integer work onto instructions is a model assumption (U in docs/t800-timing.md terms),
// stated once here, and it is the same for every level of the pipeline:
//   a piece of work      one occam PROC call (call + ret)
//   a loop entered       4 simple instructions (ldc/stl of the index and of the count)
//   a loop iteration     one lend
//   an element a[i]      2 word loads (base and index) and 2 simple cycles (wsub)
//   an IF on a result    one conditional jump
//   an integer move      one word load and one word store
//   an fpuabs            2 simple cycles to issue (ldc + fpentry); the FPU's part is negligible
// Floating-point operations, loads and stores map one to one.
#pragma once

#include "t800/operation_mix.hpp"
#include "workloads/elimination/work.hpp"
#include "workloads/run/operation_mix.hpp"

namespace workloads {

t800::OperationMix to_operation_mix(const elimination::Work& work);

}  // namespace workloads
