// ResultValue's JSON text against the JSON grammar (RFC 8259) written out by hand, and every
// shipped scene's report read back by an independent parser (nlohmann::json) with its numbers
// intact.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <nlohmann/json.hpp>

#include "cli_fixtures.hpp"
#include "tests/test_paths.hpp"
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

// Well-formed UTF-8 passes through; each byte of an ill-formed sequence (RFC 3629: a stray
// continuation byte, a truncated sequence, an overlong form, a surrogate, past U+10FFFF) becomes
// U+FFFD, so the text is valid JSON an independent parser reads back.
TEST(ResultJson, AnyLabelGivesValidJson) {
  const std::string good = "\xc3\xa9 \xe2\x82\xac \xf0\x9f\x98\x80";  // é € 😀
  EXPECT_EQ(workloads::json_string(good), "\"" + good + "\"");
  EXPECT_EQ(workloads::json_string(std::string("a\0b\x7f", 4)), "\"a\\u0000b\\u007f\"");
  for (const std::string bad :
       {"\x80", "\xc3", "\xc0\xaf", "\xed\xa0\x80", "\xf4\x90\x80\x80", "\xff", "\xe2\x82"}) {
    const std::string text = workloads::json_string("p" + bad + "q");
    std::string expected = "p";
    for (std::size_t i = 0; i < bad.size(); ++i) expected += "\xef\xbf\xbd";  // U+FFFD
    expected += "q";
    ASSERT_NO_THROW(EXPECT_EQ(nlohmann::json::parse(text).get<std::string>(), expected)) << text;
  }
}

TEST(ResultJson, EveryShippedSceneReportParsesAndKeepsItsNumbers) {
  const std::filesystem::path scenes =
      std::filesystem::path(test_paths::source_dir()) / "configs/scenes";
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
