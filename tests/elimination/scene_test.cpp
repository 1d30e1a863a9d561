// The Table 6 entry point the paper command uses: the scene plus table6_overrides(m) runs the
// m-processor pipeline and reports workload.tp_ms (no assertion on its value).
#include <gtest/gtest.h>

#include <string>

#include "tools/run_inputs.hpp"
#include "tools/scene.hpp"
#include "workloads/pipeline/pipeline.hpp"
#include "workloads/run/run.hpp"

namespace {

class Table6Scene : public ::testing::TestWithParam<int> {};

TEST_P(Table6Scene, RunsTheMProcessorPipeline) {
  const int m = GetParam();
  const tools::Scene scene =
      tools::load_scene(std::string(T800SIM_SOURCE_DIR) + "/" + workloads::kEliminationScene,
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

}  // namespace
