// Sanity benchmark (not a test): the cost model's sustained REAL32 rate for a dot product with its data in
// on-chip RAM on a T800-20, against the datasheet's "in excess of 1.5 MFLOPS sustained" (TN26,
// docs/t800-timing.md section 8). Prints the instruction mix it assumes per element, so the figure can be checked.
#include <cstdio>

#include "t800/cost_model.hpp"

namespace {

struct Kernel {
  const char* name;
  const char* code;
  t800::OperationMix per_element;
  int flops_per_element;
};

// sum := sum + (x[i] * y[i]) as occam compiles it: sum lives in workspace, indices by wsub.
t800::OperationMix compiled_occam() {
  t800::OperationMix m;
  m.word_loads = 4;   // ldl x, ldl i, ldl y, ldl i
  m.int_simple = 6;   // wsub x2, ldlp sum x2, lend set-up (ldlp, ldc)
  m.fp_loads = 3;     // fpldnlsn x[i], (fpldnlmulsn y[i]), (fpldnladdsn sum)
  m.fp_mul = 1;
  m.fp_add = 1;
  m.fp_stores = 1;    // fpstnlsn sum
  m.loop_ends = 1;    // lend
  return m;
}

// Hand-scheduled: sum kept on the FP stack, loop unrolled four times, pointers stepped once per iteration.
t800::OperationMix hand_scheduled() {
  t800::OperationMix m;
  m.word_loads = 2;   // ldl p, ldl q (each element as ldnlp-offset from them)
  m.int_simple = 2;   // ldnlp offsets
  m.fp_loads = 2;     // fpldnlsn x, fpldnlmulsn y
  m.fp_mul = 1;
  m.fp_add = 1;       // fpadd into the running sum
  t800::OperationMix per_iteration;
  per_iteration.int_simple = 4;  // step both pointers (ldlp/adc/stl pairs)
  per_iteration.word_stores = 2;
  per_iteration.loop_ends = 1;
  return m * 4 + per_iteration;  // four elements
}

}  // namespace

int main() {
  const t800::CostModel model({}, t800::Precision::real32);
  const Kernel kernels[] = {
      {"dot product, compiled occam", "SEQ i = 0 FOR n: sum := sum + (x[i] * y[i])", compiled_occam(), 2},
      {"dot product, hand-scheduled (x4)", "sum on the FP stack, 4 elements per loop", hand_scheduled(), 8},
  };
  std::printf("T800-20 (%.0f ns cycle), REAL32, data on chip. Datasheet: > 1.5 MFLOPS sustained.\n\n",
              model.cycle_ns());
  std::printf("%-36s %10s %10s %10s %8s\n", "kernel", "IU cycles", "FPU cyc.", "cycles", "MFLOPS");
  for (const Kernel& k : kernels) {
    const auto b = model.breakdown(k.per_element);
    const double seconds = b.total * model.cycle_ns() * 1e-9;
    std::printf("%-36s %10.1f %10.1f %10.1f %8.2f\n", k.name, b.integer_unit, b.fpu, b.total,
                k.flops_per_element / seconds / 1e6);
  }
  return 0;
}
