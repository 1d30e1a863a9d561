// fidelity.skip_numerics in the dynamics farm: a timing-only run evaluates no subtask and reports
// no D, c, h, but its timing is the full run's exactly -- Tp, every processor's busy time, every
// link direction's bytes, messages and busy time -- because every cost and message size comes from
// the operations counted once when the farm is built (farm_work; tests/dynamics: OpCounts are the
// same at every state), never from the values. Each case runs `t800sim run` twice (one simulation
// per process).
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include <nlohmann/json.hpp>
#include "tests/test_paths.hpp"

namespace {

nlohmann::json run_farm(const std::string& overrides, bool skip) {
  const std::string command =
      std::string("cd ") + test_paths::source_dir() + " && SYSTEMC_DISABLE_COPYRIGHT_MESSAGE=1 " +
      test_paths::binary_dir() + "/t800sim run configs/scenes/dynamics-farm.toml --json " +
      overrides + " --set fidelity.skip_numerics=" + (skip ? "true" : "false");
  FILE* pipe = popen(command.c_str(), "r");
  std::string out;
  char buffer[4096];
  while (std::size_t n = fread(buffer, 1, sizeof buffer, pipe)) out.append(buffer, n);
  EXPECT_EQ(pclose(pipe), 0) << command << "\n" << out;
  return nlohmann::json::parse(out);
}

void expect_same_timing(const std::string& overrides) {
  const nlohmann::json full = run_farm(overrides, false), timing = run_farm(overrides, true);
  const nlohmann::json &w_full = full["workload"], &w_timing = timing["workload"];
  // The values are absent, and the report says why; the full run has them.
  for (const char* key : {"D", "c", "h"}) {
    EXPECT_TRUE(w_full.contains(key)) << key;
    EXPECT_FALSE(w_timing.contains(key)) << key;
  }
  ASSERT_TRUE(w_timing.contains("numerics"));
  EXPECT_NE(w_timing["numerics"].get<std::string>().find("skipped"), std::string::npos);
  EXPECT_TRUE(timing["fidelity"]["skip_numerics"].get<bool>());
  // The timing, exactly.
  EXPECT_EQ(w_full["tp_us"].get<double>(), w_timing["tp_us"].get<double>());
  EXPECT_EQ(w_full["evaluation_us"].get<double>(), w_timing["evaluation_us"].get<double>());
  EXPECT_EQ(full["simulated_us"].get<double>(), timing["simulated_us"].get<double>());
  ASSERT_EQ(full["processors"].size(), timing["processors"].size());
  for (std::size_t i = 0; i < full["processors"].size(); ++i)
    for (const char* key : {"busy_us", "compute_us", "communicate_us"})
      EXPECT_EQ(full["processors"][i][key].get<double>(),
                timing["processors"][i][key].get<double>())
          << full["processors"][i]["name"] << " " << key;
  ASSERT_EQ(w_full["per_worker"].size(), w_timing["per_worker"].size());
  for (std::size_t i = 0; i < w_full["per_worker"].size(); ++i) {
    EXPECT_EQ(w_full["per_worker"][i]["busy_in_tp_us"].get<double>(),
              w_timing["per_worker"][i]["busy_in_tp_us"].get<double>());
    EXPECT_EQ(w_full["per_worker"][i]["subtasks"], w_timing["per_worker"][i]["subtasks"]);
  }
  ASSERT_EQ(full["links"].size(), timing["links"].size());
  for (std::size_t i = 0; i < full["links"].size(); ++i) {
    const std::string name = full["links"][i]["name"];
    EXPECT_EQ(full["links"][i]["bytes"], timing["links"][i]["bytes"]) << name;
    EXPECT_EQ(full["links"][i]["messages"], timing["links"][i]["messages"]) << name;
    EXPECT_EQ(full["links"][i]["busy_us"].get<double>(),
              timing["links"][i]["busy_us"].get<double>())
        << name;
  }
}

class SkipNumerics : public ::testing::TestWithParam<int> {};

// Table 4's runs: the paper's trees of 1, 3, 6 and 9 workers, static schedule, farm window.
TEST_P(SkipNumerics, LeavesTheTimingExactlyAsItIs) {
  expect_same_timing("--set network.workers=" + std::to_string(GetParam()));
}

INSTANTIATE_TEST_SUITE_P(Table4, SkipNumerics, ::testing::Values(1, 3, 6, 9));

// The on-demand schedule hands out subtasks as results come back: still no value decides anything.
TEST(SkipNumericsOnDemand, LeavesTheTimingExactlyAsItIs) {
  expect_same_timing(
      "--set network.workers=6 --set workload.schedule=on-demand --set "
      "workload.tp_window=evaluation");
}

}  // namespace
