#include "t800/cost_model.hpp"

#include <algorithm>
#include <cmath>

#include "t800/timing_table.hpp"

namespace t800 {

std::optional<Precision> parse_precision(std::string_view text) {
  if (text == "real32") return Precision::real32;
  if (text == "real64") return Precision::real64;
  return std::nullopt;
}

std::string_view to_string(Precision precision) {
  return precision == Precision::real64 ? "real64" : "real32";
}

namespace timing {
OperationMix sincos_routine(bool real64) {
  const int terms = real64 ? kSinCosTermsReal64 : kSinCosTermsReal32;
  OperationMix m;
  m.calls = 1;
  m.fp_mul = 3 + 1 + terms;  // k = x*2/pi, two-part k*pi/2, x*x, Horner multiplies
  m.fp_add = 2 + terms;      // two-part subtraction, Horner adds
  m.fp_loads = 1 + terms;    // the argument and one coefficient per term (constants live in memory)
  m.fp_stores = 1;
  m.fp_compare = 1;          // sign of the reduced argument
  m.int_simple = 4 + 4;      // fpint / conversion to integer and quadrant arithmetic
  m.branches = 2;            // quadrant selection
  return m;
}
}  // namespace timing

CostModel::CostModel(const ProcessorConfig& processor, Precision precision, double code_efficiency)
    : processor_(processor), precision_(precision), code_efficiency_(code_efficiency) {}

double CostModel::cycle_ns() const { return t800::cycle_ns(processor_.grade); }

double CostModel::memory_extra_per_access() const {
  return timing::kExternalExtraCycles + processor_.memory.wait_states;
}

// The overlap rule (docs/t800-timing.md section 4, status U): the integer unit issues every FP instruction and moves
// its data; the FPU executes arithmetic concurrently. Within a block the FPU is busy for the sum of its execute
// times, and an arithmetic instruction cannot execute before it is issued, so the block takes the longer of
// the integer unit's work and the FPU's work plus the issue slots that feed it.
CycleBreakdown CostModel::breakdown(const OperationMix& in) const {
  using namespace timing;
  const bool r64 = precision_ == Precision::real64;
  OperationMix mix = in;
  mix.sincos = 0;
  if (in.sincos > 0) mix += timing::sincos_routine(r64) * in.sincos;

  const double arithmetic = double(mix.fp_add + mix.fp_mul + mix.fp_div + mix.fp_sqrt + mix.fp_compare);
  const double issue = arithmetic * kFpIssue;
  double iu = mix.int_simple * kSimpleOp + mix.word_loads * kWordLoad + mix.word_stores * kWordStore +
              mix.int_mul * kIntMul + mix.int_div * kIntDiv + mix.branches * kBranch +
              mix.loop_ends * kLoopEnd + mix.calls * kCallReturn + mix.prefixes * kPrefix +
              mix.fp_loads * kFpLoad.of(r64) + mix.fp_stores * kFpStore.of(r64) + issue;
  const double fpu = mix.fp_add * kFpAdd.of(r64) + mix.fp_mul * kFpMul.of(r64) +
                     mix.fp_div * kFpDiv.of(r64) + mix.fp_sqrt * kFpSqrt.of(r64) +
                     mix.fp_compare * kFpCompare.of(r64);

  // External memory: every data access pays the slower cycle; REAL64 moves two words. Code fetched from
  // external memory pays once per word of code, about four one-byte instructions (U).
  const MemoryConfig& mem = processor_.memory;
  if (mem.data == Placement::external) {
    const double words = mix.word_loads + mix.word_stores + (mix.fp_loads + mix.fp_stores) * (r64 ? 2 : 1);
    iu += words * memory_extra_per_access();
  }
  if (mem.code == Placement::external) {
    const double instructions = mix.int_simple + mix.word_loads + mix.word_stores + mix.int_mul +
                                mix.int_div + mix.branches + mix.loop_ends + 2 * mix.calls + mix.prefixes +
                                mix.fp_loads + mix.fp_stores + 2 * arithmetic;
    iu += instructions / 4.0 * memory_extra_per_access();
  }

  CycleBreakdown b;
  b.integer_unit = iu * code_efficiency_;
  b.fpu = fpu * code_efficiency_;
  b.total = std::max(b.integer_unit, (fpu + issue) * code_efficiency_);
  return b;
}

std::int64_t CostModel::cycles(const OperationMix& mix) const {
  return static_cast<std::int64_t>(std::ceil(breakdown(mix).total - 1e-9));
}

std::int64_t CostModel::communication_cycles(std::int64_t bytes, bool internal) {
  if (!internal) return timing::kCommFixed;
  const std::int64_t words = (bytes + 3) / 4;  // part words count as whole (S)
  return timing::kCommPerWord * words + timing::kCommFixed;
}

}  // namespace t800
