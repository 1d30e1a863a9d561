// Core::checkpoint and rollback (t800/iss/checkpoint.cpp): a core run ahead and brought back must
// be the core it was, so that run on again it runs as one that never went ahead -- cycle for cycle,
// byte for byte, with the same blocks replayed. A network undoes a run ahead when an arrival proves
// it wrong (workloads/boot/iss_node.cpp); these tests undo runs at every slice of a program that
// has what a run can change: timers and an interrupting process, process switches, the FPU, data
// and code on chip and off, Error and a halt, code written over.
#include <gtest/gtest.h>

#include <cstdint>
#include <string>

#include "tests/iss/iss_fixtures.hpp"

namespace {

using iss_test::mixed_loop;
using iss_test::TestMachine;
using t800::iss::Core;
using t800::iss::StopReason;
using t800::iss::Word;

constexpr std::int64_t kCheckpointInstalled = 1 << 20;

// What a run leaves that a core brought back must have as it was (FNV-1a over memory's words). Not
// the block engine's counts: a core brought back keeps the blocks it decoded and timed ahead (they
// hold only what memory says), so it replays where the other times; the counts are checked apart.
struct Seen {
  std::int64_t cycle, instructions, iu_busy, fpu_busy, memory_cycles;
  Word a, b, c, iptr, wptr;
  bool error, halted;
  std::uint64_t memory_hash;
  bool operator==(const Seen& o) const {
    return cycle == o.cycle && instructions == o.instructions && iu_busy == o.iu_busy &&
           fpu_busy == o.fpu_busy && memory_cycles == o.memory_cycles && a == o.a && b == o.b &&
           c == o.c && iptr == o.iptr && wptr == o.wptr && error == o.error && halted == o.halted &&
           memory_hash == o.memory_hash;
  }
};

Seen seen(const Core& core) {
  std::uint64_t hash = 1469598103934665603ull;
  for (Word a = t800::iss::kMostNeg; a != t800::iss::kMostNeg + Word(kCheckpointInstalled); a += 4)
    hash = (hash ^ core.memory().word(a)) * 1099511628211ull;
  const auto& r = core.registers();
  return {core.cycle(),
          core.instructions(),
          core.timing().iu_busy,
          core.timing().fpu_busy,
          core.timing().memory_cycles,
          r.a,
          r.b,
          r.c,
          r.iptr,
          r.wptr,
          r.error,
          core.halted(),
          hash};
}

// Lets time pass as a network would between slices: due timers fire while the core is idle.
bool idle_to_next_timer(TestMachine& m) {
  const auto due = m.core.next_timer_cycle();
  if (!due) return false;
  m.core.advance_to(*due);
  return true;
}

// Runs `source` on two cores in slices of `slice` cycles; before each slice the second goes
// `ahead` cycles further, is brought back and must be as it was; then both run the slice and must
// agree. Returns how the run ended.
StopReason run_with_undone_runs(const std::string& source, std::int64_t slice, std::int64_t ahead) {
  TestMachine straight, undone;
  straight.boot(source);
  undone.boot(source);
  for (int n = 0; n < 100'000; ++n) {
    const Seen before = seen(undone.core);
    const auto counts = undone.core.block_counts();
    undone.core.checkpoint();
    undone.core.run(undone.core.cycle() + ahead, 10'000'000);
    const bool went_ahead = undone.core.cycle() != before.cycle;
    undone.core.rollback();
    EXPECT_FALSE(undone.core.checkpointed());
    EXPECT_TRUE(seen(undone.core) == before) << "slice " << n << (went_ahead ? "" : " (not run)");
    EXPECT_EQ(undone.core.block_counts().replayed, counts.replayed) << "slice " << n;
    EXPECT_EQ(undone.core.block_counts().instructions, counts.instructions) << "slice " << n;
    const StopReason a = straight.core.run(straight.core.cycle() + slice, 10'000'000);
    const StopReason b = undone.core.run(undone.core.cycle() + slice, 10'000'000);
    EXPECT_EQ(a, b) << "slice " << n;
    if (!(seen(straight.core) == seen(undone.core))) {
      ADD_FAILURE() << "slice " << n << ": the core brought back runs differently";
      return a;
    }
    if (a == StopReason::running) continue;
    if (a == StopReason::halted || a == StopReason::limit) return a;
    const bool timer = idle_to_next_timer(straight);
    EXPECT_EQ(timer, idle_to_next_timer(undone));
    if (!timer) return a;
  }
  ADD_FAILURE() << "the program did not end";
  return StopReason::running;
}

TEST(Checkpoint, RunsUndoneAtEverySliceLeaveTheProgramAsRunStraight) {
  // Code on chip and off; slices short enough to cut the timer's interrupt and the blocks.
  for (int padding : {16, 5000}) {
    EXPECT_EQ(run_with_undone_runs(mixed_loop(padding, 200), 311, 2000), StopReason::idle)
        << padding;
  }
}

TEST(Checkpoint, AHaltUndoneIsForgottenAndComesAgainWhereItWas) {
  const std::string source = R"(
        ajw 16
        sethalterr
        ldc 40
        stl 1
loop:   ldl 1
        adc -1
        stl 1
        ldl 1
        cj over
        j loop
over:   ldc #7FFFFFFF
        adc 1
        stopp
)";
  EXPECT_EQ(run_with_undone_runs(source, 50, 400), StopReason::halted);
}

TEST(Checkpoint, CodeWrittenOverAndUndoneRunsAsItWasBefore) {
  // The program adds one to the `ldc 1` at `target` (#41 -> #42) and runs it: stl 1 gets 2.
  TestMachine m;
  const auto program = m.boot(R"(
        ajw 16
        ldc target - here
        ldpi
here:   lb
        adc 1
        ldc target - there
        ldpi
there:  sb
target: ldc 1
        stl 1
        stopp
)");
  const Word target = program.labels.at("target");
  m.core.checkpoint();
  EXPECT_EQ(m.run(), StopReason::idle);
  const Word wptr = m.core.registers().wptr;  // after its ajw
  EXPECT_EQ(m.word(wptr + 4), 2u);
  EXPECT_EQ(m.core.memory().byte(target), 0x42);
  m.core.rollback();
  EXPECT_EQ(m.core.memory().byte(target), 0x41);
  EXPECT_EQ(m.word(wptr + 4), 0u);
  // Back at the boot, the process holds the CPU at MemStart: sent straight to `target` instead, it
  // runs the code as it was before the run, and a decoded `ldc 2` kept from the undone run would
  // store 2.
  m.core.registers().iptr = target;
  m.core.registers().wptr = wptr;
  EXPECT_EQ(m.run(), StopReason::idle);
  EXPECT_EQ(m.word(wptr + 4), 1u);
}

TEST(Checkpoint, ACommittedRunStandsAndWritesAreNoLongerKept) {
  TestMachine m;
  m.boot("ajw 16\nldc 5\nstl 1\nstopp\n");
  m.core.checkpoint();
  EXPECT_EQ(m.run(), StopReason::idle);
  const Word wptr = m.core.registers().wptr;
  m.core.commit();
  EXPECT_FALSE(m.core.checkpointed());
  m.core.rollback();  // nothing to go back to: no effect
  EXPECT_EQ(m.word(wptr + 4), 5u);
  EXPECT_TRUE(m.core.idle());
}

}  // namespace
