// The ISS times every instruction with the rule the static model uses: for straight-line code the
// cycles of running it equal time_sequence's for the same instructions, and a hand count from the
// datasheet's table.
#include <gtest/gtest.h>

#include "t800/processors/sequence_timing.hpp"
#include "tests/iss/iss_fixtures.hpp"

namespace {

using iss_test::TestMachine;
using t800::isa::Instruction;
using t800::isa::Op;
using t800::iss::StopReason;

Instruction in(Op op, std::int64_t operand = 0, std::int64_t param = 0, bool real64 = false) {
  Instruction i;
  i.op = op;
  i.operand = operand;
  i.param = param;
  i.real64 = real64;
  return i;
}

TEST(IssTiming, HandCountFromTheTable) {
  // ldc 1 (1) + ldc 2 (1) + add (1) + stopp (11, prefixed: pfix 1; opr 5 = +1) and ajw 16
  // (pfix 1; ajw 0: 1 + 1) = 2 + 3 + 12 = 17 cycles.
  TestMachine m;
  m.boot("ajw 16\nldc 1\nldc 2\nadd\nstopp\n");
  EXPECT_EQ(m.run(), StopReason::idle);
  EXPECT_EQ(m.core.cycle(), 17);
}

TEST(IssTiming, StraightLineCodeTakesWhatTheStaticModelSays) {
  // Integer and FPU instructions overlapping, loads and stores: the static model's sequence
  // and the ISS's run of the same bytes.
  const std::string source = R"(
        ajw 16
        ldc 3
        stl 1
        ldl 1
        ldl 1
        mul
        stl 2
        ldlp 4
        fpldzerosn
        fpldzerosn
        fpadd
        ldc 5
        ldc 7
        add
        stl 3
        fpstnlsn
        ldlp 6
        fpldzerodb
        fpdup
        fpmul
        fpstnldb
        ldc 1
        ldc 9
        shl
        stl 5
        stopp
)";
  const t800::isa::Sequence sequence = {
      in(Op::ajw, 16),    in(Op::ldc, 3),     in(Op::stl, 1), in(Op::ldl, 1),
      in(Op::ldl, 1),     in(Op::mul),        in(Op::stl, 2), in(Op::ldlp, 4),
      in(Op::fpldzerosn), in(Op::fpldzerosn), in(Op::fpadd),  in(Op::ldc, 5),
      in(Op::ldc, 7),     in(Op::add),        in(Op::stl, 3), in(Op::fpstnlsn),
      in(Op::ldlp, 6),    in(Op::fpldzerodb), in(Op::fpdup),  in(Op::fpmul, 0, 0, true),
      in(Op::fpstnldb),   in(Op::ldc, 1),     in(Op::ldc, 9), in(Op::shl, 0, 9),
      in(Op::stl, 5),     in(Op::stopp)};
  TestMachine m;
  m.boot(source);
  EXPECT_EQ(m.run(), StopReason::idle);
  const auto expected = t800::time_sequence(
      sequence, t800::processor_model(t800::ProcessorType::T800_20), t800::MemoryView{});
  EXPECT_EQ(m.core.cycle(), expected.cycles);
  EXPECT_EQ(m.core.timing().instructions, expected.instructions);
  EXPECT_EQ(m.core.timing().bytes, expected.bytes);
  EXPECT_EQ(m.core.timing().fpu_busy, expected.fpu_busy);
}

TEST(IssTiming, ExternalMemoryCostsItsAccessCycles) {
  // ldnl from on-chip memory: 2 cycles; from external memory it waits for the bus: one access of
  // 3 cycles (+ wait states) instead of the table's one cycle.
  auto cycles = [](std::uint32_t address, int wait_states) {
    TestMachine m(t800::ProcessorType::T800_20, 1 << 20, t800::iss::AddressPolicy::wrap,
                  wait_states);
    m.boot("ajw 16\nldc " + std::to_string(address) + "\nldnl 0\nstopp\n");
    m.run();
    return m.core.cycle();
  };
  const std::int64_t on_chip = cycles(0x80000200u, 0), external = cycles(0x80010000u, 0);
  EXPECT_EQ(external - on_chip, 3 - 1);
  EXPECT_EQ(cycles(0x80010000u, 2) - on_chip, 3 + 2 - 1);
}

// Code in external memory is fetched a word at a time, one word ahead (docs/t800-timing.md, 5): a
// jump empties the prefetch buffer, and the target's code is fetched from the target. How far the
// jump goes does not matter: the words it jumps over are never fetched.
std::int64_t cycles_of_forward_jump(int padding) {
  TestMachine m(t800::ProcessorType::T800_20, 2 << 20);
  // The jump and its target both in external memory (past the 4 KB on chip), each word-aligned.
  m.boot(
      "        ajw 16\n        j far\n        .space 8192\n        .align 4\n"
      "far:    j target\n        .space " +
      std::to_string(padding) + "\n        .align 4\ntarget: stopp\n");
  EXPECT_EQ(m.run(), StopReason::idle);
  return m.core.cycle();
}

TEST(IssTiming, AForwardJumpInExternalMemoryCostsWhatAJumpCosts) {
  // Both jumps are five bytes (pfix pfix pfix pfix j: the offsets need five nibbles), so they
  // differ in nothing but distance.
  const std::int64_t over_64k = cycles_of_forward_jump(64 << 10);
  EXPECT_EQ(over_64k, cycles_of_forward_jump(960 << 10));
  // Against a jump over 16 bytes (pfix j, two bytes, one word): three more prefix cycles and at
  // most one more code word (3 cycles), not the 16,384 words in between (some 49,000 cycles).
  const std::int64_t over_16 = cycles_of_forward_jump(16);
  EXPECT_GE(over_64k, over_16 + 3);
  EXPECT_LE(over_64k, over_16 + 3 + 3);
}

}  // namespace
