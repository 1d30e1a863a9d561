// `t800sim paper`, `calibrate` and `dynamics` end to end.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "cli_fixtures.hpp"

using cli_test::run;
using nlohmann::json;

TEST(PaperCommand, Table4HasTheDocumentedRowsAndTheFittedRowHolds) {
  const auto o = run("paper --table 4 --json");
  ASSERT_EQ(o.exit_code, 0) << o.out;
  const json t = json::parse(o.out);
  EXPECT_EQ(t["table"], 4);
  ASSERT_EQ(t["rows"].size(), 4u);
  const int workers[] = {1, 3, 6, 9};
  for (std::size_t i = 0; i < 4; ++i) {
    const json& r = t["rows"][i];
    EXPECT_EQ(r["workers"], workers[i]);
    for (const char* key : {"paper_ms", "simulated_ms", "error_pct"})
      EXPECT_TRUE(r[key].is_number()) << key;
    EXPECT_NEAR(r["error_pct"].get<double>(),
                100 * (r["simulated_ms"].get<double>() - r["paper_ms"].get<double>()) /
                    r["paper_ms"].get<double>(),
                1e-9);
  }
  // The recorded calibration must still reproduce the row it was fitted on: if the cost model
  // changes, rerun `t800sim calibrate` and record the new factor.
  EXPECT_EQ(t["rows"][0]["paper_ms"], 25.6);
  EXPECT_NEAR(t["rows"][0]["simulated_ms"].get<double>(), 25.6, 0.01);
}

TEST(PaperCommand, Table5ListsEveryWorker) {
  const auto o = run("paper --table 5 --json");
  ASSERT_EQ(o.exit_code, 0) << o.out;
  const json t = json::parse(o.out);
  ASSERT_EQ(t["rows"].size(), 4u);
  for (const json& r : t["rows"]) {
    EXPECT_EQ(r["paper_pct"].size(), r["workers"].get<std::size_t>());
    EXPECT_EQ(r["simulated_pct"].size(), r["workers"].get<std::size_t>());
    for (const json& u : r["simulated_pct"]) {
      EXPECT_GT(u.get<double>(), 0);
      EXPECT_LE(u.get<double>(), 100.0 + 1e-9);
    }
  }
}

TEST(PaperCommand, BadOverrideIsReported) {
  const auto o = run("paper --table 4 --set network.link_speed_mbps=15 2>&1");
  EXPECT_EQ(o.exit_code, 2);
  EXPECT_NE(o.out.find("5, 10 or 20"), std::string::npos) << o.out;
}

// The reference state (full model) whose printed values tests/dynamics/reference_state_test.cpp
// checks; tests/dynamics/kdl_agreement_test.cpp checks the same model against Orocos KDL.
TEST(DynamicsCommand, ReferenceState) {
  const auto o = run("dynamics --q 0.1,0.2,0.5,0.3,0.4,0.5 --qd 0.1,-0.2,0.05,0.3,-0.1,0.2 --json");
  ASSERT_EQ(o.exit_code, 0) << o.out;
  const json r = json::parse(o.out);
  const double D0[] = {10.98977, 4.195600, -0.1095946, 0.1920722, -0.4090546, 2.639514e-4};
  const double c[] = {-1.268386, -0.03862650, 0.9625814, -0.06971197, -0.02163600, -1.429584e-6};
  const double h[] = {0, 44.490898, 62.205512, -0.866768, -4.91195, 0};
  const double qdd[] = {0.070682, -0.318066, -9.72784, 5.13206, 0.548757, -4.902692};
  for (int i = 0; i < 6; ++i) {
    EXPECT_NEAR(r["D"][0][i].get<double>(), D0[i], 1e-6 * std::max(1.0, std::abs(D0[i])));
    EXPECT_NEAR(r["c"][i].get<double>(), c[i], 1e-6 * std::max(1e-3, std::abs(c[i])));
    EXPECT_NEAR(r["h"][i].get<double>(), h[i], 1e-5);
    EXPECT_NEAR(r["qdd"][i].get<double>(), qdd[i], 1e-5);
  }
  EXPECT_EQ(r["subtasks"].size(), 82u);
  for (const json& t : r["subtasks"]) {
    EXPECT_TRUE(t["cycles"].is_number_integer());
    EXPECT_FALSE(t["ops"].get<std::string>().empty());
  }
}

TEST(DynamicsCommand, PaperModelHasSixtyFourSubtasks) {
  const auto o = run("dynamics --q 0,0,0.5,0,0,0 --model paper --precision real32 --json");
  ASSERT_EQ(o.exit_code, 0) << o.out;
  EXPECT_EQ(json::parse(o.out)["subtasks"].size(), 64u);
}

TEST(DynamicsCommand, InvalidInputGetsAClearError) {
  const std::pair<const char*, const char*> cases[] = {
      {"--q 0.1,0.2,5,0.3,0.4,0.5", "outside its limits"},
      {"--q 0.1,nan,0.5,0.3,0.4,0.5", "finite"},
      {"--q 0.1,0.2", "expected 6 values"},
      {"--q 0.1,x,0.5,0.3,0.4,0.5", "'x' is not a number"},
      {"--q 0,0,0.5,0,0,0 --qd 1,2,3", "--qd"},
  };
  for (const auto& [args, message] : cases) {
    const auto o = run(std::string("dynamics ") + args + " 2>&1");
    EXPECT_EQ(o.exit_code, 2) << args;
    EXPECT_NE(o.out.find(message), std::string::npos) << args << "\n" << o.out;
  }
}
