// The cost model against the timing table (docs/t800-timing.md sections 2, 4, 5).
#include <gtest/gtest.h>

#include "t800/compute_model.hpp"
#include "t800/cost_model.hpp"
#include "t800/timing_table.hpp"

using t800::CostModel;
using t800::OperationMix;
using t800::Precision;

namespace {
t800::ProcessorConfig t800_20() {
  return {};
}
}  // namespace

TEST(CostModel, IntegerInstructionsAddUp) {
  OperationMix m;
  m.int_simple = 10;
  m.word_loads = 3;  // ldl 2
  m.loop_ends = 2;   // lend 10
  m.prefixes = 4;    // 1 each
  EXPECT_EQ(CostModel(t800_20(), Precision::real32).cycles(m), 10 + 3 * 2 + 2 * 10 + 4);
}

TEST(CostModel, FpuOverlapsTheIntegerUnit) {
  OperationMix m;
  m.fp_add = 1;  // REAL32: FPU 6, issue 2 -> 8
  EXPECT_EQ(CostModel(t800_20(), Precision::real32).cycles(m), 6 + 2);
  // Integer work shorter than the FPU's hides behind it ...
  m.int_simple = 5;
  EXPECT_EQ(CostModel(t800_20(), Precision::real32).cycles(m), 8);
  // ... and longer integer work hides the FPU.
  m.int_simple = 20;
  EXPECT_EQ(CostModel(t800_20(), Precision::real32).cycles(m), 22);
}

TEST(CostModel, Real64IsSlowerWhereTheTableSaysSo) {
  OperationMix m;
  m.fp_mul = 1;
  m.fp_div = 1;
  EXPECT_EQ(CostModel(t800_20(), Precision::real32).cycles(m), 11 + 16 + 4);
  EXPECT_EQ(CostModel(t800_20(), Precision::real64).cycles(m), 18 + 31 + 4);
}

TEST(CostModel, ExternalDataCostsExtraCyclesPerWord) {
  t800::ProcessorConfig p;
  p.memory.data = t800::Placement::external;
  p.memory.wait_states = 1;
  OperationMix m;
  m.word_loads = 10;
  // 10 x (2 cycles + 2 external + 1 wait state)
  EXPECT_EQ(CostModel(p, Precision::real32).cycles(m), 10 * (2 + 2 + 1));
}

TEST(CostModel, CodeEfficiencyScalesEverything) {
  OperationMix m;
  m.int_simple = 100;
  EXPECT_EQ(CostModel(t800_20(), Precision::real32, 1.5).cycles(m), 150);
}

TEST(CostModel, SineIsASoftwareRoutine) {
  OperationMix one;
  one.sincos = 1;
  const auto c64 = CostModel(t800_20(), Precision::real64).cycles(one);
  const auto c32 = CostModel(t800_20(), Precision::real32).cycles(one);
  // "hundreds of cycles" (docs/t800-timing.md section 4), and fewer terms in REAL32.
  EXPECT_GT(c64, 100);
  EXPECT_LT(c64, 1000);
  EXPECT_LT(c32, c64);
}

// ldlp buffer (1), ldl channel (2), ldc length (1, plus a prefix byte from 16), then in or out:
// 2w + 19 with the copy, 19 when a link engine moves the bytes (the datasheet's table).
TEST(ComputeModel, CommunicationAsOccamCompilesIt) {
  const t800::ComputeModel m(t800_20(), t800::ComputeSettings{});
  EXPECT_EQ(m.communication_cycles(8, true), 1 + 2 + 1 + 2 * 2 + 19);
  EXPECT_EQ(m.communication_cycles(40, true), 1 + 2 + 2 + 2 * 10 + 19);  // ldc 40: pfix, ldc
  EXPECT_EQ(m.communication_cycles(41, true), 1 + 2 + 2 + 2 * 11 + 19);  // part words are whole
  EXPECT_EQ(m.communication_cycles(4000, false), 1 + 2 + 3 + 19);        // ldc 4000: two prefixes
}

TEST(CostModel, ProcessorTypes) {
  t800::ProcessorConfig p;
  p.type = t800::ProcessorType::T800_25;
  EXPECT_DOUBLE_EQ(CostModel(p, Precision::real32).cycle_ns(), 40.0);
  EXPECT_EQ(t800::parse_processor_type("T800-30"), t800::ProcessorType::T800_30);
  EXPECT_FALSE(t800::parse_processor_type("T801-20").has_value());
}
