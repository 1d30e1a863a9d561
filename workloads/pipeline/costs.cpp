#include "workloads/pipeline/costs.hpp"

namespace workloads {

t800::OperationMix to_operation_mix(const elimination::Work& work) {
  const elimination::IntegerWork& i = work.integer;
  t800::OperationMix m = to_operation_mix(work.fp);  // the floating-point part, as every kernel
  m.int_simple += 4 * i.loops + 2 * i.indexed + 2 * i.abs;
  m.loop_ends = i.iterations;
  m.word_loads = 2 * i.indexed + i.moves;
  m.word_stores = i.moves;
  m.branches = i.tests;
  return m;
}

}  // namespace workloads
