// What a block of computation is, as the two compute cost levels see it (fidelity.compute_cost):
// its operation mix (the op-count model, t800/cost_model.hpp) and, when the work is a recorded
// kernel, its dataflow, which each processor compiles to its own T800 code and times instruction
// by instruction (the default; t800/compute_model.hpp).
#pragma once

#include <memory>

#include "t800/codegen/recording.hpp"
#include "t800/operation_mix.hpp"

namespace t800 {

struct ComputeWork {
  OperationMix mix;
  std::shared_ptr<const codegen::Recording> code;  // null: only the mix describes it
};

}  // namespace t800
