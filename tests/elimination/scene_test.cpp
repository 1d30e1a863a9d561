// The Table 6 entry point the paper command uses: the scene plus table6_overrides(m) runs the
// m-processor pipeline and reports workload.tp_ms (no assertion on its value).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "tests/cli/cli_fixtures.hpp"
#include "tests/test_paths.hpp"
#include "tools/run_inputs.hpp"
#include "tools/scene.hpp"
#include "workloads/pipeline/pipeline.hpp"
#include "workloads/run/run.hpp"

namespace {

class Table6Scene : public ::testing::TestWithParam<int> {};

TEST_P(Table6Scene, RunsTheMProcessorPipeline) {
  const int m = GetParam();
  const tools::Scene scene =
      tools::load_scene(test_paths::source_dir() + "/" + workloads::kEliminationScene,
                        workloads::table6_overrides(m));
  EXPECT_EQ(scene.topology.name, "elimination-m" + std::to_string(m));
  const workloads::RunReport report = workloads::run(tools::inputs_from(scene));
  ASSERT_TRUE(report.blocked.empty());
  const workloads::ResultValue& w = report.workload;
  EXPECT_EQ(w.get("m")->number(), m);
  EXPECT_EQ(w.get("status")->to_json(), "\"ok\"");
  EXPECT_EQ(w.get("matches_sequential")->to_json(), "true");
  EXPECT_GT(w.get("tp_ms")->number(), 0.0);
  EXPECT_LE(w.get("tp_ms")->number() * 1000, report.simulated_us);
}

INSTANTIATE_TEST_SUITE_P(Paper, Table6Scene, ::testing::Values(1, 2, 3, 4, 5),
                         [](const auto& info) { return "m" + std::to_string(info.param); });

// One simulation per process: each run is the t800sim executable, as the paper command runs it.
double scene_tp_ms(int m, bool overlap) {
  std::string args = std::string("run ") + workloads::kEliminationScene + " --json";
  for (const std::string& set : workloads::table6_overrides(m)) args += " --set " + set;
  args += std::string(" --set workload.overlap=") + (overlap ? "true" : "false");
  const cli_test::Output o = cli_test::run(args + " 2>/dev/null");
  EXPECT_EQ(o.exit_code, 0) << o.out;
  return cli_test::json_number(o.out, "tp_ms");
}

// A property of the model, not of the host: streaming rows back can only take serial work off
// the path (the same pieces, the same messages), so the pipelined steps are never slower.
class OverlapScene : public ::testing::TestWithParam<int> {};

TEST_P(OverlapScene, IsNeverSlowerThanStrictSteps) {
  EXPECT_LE(scene_tp_ms(GetParam(), true), scene_tp_ms(GetParam(), false));
}

INSTANTIATE_TEST_SUITE_P(Paper, OverlapScene, ::testing::Values(1, 2, 3),
                         [](const auto& info) { return "m" + std::to_string(info.param); });

}  // namespace

// One unknown, inside workload.n's range (1..64): the pipeline solves the 1x1 system (L1 divides,
// no row goes to level 2) instead of failing to build (issue 27: std::bad_alloc).
class OneUnknown : public ::testing::TestWithParam<std::string> {};

TEST_P(OneUnknown, IsSolved) {
  std::vector<std::string> overrides = {"workload.source=random", "workload.n=1"};
  if (!GetParam().empty()) overrides.push_back(GetParam());
  const tools::Scene scene =
      tools::load_scene(test_paths::source_dir() + "/" + workloads::kEliminationScene, overrides);
  const workloads::RunReport report = workloads::run(tools::inputs_from(scene));
  ASSERT_TRUE(report.blocked.empty());
  const workloads::ResultValue& w = report.workload;
  EXPECT_EQ(w.get("n")->number(), 1);
  EXPECT_EQ(w.get("status")->to_json(), "\"ok\"");
  EXPECT_EQ(w.get("matches_sequential")->to_json(), "true");
}

INSTANTIATE_TEST_SUITE_P(Structures, OneUnknown,
                         ::testing::Values("", "workload.overlap=true",
                                           "workload.growth_check=true"),
                         [](const auto& info) {
                           return info.param.empty()     ? std::string("strict")
                                  : info.param[9] == 'o' ? std::string("overlap")
                                                         : std::string("growth_check");
                         });
