// A pipeline of your own (programs/pipeline, configs/scenes/fixed-stages.toml, on the SDK's
// pipeline skeleton): its results are the stages' functions applied in order, and its timing is the
// closed form of k fixed-cost stages joined by links, derived by hand:
//   C  = stage_cycles x 50 ns (a T800-20's cycle);
//   T  = the time a B-byte message takes on a link: the datasheet's one-direction rate is 11.5 bit
//        times a byte at 20 Mbit/s (INMOS Transputer Databook, Table 8.1: 575 ns), the last byte a
//        whole data packet of 11 bits (550 ns): T = (B - 1) x 575 ns + 550 ns;
//   an unbuffered stage takes its item in, computes, sends it on: one item every C + 2T, plus the
//   in and out instructions' set-up (a few tens of cycles); the first result after k stages and
//   k + 1 links;
//   a buffered stage moves items while it computes: one item every max(C, T) or a little more (the
//   input and output processes' instructions share the CPU), never C + 2T.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "../cli/cli_fixtures.hpp"
#include "programs/support/checksum.hpp"

namespace {

nlohmann::json run(const std::string& sets = "") {
  const auto o = cli_test::run("run configs/scenes/fixed-stages.toml --json" + sets);
  EXPECT_EQ(o.exit_code, 0) << o.out.substr(0, 2000);
  return nlohmann::json::parse(o.out)["workload"];
}

constexpr double kCycleUs = 0.05;  // T800-20
double link_us(double bytes) {
  return ((bytes - 1) * 575 + 550) / 1000;
}
// The set-up of one stage's in and out and the switch between them: under 100 cycles.
constexpr double kInstructionsUs = 100 * kCycleUs;

// The scene's results, recomputed here: every element halved and s + 1 added at stage s, in float.
std::string sequential_stages_checksum(int stages, int reals, int rounds) {
  std::vector<float> all;
  for (int r = 0; r < rounds; ++r)
    for (int e = 0; e < reals; ++e) {
      float x = float(r) + float(e) / float(reals);
      for (int s = 0; s < stages; ++s) x = x * 0.5f + float(s + 1);
      all.push_back(x);
    }
  return programs::fnv1a_hex(all);
}

double stage_us(const nlohmann::json& w) {
  return w["stage_cycles"].get<double>() * kCycleUs;
}

TEST(FixedStages, ResultsAreTheStagesAppliedInOrderBufferedOrNot) {
  for (const char* buffered : {"false", "true"}) {
    const auto w = run(std::string(" --set workload.buffered=") + buffered);
    EXPECT_EQ(w["results_checksum"], sequential_stages_checksum(4, 16, 20)) << buffered;
  }
}

TEST(FixedStages, UnbufferedPeriodAndFillAreTheClosedForm) {
  const auto w = run();
  const int k = w["stages"];
  const double c = stage_us(w), t = link_us(w["item_bytes"]);
  const double period = w["period_us"], first = w["arrived_us"][0];
  EXPECT_GE(period, c + 2 * t);
  EXPECT_LE(period, c + 2 * t + kInstructionsUs);
  EXPECT_GE(first, k * c + (k + 1) * t);
  EXPECT_LE(first, k * c + (k + 1) * t + (2 * k + 1) * kInstructionsUs);
  // Full from the first result on: every later one a period after the one before.
  const auto& arrived = w["arrived_us"];
  for (std::size_t r = 2; r < arrived.size(); ++r)
    EXPECT_NEAR(arrived[r].get<double>() - arrived[r - 1].get<double>(), period, 0.1) << r;
}

// The period's parts, each alone: 2000 more cycles a stage add 100 us to the period and to each
// stage of the fill; 64 more bytes an item add two messages' 64 x 575 ns to the period; more stages
// lengthen the fill, not the period.
TEST(FixedStages, EachPartOfThePeriodIsWhereTheClosedFormPutsIt) {
  const auto base = run();
  const auto slower = run(" --set workload.stage_cycles=4000");
  const auto bigger = run(" --set workload.item_reals=32");
  const auto longer = run(" --set workload.stages=8 --set network.workers=8");
  const double period = base["period_us"], first = base["arrived_us"][0];
  EXPECT_NEAR(slower["period_us"].get<double>() - period, 2000 * kCycleUs, 1e-6);
  EXPECT_NEAR(slower["arrived_us"][0].get<double>() - first, 4 * 2000 * kCycleUs, 1e-6);
  EXPECT_NEAR(bigger["period_us"].get<double>() - period, 2 * 64 * 0.575, 1e-6);
  EXPECT_NEAR(longer["period_us"].get<double>(), period, 1e-6);
  const double per_stage = (longer["arrived_us"][0].get<double>() - first) / 4;
  EXPECT_GE(per_stage, stage_us(base) + link_us(64));
  EXPECT_LE(per_stage, stage_us(base) + link_us(64) + 2 * kInstructionsUs);
}

// Buffered, the CPU (2000 cycles) is the bottleneck: one item every C or more (the input and
// output processes' instructions share the CPU), under C + T, where unbuffered it is C + 2T.
// With 256-byte items and 200-cycle stages the links are: the output process sends an item, then
// takes the next from the worker -- an internal channel, whose second party copies it (in, out:
// 2w + 19 cycles for w words, the datasheet's instruction table) -- and sends again; the compute
// is hidden.
TEST(FixedStages, BufferedStagesOverlapLinksAndCompute) {
  const auto w = run(" --set workload.buffered=true");
  const double c = stage_us(w), t = link_us(w["item_bytes"]);
  EXPECT_GE(w["period_us"].get<double>(), c);
  EXPECT_LT(w["period_us"].get<double>(), c + t);
  const auto links = run(
      " --set workload.buffered=true --set workload.item_reals=64 --set workload.stage_cycles=200");
  const double bytes = links["item_bytes"];
  const double copy = (2 * bytes / 4 + 19) * kCycleUs;
  const double period = links["period_us"], tl = link_us(bytes);
  EXPECT_GE(period, tl + copy);
  EXPECT_LE(period, tl + copy + kInstructionsUs);
  EXPECT_LT(period, tl + stage_us(links) + copy);  // the stage's 10 us are not in it
  EXPECT_EQ(links["results_checksum"], sequential_stages_checksum(4, 64, 20));
}

TEST(FixedStages, MoreStagesThanProcessorsIsAnError) {
  const auto o = cli_test::run("run configs/scenes/fixed-stages.toml --set workload.stages=9 2>&1");
  EXPECT_EQ(o.exit_code, 2) << o.out;
  EXPECT_NE(o.out.find("--set workload.stages=9"), std::string::npos) << o.out;
  EXPECT_NE(o.out.find("need 10 processors"), std::string::npos) << o.out;
}

}  // namespace
