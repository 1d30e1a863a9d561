// Runs a code generator's CodeUnit (t800/codegen) on the instruction-set simulator: the code the
// generator emitted for a recorded kernel, its frame, arrays and constant table put into memory
// where the code expects them, executed instruction by instruction along the path the unit says it
// takes, the arrays read back. It is how the generator's output is checked by running it (issue 24,
// item 8): the numbers against the C++ kernel's, the cycles against the static model's.
//
// How the unit becomes a program:
//   * Order. A unit's runs are its execution with identical loop iterations grouped (a group's runs
//     each carry the group's size in `times`); the loader recovers the order from the loops' code:
//     a loop's setup (ldc first; stl 2d; ldc count; stl 2d+1) ends a run, every iteration ends with
//     ldlp 2d; ldc back; lend, and `count` iterations make the loop.
//   * Placement. The code is laid out as the processor walks it: the caller's stand-in (ldlp, call)
//     first, the PROC at the call's target, a loop's iterations each from the loop's first address
//     (an iteration's code is written there before it runs, so iterations whose code differs -- a
//     data-dependent IF -- run the code the generator emitted for them), a taken cj continuing at
//     its target. Every instruction's bytes come from the ISA's encoder. The ISS does every jump
//     itself; after each instruction the loader checks the ISS's Iptr is where the code continues
//     (for lend: the loop's first address, which checks the generator's back offset).
//   * Data. The PROC's frame is below the caller's workspace as call and ajw make it; the arrays'
//     pointers (or, for workspace arrays, their elements) are in the frame words codegen::Frame
//     names; the constant table is where ldc; ldpi say, holding CodeUnit::constants; the integer
//     variable the IF tests load is non-zero (the generator compiles the IF's path taken, its
//     condition true).
//   * End. The kernel ends with ret to the caller's stand-in; the loader stops the ISS after the
//     unit's last instruction (nothing of the loader's own is executed or timed).
// The processor is the named type's model with its on-chip RAM enlarged to hold the code of any
// kernel (1 MB): code and constants are on chip, the workspace and the arrays on chip or external
// as the placement says, so the static model's view of the same placement is exact.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "t800/codegen/code_unit.hpp"
#include "t800/codegen/recording.hpp"
#include "t800/processors/processor_model.hpp"
#include "t800/processors/sequence_timing.hpp"

namespace t800::iss {

struct KernelPlacement {
  bool workspace_external = false;
  bool arrays_external = false;
  int wait_states = 0;  // on each external access
};

struct KernelExecution {
  // Every array's elements after the run (REAL32 ones widened, INTs exact), by the unit's array
  // index.
  std::vector<std::vector<double>> arrays;
  std::int64_t cycles = 0;        // the ISS's, from the first instruction to the end of the last
  std::int64_t instructions = 0;  // executed by the ISS
  std::int64_t sequences = 0;     // run executions (a run of `times` n counts n)
  StepTotals timing;              // the ISS's totals over the kernel
  SequenceTime expected;  // the static model: Σ time_sequence(run) × times, as ComputeModel
  MemoryView view;        // the placement as the static model sees it
  bool error = false;     // the processor's Error flag at the end
  bool fp_error = false;  // the FPU's error flag at the end
  std::string failure;    // empty: the ISS followed the code's path to its end
};

// The unit's runs in execution order (indices into unit.runs, one entry per execution); throws
// std::runtime_error if the runs do not have the shape the generator gives loops.
std::vector<int> execution_order(const codegen::CodeUnit& unit);

// Runs `unit`, compiled from `recording`, with `inputs` (per array of the unit, its elements'
// values; missing arrays or elements are 0).
KernelExecution execute_kernel(const codegen::CodeUnit& unit, const codegen::Recording& recording,
                               const std::vector<std::vector<double>>& inputs, ProcessorType type,
                               const KernelPlacement& placement = {});

}  // namespace t800::iss
