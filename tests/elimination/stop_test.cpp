// occam's STOP in the pipeline (Process::stop): with overlap, L1's receiver stores each row L3
// streams back at the row number in its header word; a corrupted number out of range stops that
// branch with the number in the reason, and the run is a deadlock report naming it (exit 1), never
// results. The corrupt fault XORs the first byte of L3 -> L1's first message, the lowest byte of
// the header word (little-endian): a row number below 64 becomes itself + 64, and the system has
// n = 6 unknowns (the Stanford arm), so step 1's rows are 0..4 and the number read is 64..68.
#include <gtest/gtest.h>

#include <regex>
#include <string>

#include "tests/cli/cli_fixtures.hpp"

namespace {

TEST(PipelineStop, ARowNumberOutOfRangeStopsLevel1WithTheNumber) {
  const auto o = cli_test::run(
      "run configs/scenes/elimination.toml --set workload.m=3 --set workload.overlap=true "
      "--fault 'kind=corrupt,link=L3->L1,at_us=0,xor=64' 2>&1");
  EXPECT_EQ(o.exit_code, 1) << o.out;
  std::smatch match;
  ASSERT_TRUE(
      std::regex_search(o.out, match,
                        std::regex("level1[^ ]* on L1: stopped by a run-time error: row number "
                                   "([0-9]+) out of range")))
      << o.out;
  const int number = std::stoi(match[1]);
  EXPECT_GE(number, 64);
  EXPECT_LE(number, 68);
  EXPECT_EQ(o.out.find("qdd"), std::string::npos);  // no results
}

}  // namespace
