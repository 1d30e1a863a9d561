// Instruction timing against the datasheet's table summed by hand (T800-20, on-chip memory): the
// basic operation's cycles plus one cycle per prefix byte; the FPU running beside the integer unit.
#include <gtest/gtest.h>

#include "t800/processors/sequence_timing.hpp"

namespace {

using t800::isa::Instruction;
using t800::isa::Op;
using t800::isa::Region;

std::int64_t cycles(const t800::isa::Sequence& code, t800::MemoryView memory = {},
                    t800::ProcessorType type = t800::ProcessorType::T800_20) {
  return t800::time_sequence(code, t800::processor_model(type), memory).cycles;
}

Instruction in(Op op, std::int64_t operand = 0, Region region = Region::none) {
  Instruction i;
  i.op = op;
  i.operand = operand;
  i.data = {region, region == Region::array ? 0 : -1};
  return i;
}

// ldc 1, ldl 2, add 1, stl 1 (the table), no prefixes.
TEST(InstructionTiming, IntegerInstructionsAddUp) {
  EXPECT_EQ(cycles({in(Op::ldc, 5), in(Op::ldl, 3), in(Op::add), in(Op::stl, 2)}), 5);
}

// A prefix byte is one cycle: ldc 100 = pfix; ldc (2), ldl 20 = pfix; ldl (3), ldc -1 = nfix; ldc.
TEST(InstructionTiming, PrefixesCostACycleEach) {
  EXPECT_EQ(cycles({in(Op::ldc, 100)}), 2);
  EXPECT_EQ(cycles({in(Op::ldl, 20)}), 3);
  EXPECT_EQ(cycles({in(Op::ldc, -1)}), 2);
  EXPECT_EQ(cycles({in(Op::ldc, 20000)}), 4);
}

// ldlp (1), fpldnlsn (pfix + 2), twice: 8; fpadd: pfix, then 6 on the FPU: 15.
TEST(InstructionTiming, FpuOperationsIncludeTheirOpcodePrefix) {
  EXPECT_EQ(
      cycles({in(Op::ldlp, 0), in(Op::fpldnlsn), in(Op::ldlp, 1), in(Op::fpldnlsn), in(Op::fpadd)}),
      15);
}

// The store must wait for the product: ldlp (0-1), fpldnlsn (2-4), ldlp (4-5), fpldnlmulsn issued
// at 6, the FPU busy until 6 + 13 = 19; ldlp (8-9); fpstnlsn waits for 19, ends at 21.
TEST(InstructionTiming, AStoreWaitsForTheFpu) {
  const t800::isa::Sequence code = {in(Op::ldlp, 0),     in(Op::fpldnlsn), in(Op::ldlp, 1),
                                    in(Op::fpldnlmulsn), in(Op::ldlp, 2),  in(Op::fpstnlsn)};
  EXPECT_EQ(cycles(code), 21);
}

// Integer work after the multiply runs while the FPU multiplies: ldl, ldl, add, stl take the IU
// from 8 to 14, the FPU is done at 19, and that is the end; nothing waits.
TEST(InstructionTiming, IntegerWorkOverlapsTheFpu) {
  const t800::isa::Sequence code = {in(Op::ldlp, 0),     in(Op::fpldnlsn), in(Op::ldlp, 1),
                                    in(Op::fpldnlmulsn), in(Op::ldl, 5),   in(Op::ldl, 6),
                                    in(Op::add),         in(Op::stl, 7)};
  EXPECT_EQ(cycles(code), 19);
  std::vector<t800::InstructionTime> trace;
  t800::time_sequence(code, t800::processor_model(t800::ProcessorType::T800_20), {}, Region::code,
                      &trace);
  EXPECT_EQ(trace[4].start, 8);  // ldl right after the multiply's load part
  EXPECT_EQ(trace[7].iu_end, 14);
}

// External memory: the shortest access is three processor cycles against one on chip, so an ldl
// of an external workspace word takes 2 + 2; each wait state adds half a cycle, whole cycles per
// access.
TEST(InstructionTiming, ExternalDataAccessesTakeTheBus) {
  t800::MemoryView external;
  external.workspace_external = true;
  EXPECT_EQ(cycles({in(Op::ldl, 3, Region::workspace)}, external), 4);
  external.external_cycles = 3 + 1;  // two wait states
  EXPECT_EQ(cycles({in(Op::ldl, 3, Region::workspace)}, external), 5);
  t800::MemoryView on_chip;
  EXPECT_EQ(cycles({in(Op::ldl, 3, Region::workspace)}, on_chip), 2);
}

// Code in external memory is fetched a word at a time: a sequence of one-cycle instructions waits
// for its code.
TEST(InstructionTiming, ExternalCodeIsFetched) {
  t800::isa::Sequence code(16, in(Op::ldc, 1));
  t800::MemoryView external;
  external.code_external = true;
  EXPECT_EQ(cycles(code), 16);
  EXPECT_GT(cycles(code, external), 16);
}

// A T414 has no FPU instructions.
TEST(InstructionTiming, AT414HasNoFpu) {
  EXPECT_THROW(cycles({in(Op::fpadd)}, {}, t800::ProcessorType::T414_20), std::logic_error);
  EXPECT_EQ(cycles({in(Op::ldc, 5), in(Op::ldl, 3), in(Op::add), in(Op::stl, 2)}, {},
                   t800::ProcessorType::T414_20),
            5);
}

}  // namespace
