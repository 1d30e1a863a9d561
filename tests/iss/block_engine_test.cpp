// The block engine (t800/iss/blocks.hpp) replays the timing of straight-line code: a program must
// run the same, cycle for cycle and byte for byte, as when every instruction is stepped through the
// timing rule. Each test runs one program on two processors, one with blocks and one without, and
// compares everything the processor shows; the programs are made so that blocks recur in different
// ways (data on chip and off, REAL32 and REAL64, code on chip and off) and are cut short (a timer
// interrupt, a halt, a fault, code written ahead of itself).
#include <gtest/gtest.h>

#include <string>

#include "tests/iss/iss_fixtures.hpp"

namespace {

using iss_test::mixed_loop;
using iss_test::TestMachine;
using t800::iss::AddressPolicy;
using t800::iss::StopReason;
using t800::iss::Word;

constexpr std::int64_t kInstalled = 1 << 20;

struct Twins {
  explicit Twins(AddressPolicy policy = AddressPolicy::wrap, int wait_states = 0)
      : blocks(t800::ProcessorType::T800_20, kInstalled, policy, wait_states, true),
        steps(t800::ProcessorType::T800_20, kInstalled, policy, wait_states, false) {}

  void boot(const std::string& source) {
    blocks.boot(source);
    steps.boot(source);
  }
  // Runs both in slices of `slice` cycles (the way a network drives a core between its
  // synchronisations) and checks that each slice ends at the same instruction and cycle.
  StopReason run(std::int64_t slice) {
    for (int n = 0; n < 1'000'000; ++n) {
      const StopReason a = blocks.core.run(blocks.core.cycle() + slice, 10'000'000);
      const StopReason b = steps.core.run(steps.core.cycle() + slice, 10'000'000);
      EXPECT_EQ(a, b) << "slice " << n;
      EXPECT_EQ(blocks.core.cycle(), steps.core.cycle()) << "slice " << n;
      EXPECT_EQ(blocks.core.instructions(), steps.core.instructions()) << "slice " << n;
      if (a != b || blocks.core.cycle() != steps.core.cycle()) return a;
      if (a == StopReason::running) continue;
      if (a == StopReason::halted || a == StopReason::limit) return a;
      const bool delivered = blocks.links.deliver();
      EXPECT_EQ(delivered, steps.links.deliver());
      if (delivered) continue;
      const auto due = blocks.core.next_timer_cycle();
      EXPECT_EQ(due, steps.core.next_timer_cycle());
      if (!due) return a;
      blocks.core.advance_to(*due);
      steps.core.advance_to(*due);
    }
    ADD_FAILURE() << "the program did not end";
    return StopReason::running;
  }

  // Everything a run leaves that the two must agree on.
  void expect_same() const {
    const auto& x = blocks.core;
    const auto& y = steps.core;
    EXPECT_EQ(x.cycle(), y.cycle());
    EXPECT_EQ(x.instructions(), y.instructions());
    const t800::StepTotals& p = x.timing();
    const t800::StepTotals& q = y.timing();
    EXPECT_EQ(p.iu_busy, q.iu_busy);
    EXPECT_EQ(p.fpu_busy, q.fpu_busy);
    EXPECT_EQ(p.fpu_waits, q.fpu_waits);
    EXPECT_EQ(p.fetch_waits, q.fetch_waits);
    EXPECT_EQ(p.memory_cycles, q.memory_cycles);
    EXPECT_EQ(p.bytes, q.bytes);
    EXPECT_EQ(p.instructions, q.instructions);
    EXPECT_EQ(x.registers().a, y.registers().a);
    EXPECT_EQ(x.registers().b, y.registers().b);
    EXPECT_EQ(x.registers().c, y.registers().c);
    EXPECT_EQ(x.registers().iptr, y.registers().iptr);
    EXPECT_EQ(x.registers().wptr, y.registers().wptr);
    EXPECT_EQ(x.registers().error, y.registers().error);
    EXPECT_EQ(x.halted(), y.halted());
    if (x.halted() && y.halted()) {
      EXPECT_EQ(x.halt_report()->reason, y.halt_report()->reason);
      EXPECT_EQ(x.halt_report()->iptr, y.halt_report()->iptr);
    }
    Word differing = 0;
    for (Word a = t800::iss::kMostNeg; a != t800::iss::kMostNeg + Word(kInstalled); a += 4)
      if (x.memory().word(a) != y.memory().word(a)) ++differing;
    EXPECT_EQ(differing, 0u) << "memory words that differ";
    EXPECT_EQ(y.block_counts().replayed, 0);
  }

