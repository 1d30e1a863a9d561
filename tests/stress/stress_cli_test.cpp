// `t800sim stress` end to end: the quick run prints the summary and the documented JSON keys.
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <array>
#include <cstdio>
#include <string>

#include <nlohmann/json.hpp>
#include "tests/test_paths.hpp"

namespace {

struct Output {
  int exit_code = -1;
  std::string out;
};

Output run(const std::string& args) {
  const std::string command = std::string("cd ") + test_paths::source_dir() +
                              " && SYSTEMC_DISABLE_COPYRIGHT_MESSAGE=1 timeout 120 " +
                              test_paths::binary_dir() + "/t800sim " + args;
  Output o;
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return o;
  std::array<char, 4096> buffer;
  while (std::size_t n = fread(buffer.data(), 1, buffer.size(), pipe))
    o.out.append(buffer.data(), n);
  const int status = pclose(pipe);
  o.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return o;
}

void expect_keys(const nlohmann::json& j, std::initializer_list<const char*> keys,
                 const std::string& where) {
  for (const char* key : keys) EXPECT_TRUE(j.contains(key)) << where << " has no key " << key;
}

void expect_tally(const nlohmann::json& t) {
  expect_keys(
      t,
      {"strategy", "precision", "pivot_threshold", "forward_error", "backward_error", "growth_max",
       "smallest_relative_pivot", "interchanges", "ok", "unstable", "no_pivot", "non_finite",
       "inaccurate", "silent_inaccurate", "growth_flagged", "missed_by_growth_check"},
      "a strategy");
  expect_keys(t["forward_error"], {"median", "max"}, "forward_error");
}

TEST(StressCommand, QuickJsonHasTheDocumentedKeys) {
  const Output o = run("stress --quick --json");
  ASSERT_EQ(o.exit_code, 0) << o.out;
  const nlohmann::json j = nlohmann::json::parse(o.out);
  expect_keys(j, {"quick", "seed", "arm", "condition_sweep", "tiny_pivot", "energy", "wall_s"},
              "the report");
  EXPECT_EQ(j["quick"], true);
  expect_keys(j["arm"], {"states", "condition", "worst_condition_q", "strategies"}, "arm");
  EXPECT_EQ(j["arm"]["states"], 5000);
  for (const auto& t : j["arm"]["strategies"]) expect_tally(t);
  ASSERT_FALSE(j["condition_sweep"].empty());
  expect_keys(j["condition_sweep"][0],
              {"kind", "condition", "matrices", "measured_condition", "strategies"},
              "condition_sweep");
  ASSERT_FALSE(j["tiny_pivot"].empty());
  expect_keys(j["tiny_pivot"][0], {"step", "delta", "matrices", "measured_condition", "strategies"},
              "tiny_pivot");
  for (const auto& t : j["tiny_pivot"][0]["strategies"]) expect_tally(t);
  ASSERT_EQ(j["energy"].size(), 5u);
  expect_keys(j["energy"][0],
              {"model", "method", "precision", "seconds", "dt", "e0_J", "max_abs_drift_J",
               "final_drift_J", "max_kinetic_J", "relative_drift", "first_limit_exit_s", "failure"},
              "energy");
  // The arm's D is positive definite: simple interchange never interchanges and never fails.
  for (const auto& t : j["arm"]["strategies"]) {
    EXPECT_EQ(t["no_pivot"], 0);
    EXPECT_EQ(t["inaccurate"], 0);
  }
}

TEST(StressCommand, TextSummaryAndBadOptions) {
  const Output o = run("stress --quick --states 200");
  ASSERT_EQ(o.exit_code, 0) << o.out;
  for (const char* part : {"(a) Stanford arm", "(b) random 6x6", "(c) passive trajectory"})
    EXPECT_NE(o.out.find(part), std::string::npos) << part;
  EXPECT_EQ(run("stress --states 0 2>&1").exit_code, 2);
  const Output missing = run("stress --quick --robot no-such-robot.toml 2>&1");
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_NE(missing.out.find("no-such-robot.toml"), std::string::npos) << missing.out;
}

}  // namespace
