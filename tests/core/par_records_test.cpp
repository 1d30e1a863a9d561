// A PAR in a loop spawns the same branches every time round; each branch's record is used again by
// the next PAR's branch of its index (network::Process::start_branch), so a long run keeps one
// record per branch, not one per branch ever run -- and nothing the ended branch left behind
// changes what the next one does or how a deadlock report reads.
#include <gtest/gtest.h>

#include "core_fixtures.hpp"

namespace {

using network::Machine;
using network::Process;
using t800::Priority;

// 50 rounds of a 3-branch PAR: 150 branches run, on 3 records. The time is the hand-worked sum of
// what one processor does, one thing after another: per round the parent's three start-process
// instructions, and each branch's 10 cycles and its end-process instruction.
TEST(ParRecords, ALoopOfParsKeepsOneRecordPerBranchAndItsTiming) {
  Machine m(core_test::chain(1), core_test::options(20));
  int branches_run = 0;
  const int rounds = 50;
  m.spawn(0, "looper", Priority::low, [&](Process& p) {
    auto branch = [&](Process& b) {
      b.compute(10, "work");
      ++branches_run;
    };
    for (int r = 0; r < rounds; ++r) p.par({branch, branch, branch});
  });
  ASSERT_TRUE(m.run().empty());
  EXPECT_EQ(branches_run, 3 * rounds);
  EXPECT_EQ(m.processes().size(), 4u);  // looper and its three branches
  const std::int64_t cycles_per_round =
      3 * (t800::timing::start_process_cycles() + 10 + t800::timing::end_process_cycles());
  EXPECT_DOUBLE_EQ(m.simulated_us(),
                   m.transputer(0).cpu().cycles(rounds * cycles_per_round).to_seconds() * 1e6);
}

// The channel was last read by the first PAR's branch, which has ended; the second PAR's branch of
// the same name -- on the same record -- waits elsewhere. The writer left waiting is reported as
// waiting for the branch that has ended, not for the one now running under its name.
TEST(ParRecords, ADeadlockReportNamesTheEndedBranchNotItsSuccessor) {
  Machine m(core_test::chain(1), core_test::options(20));
  auto& c = m.channel("c", 0, 0);
  auto& never = m.channel("never", 0, 0);
  m.spawn(0, "writer", Priority::low, [&](Process& p) {
    p.out(c, {4, {}, "x"});
    p.out(c, {4, {}, "x"});
  });
  m.spawn(0, "looper", Priority::low, [&](Process& p) {
    p.par({[&](Process& b) { b.in(c); }});
    p.par({[&](Process& b) { b.in(never); }});
  });
  const std::vector<network::BlockedProcess> blocked = m.run();
  EXPECT_EQ(m.processes().size(), 3u);  // the second branch took the first one's record
  ASSERT_EQ(blocked.size(), 3u);
  // Listed in the order they were spawned, as when every branch had a record of its own.
  EXPECT_EQ(blocked[0].process, "writer");
  EXPECT_EQ(blocked[1].process, "looper");
  EXPECT_EQ(blocked[2].process, "looper.0");
  EXPECT_EQ(blocked[0].waits_for, "looper.0 on P0, which has ended");
  EXPECT_EQ(blocked[2].status, "in on channel never");
}

}  // namespace