  TestMachine blocks, steps;
};

// `padding`: 16 bytes keep the code on chip, 5000 put it in external memory.
void expect_loop_runs_as_stepped(int padding) {
  Twins t;
  t.boot(mixed_loop(padding, 300));
  EXPECT_EQ(t.run(1 << 30), StopReason::idle);
  t.expect_same();
  // The blocks were replayed, not only timed: the test would prove nothing otherwise.
  EXPECT_GT(t.blocks.core.block_counts().replayed, 1000);
}

TEST(BlockEngine, ALoopRunsAsSteppedWithItsCodeOnChip) {
  expect_loop_runs_as_stepped(16);
}

TEST(BlockEngine, ALoopRunsAsSteppedWithItsCodeInExternalMemory) {
  expect_loop_runs_as_stepped(5000);
}

TEST(BlockEngine, WaitStatesAndShortSlicesStopWhereSteppingStops) {
  // Slices of 97 cycles: a block that would end past the slice's end is stepped instead, so every
  // slice ends at the instruction stepping ends it at.
  Twins t(AddressPolicy::wrap, 2);
  t.boot(mixed_loop(5000, 60));
  EXPECT_EQ(t.run(97), StopReason::idle);
  t.expect_same();
  EXPECT_GT(t.blocks.core.block_counts().replayed, 0);
}

TEST(BlockEngine, CodeWrittenAheadInItsOwnBlockRunsAsWritten) {
  // sb writes #42 (ldc 2) over the `ldc 1` after it, in the same straight-line run.
  Twins t;
  t.boot(R"(
        ajw 16
        ldc #42
        ldc target - here
        ldpi
here:   sb
target: ldc 1
        stl 1
        stopp
)");
  EXPECT_EQ(t.run(1 << 30), StopReason::idle);
  t.expect_same();
  EXPECT_EQ(t.blocks.core.memory().word(t.blocks.core.registers().wptr + 4), 2u);
}

TEST(BlockEngine, HaltOnErrorStopsAtTheInstructionThatSetError) {
  Twins t;
  const std::string source = R"(
        ajw 16
        sethalterr
        ldc 1
        ldc 2
        ldc #7FFFFFFF
overflow: adc 1
        ldc 5
        stl 1
        stopp
)";
  const auto program = t.blocks.boot(source);
  t.steps.boot(source);
  EXPECT_EQ(t.run(1 << 30), StopReason::halted);
  t.expect_same();
  EXPECT_EQ(t.blocks.core.halt_report()->iptr, program.labels.at("overflow"));
}

TEST(BlockEngine, AFaultInsideABlockHaltsThereWithTheInstructionsBeforeItDone) {
  Twins t(AddressPolicy::strict);
  t.boot(R"(
        ajw 16
        ldc 7
        stl 1
        ldc #80100000
        ldnl 0
        ldc 5
        stl 2
        stopp
)");
  EXPECT_EQ(t.run(1 << 30), StopReason::halted);
  t.expect_same();
  const Word wptr = t.blocks.core.registers().wptr;
  EXPECT_EQ(t.blocks.core.memory().word(wptr + 4), 7u);
  EXPECT_EQ(t.blocks.core.memory().word(wptr + 8), 0u);
}

