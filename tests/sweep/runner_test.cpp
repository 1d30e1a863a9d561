// The child-process pool under sweeps: output, exit codes, signals, time limits, parallelism.
#include <gtest/gtest.h>

#include <csignal>
#include <map>

#include <unistd.h>

#include "tools/sweep_runner.hpp"

using tools::ChildOutcome;
using tools::ChildPool;

namespace {
std::map<std::size_t, ChildOutcome> run_all(const std::vector<std::vector<std::string>>& commands,
                                            int parallel, double timeout_s = 0) {
  std::map<std::size_t, ChildOutcome> got;
  ChildPool pool;
  pool.parallel = parallel;
  pool.timeout_s = timeout_s;
  pool.done = [&](std::size_t i, const ChildOutcome& o) { got[i] = o; };
  tools::run_children(commands, pool);
  return got;
}
}  // namespace

TEST(ChildPool, CapturesOutputAndExitCodes) {
  const auto got =
      run_all({{"/bin/sh", "-c", "echo out; echo err >&2; exit 3"}, {"/bin/sh", "-c", "true"}}, 2);
  ASSERT_EQ(got.size(), 2u);
  EXPECT_EQ(got.at(0).out, "out\n");
  EXPECT_EQ(got.at(0).err, "err\n");
  EXPECT_EQ(got.at(0).exit_code, 3);
  EXPECT_EQ(got.at(1).exit_code, 0);
}

TEST(ChildPool, LargeOutputOnBothStreamsDoesNotBlock) {
  const auto got = run_all(
      {{"/bin/sh", "-c", "head -c 300000 /dev/zero | tr '\\0' a; head -c 300000 /dev/zero >&2"}},
      1);
  EXPECT_EQ(got.at(0).out.size(), 300000u);
  EXPECT_EQ(got.at(0).err.size(), 300000u);
}

TEST(ChildPool, ACrashIsReportedWithItsSignal) {
  const auto got = run_all({{"/bin/sh", "-c", "kill -SEGV $$"}}, 1);
  EXPECT_EQ(got.at(0).signal, SIGSEGV);
  EXPECT_EQ(got.at(0).exit_code, -1);
}

TEST(ChildPool, AChildPastItsTimeLimitIsStopped) {
  const auto got = run_all({{"/bin/sleep", "30"}, {"/bin/sh", "-c", "exit 0"}}, 2, 0.3);
  EXPECT_TRUE(got.at(0).timed_out);
  EXPECT_EQ(got.at(0).signal, SIGKILL);
  EXPECT_FALSE(got.at(1).timed_out);
  EXPECT_EQ(got.at(1).exit_code, 0);
}

TEST(ChildPool, AMissingProgramIsAnErrorNotAHang) {
  const auto got = run_all({{"/no/such/program"}}, 1);
  EXPECT_EQ(got.at(0).exit_code, 127);
  EXPECT_NE(got.at(0).err.find("/no/such/program"), std::string::npos) << got.at(0).err;
}

// With -j 2 never more than two at a time: each child takes a slot file, and fails if a third is
// taken.
TEST(ChildPool, RunsAtMostParallelAtOnce) {
  const std::string dir = ::testing::TempDir() + "/pool-slots-" + std::to_string(getpid());
  std::system(("rm -rf " + dir + " && mkdir -p " + dir).c_str());
  const std::string body = "n=$(ls " + dir + " | wc -l); touch " + dir +
                           "/$$; [ $n -lt 2 ] || exit 9; sleep 0.05; rm " + dir + "/$$";
  std::vector<std::vector<std::string>> commands(8, {"/bin/sh", "-c", body});
  const auto got = run_all(commands, 2);
  ASSERT_EQ(got.size(), 8u);
  for (const auto& [i, o] : got) EXPECT_EQ(o.exit_code, 0) << "child " << i;
}
