// The scheduler, channels, timers and halts of the ISS, on programs assembled here. Expected
// values by hand from the CWG's definitions and the datasheet's timer rates.
#include <gtest/gtest.h>

#include "tests/iss/iss_fixtures.hpp"

namespace {

using iss_test::TestMachine;
using iss_test::Word;
using t800::iss::StopReason;

// PAR of two processes joined by endp; the child outputs a word the parent inputs over an
// internal channel (the channel and the join block in the parent's workspace).
constexpr const char* kParWithChannel = R"(
        ajw 64
        ldc join - l1
        ldpi
l1:     stl 0            -- ws[0]: where the PAR continues
        ldc 2
        stl 1            -- ws[1]: two branches to end
        mint
        stl 2            -- ws[2]: the channel, empty
        ldc child - l2
        ldlp -20         -- the child's workspace, 20 words below
        startp
l2:     ldlp 3           -- C: where the word goes
        ldlp 2           -- B: the channel
        ldc 4            -- A: 4 bytes
        in
        ldlp 0
        endp
child:  ldc 42
        stl 0
        ldlp 0
        ldlp 22          -- the parent's ws[2]
        ldc 4
        out
        ldlp 20          -- the parent's ws[0]: the join block
        endp
join:   ldl 3
        stopp
)";

TEST(IssScheduler, ParallelProcessesCommunicateAndJoin) {
  TestMachine m;
  m.boot(kParWithChannel);
  EXPECT_EQ(m.run(), StopReason::idle);
  EXPECT_EQ(m.core.registers().a, 42u);
  // Only the final stopp's process is left waiting, for ever.
  ASSERT_EQ(m.core.waiting().size(), 1u);
  EXPECT_EQ(m.core.waiting()[0].what, "stopped (stopp)");
}

TEST(IssScheduler, TimerInputWaitsUntilTheClockIsAfterTheTime) {
  TestMachine m;
  m.boot(R"(
        ajw 16
        ldc 0
        sttimer
        ldtimer
        adc 100
        tin              -- until the clock is AFTER 100
        ldtimer
        stopp
)");
  EXPECT_EQ(m.run(), StopReason::idle);
  EXPECT_EQ(m.core.registers().a, 101u);
  // The low-priority clock ticks every 64 us: 101 ticks = 6464 us = 129,280 cycles of 50 ns.
  EXPECT_GE(m.core.cycle(), 129280);
  EXPECT_LT(m.core.cycle(), 129280 + 40);
}

TEST(IssScheduler, AltSelectsTheReadyChannel) {
  TestMachine m;
  // Two channels at ws[2] and ws[3]; a child outputs on the second; the ALT must take it.
  const auto p = m.boot(R"(
        ajw 64
        mint
        stl 2
        mint
        stl 3
        ldc child - l1
        ldlp -20
        startp
l1:     alt
        ldlp 2
        ldc 1            -- enbc: A guard, B channel
        enbc
        ldlp 3
        ldc 1
        enbc
        altwt
        ldlp 2           -- disc: A offset, B guard, C channel
        ldc 1
        ldc first - done
        disc
        ldlp 3
        ldc 1
        ldc second - done
        disc
        altend
done:
first:  ldc 1
        stopp
second: ldlp 4           -- take the message
        ldlp 3
        ldc 4
        in
        ldl 4
        ldc result
        stnl 0
        stopp
child:  ldc 7
        stl 0
        ldlp 0
        ldlp 23          -- the parent's ws[3]
        ldc 4
        out
        stopp
        .align 4
result: .word 0
)");
  EXPECT_EQ(m.run(), StopReason::idle);
  EXPECT_EQ(m.word(p.labels.at("result")), 7u);
}

TEST(IssScheduler, LinkOutputAndInputGoThroughTheEngine) {
  TestMachine m;
  m.links.incoming[2] = {1, 2, 3, 4};
  m.boot(R"(
        ajw 16
        ldc #11223344
        stl 0
        ldlp 0
        ldc #80000004    -- link 1's output channel
        ldc 4
        out
        ldlp 1
        ldc #80000018    -- link 2's input channel
        ldc 4
        in
        ldl 1
        stopp
)");
  EXPECT_EQ(m.run(), StopReason::idle);
  EXPECT_EQ(m.links.sent[1], (std::vector<std::uint8_t>{0x44, 0x33, 0x22, 0x11}));
  EXPECT_EQ(m.core.registers().a, 0x04030201u);
}

TEST(IssScheduler, TwoInputsWithNoOutputAreReportedAsWaiting) {
  TestMachine m;
  m.boot(R"(
        ajw 16
        ldlp 1
        ldc #8000001C    -- link 3's input: nothing ever comes
        ldc 4
        in
        stopp
)");
  EXPECT_EQ(m.run(), StopReason::idle);
  ASSERT_EQ(m.core.waiting().size(), 1u);
  EXPECT_EQ(m.core.waiting()[0].what, "input");
  EXPECT_EQ(m.core.waiting()[0].channel, 0x8000001Cu);
}

TEST(IssHalt, UndefinedOperationHaltsWithAReport) {
  TestMachine m;
  m.boot("ajw 16\nopr #1FE\n");
  EXPECT_EQ(m.run(), StopReason::halted);
  ASSERT_TRUE(m.core.halt_report());
  EXPECT_NE(m.core.halt_report()->reason.find("undefined operation #1FE"), std::string::npos);
  EXPECT_EQ(m.core.halt_report()->iptr, m.core.mem_start() + 2);  // after ajw 16 (pfix 1; ajw 0)
}

TEST(IssHalt, HaltOnErrorHaltsAtTheInstructionThatSetError) {
  TestMachine m;
  m.boot("ajw 16\nsethalterr\nldc #7FFFFFFF\nadc 1\nstopp\n");
  EXPECT_EQ(m.run(), StopReason::halted);
  EXPECT_NE(m.core.halt_report()->reason.find("HaltOnError: Error set by adc"), std::string::npos);
}

TEST(IssHalt, StrictAddressingHaltsOnAWildAccessAndWrapWraps) {
  TestMachine strict(t800::ProcessorType::T800_20, 1 << 16, t800::iss::AddressPolicy::strict);
  strict.boot("ajw 16\nldc #80100000\nldnl 0\nstopp\n");
  EXPECT_EQ(strict.run(), StopReason::halted);
  EXPECT_NE(strict.core.halt_report()->reason.find("#80100000"), std::string::npos);

  TestMachine wrap(t800::ProcessorType::T800_20, 1 << 16);
  wrap.boot("ajw 16\nldc 99\nldc #80200100\nstnl 0\nldc #80000100\nldnl 0\nstopp\n");
  EXPECT_EQ(wrap.run(), StopReason::idle);
  EXPECT_EQ(wrap.core.registers().a, 99u);  // #80200100 wraps modulo 64 KiB to #80000100
}

TEST(IssHalt, T800OnlyInstructionsHaltATransputerWithoutThem) {
  TestMachine m(t800::ProcessorType::T414_20);
  m.boot("ajw 16\nldc 1\ndup\nstopp\n");
  EXPECT_EQ(m.run(), StopReason::halted);
  EXPECT_NE(m.core.halt_report()->reason.find("not an instruction of the T414"), std::string::npos);
}

}  // namespace