// Two low-priority processes, one looping with j and one with lend, each noting in shared words
// who ran last, how often that changed and at which of their iterations: a timeslice is taken at a
// j or lend that ends a block, as of the cycle that instruction starts (not the block's), so the
// two must switch at the same instructions as when stepped. `padding` as in mixed_loop.
// Process `id` notes that it runs after the other: who ran last, the count of switches, and in the
// log the switch's index with this process's count then.
std::string note_switch(int id) {
  return "        ldc " + std::to_string(id) + R"(
        ldc #80000F00
        stnl 0
        ldc #80000F00
        ldnl 1
        adc 1
        dup
        ldc #80000F00
        stnl 1
        ldl 1
        rev
        ldc #80020000
        wsub
        stnl 0
)";
}

// Nine divisions, some 400 cycles of straight-line code.
std::string divisions() {
  std::string code;
  for (int k = 0; k < 9; ++k) code += "        ldc 7\n        div\n";
  return code;
}

std::string timesliced_loops(int padding, int iterations) {
  const std::string n = std::to_string(iterations);
  return R"(
        j start
        .space )" +
         std::to_string(padding) + R"(
start:  ajw 64
        ldc 0
        sttimer
        ldc second - next
        ldpi
next:   stl -41              -- the second's Iptr, below its workspace
        ldlp -40
        adc 1                -- its Wdesc: priority 1, low
        runp
        ldc )" +
         n + R"(
        stl 1
loop:   ldc #80000F00        -- who ran last: if not this one, a switch
        ldnl 0
        eqc 1
        cj switched
        j counted
switched:
)" + note_switch(1) +
         R"(counted: ldl 1
        adc -1
        stl 1
        ldl 1
        cj done
        ldl 1                -- a long block, so a tick is likely to pass between its start and j
)" + divisions() +
         R"(        stl 3
        j loop
done:   stopp
second: ldc 0
        stl 1
        ldc )" +
         n + R"(
        stl 2
again:  ldc #80000F00
        ldnl 0
        eqc 2
        cj switch2
        j other
switch2:
)" + note_switch(2) +
         R"(other:  ldc 1000             -- and another before lend
)" + divisions() +
         R"(        stl 3
        ldlp 1
        ldc ended - again
        lend
ended:  stopp
)";
}

void expect_timeslices_as_stepped(int padding) {
  Twins t;
  t.boot(timesliced_loops(padding, 5000));
  EXPECT_EQ(t.run(1 << 30), StopReason::idle);
  t.expect_same();
  // Each ran several slices, and their j and lend ended replayed blocks.
  EXPECT_GE(t.blocks.core.memory().word(0x80000F04), 4u);
  EXPECT_GT(t.blocks.core.block_counts().replayed, 10000);
}

TEST(BlockEngine, ProcessesTimeslicedAtJAndLendSwitchAsStepped) {
  expect_timeslices_as_stepped(16);
}

TEST(BlockEngine, ProcessesTimeslicedWithTheirCodeInExternalMemorySwitchAsStepped) {
  expect_timeslices_as_stepped(5000);
}

// Instructions whose time depends on their operands end their blocks, and a block is replayed only
// for the parameter it ran with: prod (the highest bit of its operand), shl (the places) and move
// (the words), each with an operand that changes from one iteration to the next and recurs.
TEST(BlockEngine, OperandTimedInstructionsEndBlocksTimedForTheirOperands) {
  Twins t;
  t.boot(R"(
        ajw 64
        ldc 400
        stl 1
loop:   ldl 1
        ldc 7
        and                  -- 0..7, recurring
        stl 2
        ldc 1
        ldl 2
        ldc 3
        mul
        shl                  -- 1 << 3k: prod's operand's highest bit changes
        ldc 5
        prod
        stl 3
        ldc 1
        ldl 2
        shl                  -- shl by 0..7 places
        stl 4
        ldl 2                -- move 4k bytes
        ldc 4
        prod
        stl 5
        ldc #80000E00
        ldc #80020000
        ldl 5
        move
        ldl 1
        adc -1
        stl 1
        ldl 1
        cj done
        j loop
done:   stopp
)");
  EXPECT_EQ(t.run(1 << 30), StopReason::idle);
  t.expect_same();
  EXPECT_GT(t.blocks.core.block_counts().replayed, 1000);
}

}  // namespace
