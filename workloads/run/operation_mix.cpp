#include "workloads/run/operation_mix.hpp"

namespace workloads {

t800::OperationMix to_operation_mix(const dynamics::OpCounts& c) {
  t800::OperationMix m;
  m.fp_add = c.fadd;
  m.fp_mul = c.fmul;
  m.fp_div = c.fdiv;
  m.fp_sqrt = c.fsqrt;
  m.sincos = c.fsincos;
  m.fp_compare = c.fcompare;
  m.fp_loads = c.fload;
  m.fp_stores = c.fstore;
  m.int_simple = c.int_ops;
  m.int_mul = c.int_mul;
  m.int_div = c.int_div;
  m.calls = 1;
  return m;
}

}  // namespace workloads
