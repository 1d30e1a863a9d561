// The elimination declared on the SDK's pipeline skeleton: which channels it has and where they
// run, read from the report's channel list and checked against the topology files by hand
// (configs/topologies/elimination-m4.toml, -m5.toml): L1 and L3 are linked to E1 and E2 only, so
// E3.. are reached through the link processors X (from L1) and Y (to L3); E1 forwards the pivot
// rows to L3 outside the relays' plan, so its channels are its own (the relay plan lists it as
// direct); the host feeds L1 through E1's router; L3 reaches L4 through E2.
#include <gtest/gtest.h>

#include <map>
#include <string>

#include <nlohmann/json.hpp>

#include "../cli/cli_fixtures.hpp"

namespace {

// name -> "kind path"
std::map<std::string, std::string> channels(int m) {
  const std::string M = std::to_string(m);
  const auto o = cli_test::run(
      "run configs/scenes/elimination.toml --json --set network.topology=../"
      "topologies/elimination-m" +
      M + ".toml --set workload.m=" + M);
  EXPECT_EQ(o.exit_code, 0) << o.out.substr(0, 2000);
  std::map<std::string, std::string> out;
  const nlohmann::json report = nlohmann::json::parse(o.out);
  for (const auto& c : report["workload"]["channels"])
    out[c["name"].get<std::string>()] =
        c["kind"].get<std::string>() + " " + c["path"].get<std::string>();
  return out;
}

class RelayedLevel2 : public ::testing::TestWithParam<int> {};

TEST_P(RelayedLevel2, TheProcessorsWithoutALinkAreBehindXAndYAndE1IsDirect) {
  const int m = GetParam();
  const auto c = channels(m);
  std::map<std::string, std::string> expected{
      {"client->level1[0][0]", "routed host-E1-L1"},
      {"level1->level2[0][0]", "direct L1-E1"},
      {"level1->level2[0][1]", "direct L1-E2"},
      {"level1->level2_fan_out[0][0]", "direct L1-X"},
      {"level2->level3[0][0]", "direct E1-L3"},
      {"level2->level3[1][0]", "direct E2-L3"},
      {"level2_fan_in->level3[0][0]", "direct Y-L3"},
      {"level3->level1", "direct L3-L1"},
      {"level3->level4[0][0]", "routed L3-E2-L4"},
  };
  for (int e = 2; e < m; ++e) {  // E3 .. Em
    const std::string i = std::to_string(e), E = "E" + std::to_string(e + 1);
    expected["level2_fan_out->level2[0][" + i + "]"] = "direct X-" + E;
    expected["level2_fan_out.inner[" + i + "]"] = "internal X";
    expected["level2->level2_fan_in[" + i + "][0]"] = "direct " + E + "-Y";
    expected["level2_fan_in.inner[" + i + "]"] = "internal Y";
  }
  EXPECT_EQ(c, expected);
}

INSTANTIATE_TEST_SUITE_P(ElimSkeleton, RelayedLevel2, ::testing::Values(4, 5));

}  // namespace
