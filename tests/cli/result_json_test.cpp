// ResultValue's JSON text against the JSON grammar (RFC 8259) written out by hand, and every
// shipped scene's report read back by an independent parser (nlohmann::json) with its numbers
// intact.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <nlohmann/json.hpp>

#include "cli_fixtures.hpp"
#include "workloads/run/result_value.hpp"

using workloads::ResultValue;

TEST(ResultJson, ScalarsNestingAndEscapesFollowTheGrammar) {
  ResultValue v;
  v.set("i", std::int64_t{-42});
  v.set("x", 0.1);  // the shortest text that reads back as the same double
  v.set("big", 1e21);
  v.set("nan", std::nan(""));  // JSON has no NaN: null
  v.set("inf", std::numeric_limits<double>::infinity());
  v.set("yes", true);
  v.set("text", std::string("a\"b\\c\nd\te\x01"));
  ResultValue list = ResultValue::list();
  list.push(1);
  list.push(ResultValue());
  v.set("list", list);
  EXPECT_EQ(v.to_json(),
            "{\"i\": -42, \"x\": 0.1, \"big\": 1e+21, \"nan\": null, \"inf\": null, \"yes\": true, "
            "\"text\": \"a\\\"b\\\\c\\nd\\te\\u0001\", \"list\": [1, {}]}");
  std::string out = "prefix ";
  v.append_json(out);
  EXPECT_EQ(out, "prefix " + v.to_json());
}

TEST(ResultJson, EveryShippedSceneReportParsesAndKeepsItsNumbers) {
  const std::filesystem::path scenes = std::filesystem::path(T800SIM_SOURCE_DIR) / "configs/scenes";
  int checked = 0;
  for (const auto& entry : std::filesystem::directory_iterator(scenes)) {
    if (entry.path().extension() != ".toml") continue;
    const auto o = cli_test::run("run " + entry.path().string() + " --json");
    ASSERT_EQ(o.exit_code, 0) << entry.path() << "\n" << o.out;
    const nlohmann::json j = nlohmann::json::parse(o.out);
    // The same number the text report prints to 3 decimals, read back from the JSON text.
    const double simulated = j.at("simulated_us").get<double>();
    EXPECT_NE(o.out.find("\"simulated_us\": "), std::string::npos);
    EXPECT_GT(simulated, 0) << entry.path();
    const auto text = cli_test::run("run " + entry.path().string());
    char printed[64];
    std::snprintf(printed, sizeof printed, "simulated time  %.3f us", simulated);
    EXPECT_NE(text.out.find(printed), std::string::npos) << entry.path() << ": " << printed;
    ++checked;
  }
  EXPECT_GE(checked, 10);
}
