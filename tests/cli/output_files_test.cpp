// Nothing a run writes is lost or half written: traces and trajectory CSVs replace the previous
// file whole or not at all, every write error is an error, and an unwritable path is found before
// the simulation starts.
#include <gtest/gtest.h>

#include <csignal>
#include <filesystem>

#include "cli_fixtures.hpp"
#include "tests/test_paths.hpp"

namespace {

namespace fs = std::filesystem;

using cli_test::fresh_dir;
using cli_test::read_file;

std::size_t files_in(const std::string& dir) {
  return std::size_t(std::distance(fs::directory_iterator(dir), fs::directory_iterator()));
}

// The trace is written once the simulation has ended; the test waits for the temporary file that
// receives it to appear beside the trace, then kills the run while it writes.
TEST(OutputFiles, ARunKilledWhileWritingItsTraceLeavesThePreviousTraceWhole) {
  const std::string dir = fresh_dir();
  const std::string trace = dir + "/trace.csv";
  std::ofstream(trace) << "the previous trace\n";
  const pid_t run = cli_test::start({"run", "configs/scenes/trajectory.toml", "--set",
                                     "workload.steps=300", "--trace-csv", trace});
  const bool writing = cli_test::wait_until([&] { return files_in(dir) > 1; }, 120);
  kill(run, SIGKILL);
  waitpid(run, nullptr, 0);
  ASSERT_TRUE(writing) << "the run never started writing its trace";
  EXPECT_EQ(read_file(trace), "the previous trace\n");
}

TEST(OutputFiles, AFinishedRunReplacesTheTraceAndLeavesNoTemporaryFile) {
  const std::string dir = fresh_dir();
  const std::string trace = dir + "/trace.csv";
  std::ofstream(trace) << "the previous trace\n";
  const auto o = cli_test::run("run configs/scenes/pingpong.toml --trace-csv " + trace + " 2>&1");
  ASSERT_EQ(o.exit_code, 0) << o.out;
  EXPECT_EQ(read_file(trace).rfind("kind,name,state,start_us,end_us,label\n", 0), 0u);
  EXPECT_EQ(files_in(dir), 1u);
}

TEST(OutputFiles, AWriteErrorIsAnError) {
  const auto trace = cli_test::run("run configs/scenes/pingpong.toml --trace-csv /dev/full 2>&1");
  EXPECT_EQ(trace.exit_code, 1) << trace.out;
  EXPECT_NE(trace.out.find("--trace-csv /dev/full: cannot write it"), std::string::npos)
      << trace.out;
  const auto csv = cli_test::run(
      "run configs/scenes/trajectory.toml --set workload.steps=2 --set "
      "workload.output_csv=/dev/full 2>&1");
  EXPECT_EQ(csv.exit_code, 1) << csv.out;
  EXPECT_NE(csv.out.find("workload.output_csv /dev/full: cannot write it"), std::string::npos)
      << csv.out;
}

// A path that cannot be written is bad input, found before anything is simulated: the message names
// the flag (or the scene key) and no report is printed.
TEST(OutputFiles, AnUnwritablePathIsFoundBeforeTheRun) {
  const auto trace =
      cli_test::run("run configs/scenes/pingpong.toml --trace-json /no/such/dir/t.json 2>&1");
  EXPECT_EQ(trace.exit_code, 2) << trace.out;
  EXPECT_NE(trace.out.find("--trace-json /no/such/dir/t.json: cannot write it"), std::string::npos)
      << trace.out;
  EXPECT_EQ(trace.out.find("simulated time"), std::string::npos) << trace.out;
  const auto csv = cli_test::run(
      "run configs/scenes/trajectory.toml --set workload.output_csv=/no/such/dir/t.csv 2>&1");
  EXPECT_EQ(csv.exit_code, 2) << csv.out;
  EXPECT_EQ(csv.out.rfind("--set workload.output_csv=/no/such/dir/t.csv: error: ", 0), 0u)
      << csv.out;
  const auto check = cli_test::run("check configs/scenes/trajectory.toml 2>&1");
  EXPECT_EQ(check.exit_code, 0) << check.out;
}

}  // namespace
