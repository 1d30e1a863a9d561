// 1024 transputers: generated trees, meshes and hypercubes of P0 and 1023 workers elaborate and run
// the dynamics farm to the end, every subtask done exactly once and D, c, h finite. (Their speed is
// not tested here: tests never time the host.)
#include <gtest/gtest.h>

#include <map>

#include <nlohmann/json.hpp>

#include "../cli/cli_fixtures.hpp"

namespace {

class Scale : public ::testing::TestWithParam<const char*> {};

TEST_P(Scale, A1024TransputerNetworkRunsTheFarm) {
  const std::string family = GetParam();
  const auto o =
      cli_test::run("run configs/scenes/dynamics-farm.toml --set network.family=" + family +
                    " --set network.workers=1023 --json");
  ASSERT_EQ(o.exit_code, 0) << o.out.substr(0, 2000);
  const nlohmann::json r = nlohmann::json::parse(o.out);
  EXPECT_EQ(r["processors"].size(), 1024u);
  EXPECT_FALSE(r.contains("deadlock"));
  EXPECT_FALSE(r.contains("failure"));
  const nlohmann::json& w = r["workload"];
  EXPECT_EQ(w["workers"], 1023);
  std::map<std::string, int> done;
  for (const nlohmann::json& worker : w["per_worker"])
    for (const nlohmann::json& subtask : worker["subtasks"]) ++done[subtask.get<std::string>()];
  EXPECT_EQ(int(done.size()), w["subtasks"].get<int>());
  for (const auto& [name, times] : done) EXPECT_EQ(times, 1) << name;
  EXPECT_EQ(w["c"].size(), 6u);
  EXPECT_GT(w["tp_us"].get<double>(), 0);
}

INSTANTIATE_TEST_SUITE_P(Families, Scale, ::testing::Values("tree", "mesh", "hypercube"),
                         [](const auto& info) { return std::string(info.param); });

}  // namespace
