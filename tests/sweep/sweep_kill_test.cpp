// A sweep stopped while its points run ends them: SIGTERM and SIGINT it catches and ends its
// children itself; SIGKILL it cannot catch, and its children die with it (PR_SET_PDEATHSIG). The
// rows of the points that finished stay in the CSV, and running the same sweep again runs exactly
// the others.
#include <gtest/gtest.h>

#include <algorithm>
#include <csignal>
#include <set>

#include "sweep_fixtures.hpp"

namespace {

using sweep_test::column;
using sweep_test::table;

class SweepStopped : public ::testing::TestWithParam<int> {};

TEST_P(SweepStopped, EndsItsRunningPointsAndAReRunResumesExactly) {
  const int signal = GetParam();
  const std::string out = sweep_test::fresh_dir() + "/r.csv";
  // Six points of about half a second each (simulated step by step), two at a time.
  const std::vector<std::string> args = {"sweep",  "configs/scenes/trajectory.toml",
                                         "--vary", "workload.steps=100..105",
                                         "--set",  "fidelity.reuse_steps=false",
                                         "-j",     "2",
                                         "-o",     out};
  const pid_t sweep = cli_test::start(args);
  std::vector<pid_t> points;
  ASSERT_TRUE(cli_test::wait_until(
      [&] { return (points = cli_test::children_of(sweep)).size() == 2; }, 60));
  kill(sweep, signal);
  int status = 0;
  waitpid(sweep, &status, 0);
  if (signal == SIGKILL)
    EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL);
  else
    EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 128 + signal) << status;
  EXPECT_TRUE(cli_test::wait_until(
      [&] { return std::all_of(points.begin(), points.end(), cli_test::ended); }, 5))
      << "a point outlived its sweep";

  const auto before = table(out);
  ASSERT_GE(before.size(), 1u);
  for (std::size_t r = 1; r < before.size(); ++r)
    EXPECT_EQ(before[r][column(before, "status")], "ok");  // an ended point is not a result

  std::string command;
  for (const std::string& a : args) command += a + " ";
  const auto rerun = cli_test::run(command + "2>&1");
  EXPECT_EQ(rerun.exit_code, 0) << rerun.out;
  const auto after = table(out);
  ASSERT_EQ(after.size(), 7u) << rerun.out;
  std::set<std::string> steps;
  for (std::size_t r = 1; r < after.size(); ++r) {
    steps.insert(after[r][0]);
    EXPECT_EQ(after[r][column(after, "status")], "ok");
  }
  EXPECT_EQ(steps, (std::set<std::string>{"100", "101", "102", "103", "104", "105"}));
  for (std::size_t r = 1; r < before.size(); ++r)  // kept exactly, wall time included: not rerun
    EXPECT_NE(std::find(after.begin(), after.end(), before[r]), after.end());
}

INSTANTIATE_TEST_SUITE_P(Signals, SweepStopped, ::testing::Values(SIGKILL, SIGTERM, SIGINT),
                         [](const auto& info) -> std::string {
                           return info.param == SIGKILL   ? "KILL"
                                  : info.param == SIGTERM ? "TERM"
                                                          : "INT";
                         });

}  // namespace
