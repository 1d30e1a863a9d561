// How a run ends, as the exit code and the report say: results that are not results (a NaN, an
// infinity, a solve without a usable pivot) are a failure (exit 3), never null in a report that
// exits 0; a limit stops a run (exit 4); a sweep records such points as failed and a rerun runs
// them again.
#include <gtest/gtest.h>

#include <filesystem>

#include <nlohmann/json.hpp>

#include "cli_fixtures.hpp"
#include "tests/test_paths.hpp"

namespace {

using nlohmann::json;

using cli_test::report_of;

// 1e20 rad/s squared overflows REAL32 (3.4e38) in the Coriolis terms: c comes out infinite or NaN.
TEST(RunOutcome, AnOverflowInReal32IsAFailureNotNull) {
  const auto o = cli_test::run(
      "run configs/scenes/dynamics-farm.toml --set 'workload.qd=[1e20,1e20,1e20,1e20,1e20,1e20]' "
      "--json");
  EXPECT_EQ(o.exit_code, 3) << o.out;
  const json r = report_of(o);
  ASSERT_TRUE(r.is_object()) << o.out;
  ASSERT_TRUE(r.contains("failure")) << o.out;
  EXPECT_EQ(r["failure"].get<std::string>().rfind("workload.c[", 0), 0u) << r["failure"];
  // The same in REAL64 is finite: no failure.
  const auto wide = cli_test::run(
      "run configs/scenes/dynamics-farm.toml --set workload.precision=real64 "
      "--set 'workload.qd=[1e20,1e20,1e20,1e20,1e20,1e20]' --json");
  EXPECT_EQ(wide.exit_code, 0) << wide.out;
  EXPECT_FALSE(report_of(wide).contains("failure"));
}

TEST(RunOutcome, ASingularEliminationIsAFailure) {
  const auto o = cli_test::run(
      "run configs/scenes/elimination.toml --set workload.source=given --set "
      "'workload.a=[1,2,2,4]' "
      "--set 'workload.b=[1,1]' --set workload.m=1 2>&1");
  EXPECT_EQ(o.exit_code, 3) << o.out;
  EXPECT_NE(o.out.find("FAILED: level 1: no usable pivot"), std::string::npos) << o.out;
  EXPECT_NE(o.out.find("error: the run failed: level 1: no usable pivot"), std::string::npos)
      << o.out;
}

// A sweep over a regular and a singular system: the singular point is an error row, and a rerun
// does not take it as done.
TEST(RunOutcome, ASweepRecordsFailedSolvesAsFailedPointsAndRetriesThem) {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const std::filesystem::path dir = std::filesystem::path(test_paths::binary_dir()) /
                                    "test-output" / info->test_suite_name() / info->name();
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const std::string out = (dir / "r.csv").string();
  const std::string sweep =
      "sweep configs/scenes/elimination.toml --set 'workload.a=[1,2,2,4]' --set 'workload.b=[1,1]' "
      "--set workload.n=2 --set workload.m=1 --vary workload.source=random,given -o " +
      out + " 2>&1";
  const auto first = cli_test::run(sweep);
  EXPECT_EQ(first.exit_code, 1) << first.out;
  std::ifstream in(out);
  std::string header, regular, singular;
  std::getline(in, header), std::getline(in, regular), std::getline(in, singular);
  EXPECT_NE(regular.find(",ok"), std::string::npos) << regular;
  EXPECT_NE(singular.find("error: the run failed: level 1: no usable pivot"), std::string::npos)
      << singular;
  const auto again = cli_test::run(sweep);
  EXPECT_NE(again.out.find("1 of 2 points already in"), std::string::npos) << again.out;
  EXPECT_NE(again.out.find("[1/1] workload.source=given"), std::string::npos) << again.out;
}

// More workers than subtasks: the idle ones have none, and their end is not before Tp began.
TEST(RunOutcome, WorkersWithoutSubtasksDoNotEndBeforeTheStart) {
  const auto o =
      cli_test::run("run configs/scenes/dynamics-farm.toml --set network.workers=80 --json");
  ASSERT_EQ(o.exit_code, 0) << o.out;
  const json r = report_of(o);
  int idle = 0;
  for (const json& w : r["workload"]["per_worker"]) {
    EXPECT_GE(w["end_us"].get<double>(), 0.0) << w;
    idle += w["subtasks"].empty();
  }
  EXPECT_GT(idle, 0);
}

TEST(RunOutcome, TheSimulatedTimeLimitStopsARun) {
  const auto o = cli_test::run(
      "run configs/scenes/trajectory.toml --set workload.steps=1000 --max-sim-time 0.05 --json "
      "2>&1");
  EXPECT_EQ(o.exit_code, 4) << o.out;
  EXPECT_NE(o.out.find("error: stopped by --max-sim-time 0.05 s"), std::string::npos) << o.out;
  const json r = report_of(o);
  EXPECT_EQ(r["stopped_by"], "max_sim_time") << o.out;
  EXPECT_LE(r["simulated_us"].get<double>(), 50000.0);
  EXPECT_FALSE(r.contains("deadlock"));  // stopped processes are not blocked ones
}

TEST(RunOutcome, TheWallTimeLimitStopsARun) {
  const auto o = cli_test::run(
      "run configs/scenes/trajectory.toml --set workload.steps=10000000 --max-wall-time 0.5 --json "
      "2>&1");
  EXPECT_EQ(o.exit_code, 4) << o.out;
  EXPECT_NE(o.out.find("error: stopped by --max-wall-time 0.5 s"), std::string::npos) << o.out;
  EXPECT_EQ(report_of(o)["stopped_by"], "max_wall_time") << o.out;
}

// Watching the wall clock runs the simulation in slices; the slices run the same events in the same
// order, so every result is the same.
TEST(RunOutcome, ALimitThatIsNotReachedChangesNothing) {
  const std::string run =
      "run configs/scenes/trajectory.toml --set workload.steps=5 --set fidelity.reuse_steps=false "
      "--json";
  json plain = report_of(cli_test::run(run));
  json sliced = report_of(cli_test::run(run + " --max-wall-time 1000 --max-sim-time 1000"));
  ASSERT_TRUE(plain.is_object() && sliced.is_object());
  for (json* r : {&plain, &sliced}) {
    r->erase("wall_s");
    r->erase("elaboration_s");
  }
  EXPECT_EQ(plain, sliced);
}

TEST(RunOutcome, BadLimitsNameTheFlag) {
  // A limit that is negative, not finite or not a number would otherwise stop the run at once or
  // never: each is refused before anything runs, naming the flag and the value given.
  for (const std::string flag : {"--max-wall-time", "--max-sim-time"}) {
    for (const std::string value : {"-1", "nan", "inf", "abc"}) {
      const auto o =
          cli_test::run("run configs/scenes/pingpong.toml " + flag + " " + value + " 2>&1");
      EXPECT_EQ(o.exit_code, 2) << flag << " " << value << "\n" << o.out;
      EXPECT_NE(o.out.find(flag + ": '" + value + "' is not a number of seconds"),
                std::string::npos)
          << o.out;
    }
  }
}

}  // namespace
