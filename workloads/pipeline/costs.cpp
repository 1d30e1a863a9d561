#include "workloads/pipeline/costs.hpp"

namespace workloads {

t800::OperationMix to_operation_mix(const elimination::Work& work) {
  const dynamics::OpCounts& f = work.fp;
  const elimination::IntegerWork& i = work.integer;
  t800::OperationMix m;
  m.fp_add = f.fadd;
  m.fp_mul = f.fmul;
  m.fp_div = f.fdiv;
  m.fp_sqrt = f.fsqrt;
  m.fp_compare = f.fcompare;
  m.fp_loads = f.fload;
  m.fp_stores = f.fstore;
  m.sincos = f.fsincos;
  m.calls = 1;
  m.int_simple = f.int_ops + 4 * i.loops + 2 * i.indexed + 2 * i.abs;
  m.loop_ends = i.iterations;
  m.word_loads = 2 * i.indexed + i.moves;
  m.word_stores = i.moves;
  m.branches = i.tests;
  return m;
}

}  // namespace workloads
