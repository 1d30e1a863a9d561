// The t800sim command end to end: reports, JSON schema, overrides, errors.
#include <gtest/gtest.h>

#include <cmath>

#include "cli_fixtures.hpp"

using cli_test::json_number;
using cli_test::run;

TEST(RunCommand, TextReportHasProcessorsLinksAndWorkload) {
  const auto o = run("run configs/scenes/pingpong.toml");
  ASSERT_EQ(o.exit_code, 0) << o.out;
  for (const char* expected :
       {"simulated time", "processor", "P0", "P1", "link direction", "one_way_us"})
    EXPECT_NE(o.out.find(expected), std::string::npos) << expected << "\n" << o.out;
}

TEST(RunCommand, JsonHasTheDocumentedKeys) {
  const auto o = run("run configs/scenes/pingpong.toml --json");
  ASSERT_EQ(o.exit_code, 0) << o.out;
  for (const char* key :
       {"\"simulated_us\":", "\"wall_s\":", "\"events\":", "\"processors\":", "\"name\":",
        "\"busy_us\":", "\"utilisation\":", "\"links\":", "\"workload\":", "\"one_way_us\":"})
    EXPECT_NE(o.out.find(key), std::string::npos) << key;
  EXPECT_EQ(o.out.front(), '{');
}

// One-way time of a ping-pong = out set-up + the message on the link + in completion; it must grow
// by one byte period (11.5 bit-times at 20 Mbit/s) per byte, and double the per-byte time at 10
// Mbit/s is 22 bits.
TEST(RunCommand, PingPongOneWayTimeGrowsByOneBytePeriodPerByte) {
  // 300 and 1300 bytes: both lengths take two prefix bytes in the ldc that sets up the message.
  const double t300 = json_number(
      run("run configs/scenes/pingpong.toml --json --set workload.bytes=300").out, "one_way_us");
  const double t1300 = json_number(
      run("run configs/scenes/pingpong.toml --json --set workload.bytes=1300").out, "one_way_us");
  EXPECT_NEAR((t1300 - t300) / 1000.0, 11.5 * 0.05, 1e-6);
  const double t1064 = json_number(
      run("run configs/scenes/pingpong.toml --json --set workload.bytes=1064").out, "one_way_us");
  const double slow = json_number(run("run configs/scenes/pingpong.toml --json --set "
                                      "workload.bytes=1064 --set network.link_speed_mbps=10")
                                      .out,
                                  "one_way_us");
  EXPECT_GT(slow, t1064 * 1.8);
}

TEST(RunCommand, StreamBandwidthHonoursTheLinkSpeed) {
  const auto o = run("run configs/scenes/link-stream.toml --json --set network.link_speed_mbps=10");
  ASSERT_EQ(o.exit_code, 0) << o.out;
  EXPECT_NEAR(json_number(o.out, "total_kBps"), 910, 0.02 * 910);
}

TEST(RunCommand, BadOverrideNamesTheFlag) {
  const auto o = run("run configs/scenes/pingpong.toml --set workload.bytes=-5 2>&1");
  EXPECT_EQ(o.exit_code, 2);
  EXPECT_NE(o.out.find("--set workload.bytes=-5"), std::string::npos) << o.out;
}

TEST(RunCommand, MissingSceneIsAClearError) {
  const auto o = run("run configs/scenes/no-such-scene.toml 2>&1");
  EXPECT_EQ(o.exit_code, 2);
  EXPECT_NE(o.out.find("no-such-scene.toml"), std::string::npos) << o.out;
}

TEST(CheckCommand, AcceptsEveryShippedTopology) {
  const auto o = run("check configs/topologies/tree-9.toml");
  EXPECT_EQ(o.exit_code, 0) << o.out;
}

TEST(Help, EveryCommandHasHelp) {
  for (const char* cmd : {"--help", "run --help", "check --help"}) {
    const auto o = run(cmd);
    EXPECT_EQ(o.exit_code, 0) << cmd;
    EXPECT_NE(o.out.find("Usage"), std::string::npos) << cmd << "\n" << o.out;
  }
}

// `run --help` lists every workload kind and its parameters, from the catalogue.
TEST(Help, RunListsWorkloadKindsAndParameters) {
  const auto o = run("run --help");
  EXPECT_EQ(o.exit_code, 0);
  for (const char* text : {"pingpong:", "link-stream:", "dynamics-farm:", "elimination:",
                           "trajectory:", "tp_window = \"farm\"", "bytes = 64"})
    EXPECT_NE(o.out.find(text), std::string::npos) << text << "\n" << o.out;
}
