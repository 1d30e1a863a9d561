// The bytes the elimination pipeline puts on each link follow from its messages' protocol, counted
// here by hand for n = 6 unknowns on the one-processor level 2 (m = 1: every channel direct):
//   the system, host -> L1: its n x (n + 1) REALs, no header;
//   every other message: one INT32 header word and its REALs (README, "The pipeline (Fig. 7)");
//   step k (0-based) of the augmented system has n - k rows of n + 1 - k REALs: L1 sends the
//   normalised pivot row (its leading 1 dropped: n - k REALs) and the other n - 1 - k rows whole;
//   E1 forwards the pivot row and sends each row without its eliminated leading element (n - k);
//   L3 returns those rows to L1 and passes the pivot rows to L4;
//   with the growth check, step 0's pivot row also carries the matrix's scale (one REAL) as far as
//   L3, which needs it; with recovery, every message out of L1 and E1 also carries a checksum word,
//   L3 ends with a bare header ("done") and L1 stops E1 with one.
#include <gtest/gtest.h>

#include <map>
#include <string>

#include <nlohmann/json.hpp>

#include "../cli/cli_fixtures.hpp"

namespace {

struct Traffic {
  long bytes = 0, messages = 0;
};

std::map<std::string, Traffic> links(const std::string& sets) {
  const auto o = cli_test::run(
      "run configs/scenes/elimination.toml --json --set network.topology=../topologies/"
      "elimination-m1.toml --set workload.m=1" +
      sets);
  EXPECT_EQ(o.exit_code, 0) << o.out.substr(0, 2000);
  const nlohmann::json report = nlohmann::json::parse(o.out);
  std::map<std::string, Traffic> out;
  for (const auto& l : report["links"]) {
    const std::string name = l["name"];
    out[name.substr(0, name.find(' '))] = {l["bytes"].get<long>(), l["messages"].get<long>()};
  }
  return out;
}

// Bytes and messages of each channel, from the protocol above.
struct Expected {
  Traffic system, to_e1, to_l3, back, to_l4;
};
Expected by_hand(int real, bool growth_check, bool recovery) {
  const int n = 6;
  const int header = 4, check = recovery ? 4 : 0;
  Expected x;
  x.system = {real * n * (n + 1), 1};
  for (int k = 0; k < n; ++k) {
    const int scale = k == 0 && growth_check ? 1 : 0;
    const long pivot = header + real * (n - k + scale) + check;
    const long others = n - 1 - k;
    x.to_e1.bytes += pivot + others * (header + real * (n + 1 - k) + check);
    x.to_e1.messages += 1 + others;
    x.to_l3.bytes += pivot + others * (header + real * (n - k) + check);
    x.to_l3.messages += 1 + others;
    x.back.bytes += others * (header + real * (n - k));
    x.back.messages += others;
    x.to_l4.bytes += header + real * (n - k);
    x.to_l4.messages += 1;
  }
  if (recovery) {
    x.back.bytes += header;  // "done"
    x.back.messages += 1;
    x.to_e1.bytes += header;  // E1's stop
    x.to_e1.messages += 1;
  }
  return x;
}

void expect_traffic(const std::string& sets, int real, bool growth_check, bool recovery) {
  const auto got = links(sets);
  const Expected x = by_hand(real, growth_check, recovery);
  const std::pair<const char*, Traffic> rows[] = {{"host->L1", x.system},
                                                  {"L1->E1", x.to_e1},
                                                  {"E1->L3", x.to_l3},
                                                  {"L3->L1", x.back},
                                                  {"L3->L4", x.to_l4}};
  for (const auto& [name, want] : rows) {
    ASSERT_TRUE(got.count(name)) << name << " among " << got.size() << " links";
    EXPECT_EQ(got.at(name).bytes, want.bytes) << name << sets;
    EXPECT_EQ(got.at(name).messages, want.messages) << name << sets;
  }
}

TEST(EliminationWire, Real32) {
  expect_traffic("", 4, false, false);
}
TEST(EliminationWire, Real64) {
  expect_traffic(" --set workload.precision=real64", 8, false, false);
}
TEST(EliminationWire, TheGrowthCheckSendsTheScaleAsFarAsLevel3) {
  expect_traffic(" --set workload.growth_check=true", 4, true, false);
}
TEST(EliminationWire, RecoveryAddsAChecksumWordToEveryMessageOutOfL1AndE1) {
  expect_traffic(" --set workload.recovery=true", 4, false, true);
  expect_traffic(" --set workload.recovery=true --set workload.growth_check=true", 4, true, true);
}

}  // namespace
