#include "t800/cost_model.hpp"

#include <algorithm>
#include <cmath>

#include "t800/codegen/generator.hpp"
#include "t800/codegen/runtime_library.hpp"
#include "t800/memory_map.hpp"
#include "t800/processors/sequence_timing.hpp"
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
int start_process_cycles() {
  return t800_timing()[isa::Op::startp].cycles;
}
int end_process_cycles() {
  return t800_timing()[isa::Op::endp].cycles;
}

OperationMix sincos_routine(bool real64) {
  const int terms = real64 ? kSinCosTermsReal64 : kSinCosTermsReal32;
  OperationMix m;
  m.calls = 1;
  m.fp_mul = 3 + 1 + terms;  // k = x*2/pi, two-part k*pi/2, x*x, Horner multiplies
  m.fp_add = 2 + terms;      // two-part subtraction, Horner adds
  m.fp_loads = 1 + terms;    // the argument and one coefficient per term (constants live in memory)
  m.fp_stores = 1;
  m.fp_compare = 1;      // sign of the reduced argument
  m.int_simple = 4 + 4;  // fpint / conversion to integer and quadrant arithmetic
  m.branches = 2;        // quadrant selection
  return m;
}
}  // namespace timing

CostModel::CostModel(const ProcessorConfig& processor, Precision precision, double code_efficiency)
    : processor_(processor), precision_(precision), code_efficiency_(code_efficiency) {}

double CostModel::cycle_ns() const {
  return t800::cycle_ns(processor_.type);
}

double CostModel::memory_extra_per_access() const {
  return external_access_cycles(processor_model(processor_.type), processor_.memory.wait_states) -
         1;
}

namespace {

using isa::Op;

// The figures the op-count model prices a mix with, read from the processor's instruction table
// (processors/instruction_tables.cpp), so both compute levels share one source.
struct MixFigures {
  double simple, word_load, word_store, int_mul, int_div, branch, loop_end, call_return, prefix;
  double fp_issue;  // ldc + fpentry: the IU's part of an FP arithmetic instruction
  double fp_load, fp_store, fp_add, fp_mul, fp_div, fp_sqrt, fp_compare;
  bool fpu;
};

// Without an FPU (a T414), REAL arithmetic is a call of the run-time library's routine: its
// instructions, timed once, plus the call's operand loads (ldl, ldc, ldl, call).
double software_routine(codegen::NodeKind kind, bool real64, const ProcessorModel& processor) {
  const codegen::CodeUnit& routine =
      codegen::library_routine(kind, real64, codegen::Target{false, true});
  SequenceTime t;
  for (const codegen::CodeRun& run : routine.runs)
    t += time_sequence(run.code, processor, MemoryView{}, isa::Region::library).repeated(run.times);
  const InstructionTimingTable& table = *processor.timing;
  return double(t.cycles) + 2 * table[Op::ldl].cycles + table[Op::ldc].cycles +
         table[Op::call].cycles;
}

MixFigures figures(const ProcessorModel& processor, bool r64) {
  const InstructionTimingTable& t = *processor.timing;
  auto c = [&](Op op, std::int64_t param = 0) { return double(t[op].cycles_for(param, r64)); };
  MixFigures f{};
  f.simple = c(Op::ldc);
  f.word_load = c(Op::ldl);
  f.word_store = c(Op::stnl);
  f.int_mul = c(Op::mul);
  f.int_div = c(Op::div);
  f.branch = c(Op::cj, 1);  // taken: the loop-closing and IF jumps
  f.loop_end = c(Op::lend, 1);
  f.call_return = c(Op::call) + c(Op::ret);
  f.prefix = c(Op::pfix);
  f.fpu = processor.has_fpu;
  const int words = r64 ? 2 : 1;
  if (f.fpu) {
    f.fp_issue = c(Op::ldc) + c(Op::fpentry);
    f.fp_load = c(r64 ? Op::fpldnldb : Op::fpldnlsn);
    f.fp_store = c(r64 ? Op::fpstnldb : Op::fpstnlsn);
    f.fp_add = c(Op::fpadd);
    f.fp_mul = c(Op::fpmul);
    f.fp_div = c(Op::fpdiv);
    f.fp_sqrt = c(Op::fpusqrtfirst) + (r64 ? 5 : 2) * c(Op::fpusqrtstep) + c(Op::fpusqrtlast);
    f.fp_compare = c(Op::fpgt);
  } else {
    f.fp_issue = 0;
    f.fp_load = words * f.word_load;
    f.fp_store = words * f.word_store;
    f.fp_add = software_routine(codegen::NodeKind::add, r64, processor);
    f.fp_mul = software_routine(codegen::NodeKind::mul, r64, processor);
    f.fp_div = software_routine(codegen::NodeKind::div, r64, processor);
    f.fp_sqrt = software_routine(codegen::NodeKind::sqrt, r64, processor);
    f.fp_compare = software_routine(codegen::NodeKind::greater, r64, processor);
  }
  return f;
}

}  // namespace

// The overlap rule (docs/t800-timing.md, "The op-count model", status U): the integer unit issues
// every FP instruction and moves its data; the FPU executes arithmetic concurrently. Within a block
// the FPU is busy for the sum of its execute times, and an arithmetic instruction cannot execute
// before it is issued, so the block takes the longer of the integer unit's work and the FPU's work
// plus the issue slots that feed it. Without an FPU the routines run on the integer unit.
CycleBreakdown CostModel::breakdown(const OperationMix& in) const {
  const bool r64 = precision_ == Precision::real64;
  const MixFigures f = figures(processor_model(processor_.type), r64);
  OperationMix mix = in;
  mix.sincos = 0;
  if (in.sincos > 0) mix += timing::sincos_routine(r64) * in.sincos;

  const double arithmetic =
      double(mix.fp_add + mix.fp_mul + mix.fp_div + mix.fp_sqrt + mix.fp_compare);
  const double issue = arithmetic * f.fp_issue;
  double iu = mix.int_simple * f.simple + mix.word_loads * f.word_load +
              mix.word_stores * f.word_store + mix.int_mul * f.int_mul + mix.int_div * f.int_div +
              mix.branches * f.branch + mix.loop_ends * f.loop_end + mix.calls * f.call_return +
              mix.prefixes * f.prefix + mix.fp_loads * f.fp_load + mix.fp_stores * f.fp_store +
              issue;
  const double arithmetic_cycles = mix.fp_add * f.fp_add + mix.fp_mul * f.fp_mul +
                                   mix.fp_div * f.fp_div + mix.fp_sqrt * f.fp_sqrt +
                                   mix.fp_compare * f.fp_compare;
  const double fpu = f.fpu ? arithmetic_cycles : 0.0;
  if (!f.fpu) iu += arithmetic_cycles;

  // External memory: every data access pays the slower cycle; REAL64 moves two words. Code fetched
  // from external memory pays once per word of code, about four one-byte instructions (U).
  const MemoryConfig& mem = processor_.memory;
  if (mem.data == Placement::external) {
    const double words =
        mix.word_loads + mix.word_stores + (mix.fp_loads + mix.fp_stores) * (r64 ? 2 : 1);
    iu += words * memory_extra_per_access();
  }
  if (mem.code == Placement::external) {
    const double instructions = mix.int_simple + mix.word_loads + mix.word_stores + mix.int_mul +
                                mix.int_div + mix.branches + mix.loop_ends + 2 * mix.calls +
                                mix.prefixes + mix.fp_loads + mix.fp_stores + 2 * arithmetic;
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

}  // namespace t800
