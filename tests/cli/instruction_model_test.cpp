// The instruction-level compute model end to end: Livermore loop 7 against INMOS's published rates,
// on-chip memory that matters, placement errors, processor types, listings.
#include <cmath>

#include <gtest/gtest.h>

#include "tests/cli/cli_fixtures.hpp"

namespace {

using cli_test::json_number;
using cli_test::run;

double mflops(const std::string& sets) {
  const auto o = run("run configs/scenes/livermore7.toml --json " + sets);
  EXPECT_EQ(o.exit_code, 0) << o.out;
  return json_number(o.out, "mflops");
}

double cycles_per_element(const std::string& sets) {
  const auto o = run("run configs/scenes/livermore7.toml --json " + sets);
  EXPECT_EQ(o.exit_code, 0) << o.out;
  return json_number(o.out, "cycles_per_element");
}

// INMOS Technical Note 6: loop 7 at 1.5 MFLOPS on a T800-20 and 2.25 on a T800-30. Nothing in the
// scene is fitted; the goal is 10 %.
TEST(InstructionModel, LivermoreLoop7MatchesInmosFigures) {
  EXPECT_NEAR(mflops("--set network.processor=T800-20"), 1.5, 0.15);
  EXPECT_NEAR(mflops("--set network.processor=T800-30"), 2.25, 0.225);
}

// The compiler's run-time checks cost a bound check per computed subscript and an error check per
// store; a T414 computes REAL32 in software, many times slower.
TEST(InstructionModel, ChecksAndSoftwareArithmeticCostWhatTheyShould) {
  const double plain = cycles_per_element("");
  EXPECT_GT(cycles_per_element("--set compiler.run_time_checks=true"), plain + 20);
  EXPECT_GT(cycles_per_element("--set network.processor=T414-20 --set network.memory=auto"),
            5 * plain);
}

// A footprint above on-chip RAM moves work off chip (the report says what), and makes it slower.
TEST(InstructionModel, AFootprintAboveFourKilobytesGoesOffChipAndIsSlower) {
  const auto small = run("run configs/scenes/livermore7.toml --json --set network.memory=auto");
  ASSERT_EQ(small.exit_code, 0) << small.out;
  EXPECT_NE(small.out.find("\"off_chip\": []"), std::string::npos) << small.out;
  const auto large =
      run("run configs/scenes/livermore7.toml --json --set network.memory=auto "
          "--set workload.elements=2000");
  ASSERT_EQ(large.exit_code, 0) << large.out;
  EXPECT_NE(large.out.find("\"arrays\""), std::string::npos) << large.out;
  EXPECT_GT(json_number(large.out, "cycles_per_element"),
            json_number(small.out, "cycles_per_element") + 10);
}

// Explicit placement is honoured, and slower with wait states.
TEST(InstructionModel, ExplicitExternalPlacementIsHonoured) {
  const double on_chip = cycles_per_element("");
  const double external = cycles_per_element("--set network.memory=external");
  const double slower =
      cycles_per_element("--set network.memory=external --set network.wait_states=4");
  EXPECT_GT(external, on_chip);
  EXPECT_GT(slower, external);
}

// A placement that cannot hold the program is an error naming the processor and the sizes.
TEST(InstructionModel, OnChipPlacementThatDoesNotFitIsAnError) {
  const auto o = run("run configs/scenes/livermore7.toml --set workload.elements=2000 2>&1");
  EXPECT_EQ(o.exit_code, 2) << o.out;
  EXPECT_NE(o.out.find("processor P0"), std::string::npos) << o.out;
  EXPECT_NE(o.out.find("on-chip RAM has 4096 bytes"), std::string::npos) << o.out;
  EXPECT_NE(o.out.find("memory = \"auto\""), std::string::npos) << o.out;
}

TEST(InstructionModel, UnknownProcessorTypeIsAnError) {
  const auto o = run("run configs/scenes/livermore7.toml --set network.processor=T900-20 2>&1");
  EXPECT_EQ(o.exit_code, 2) << o.out;
  EXPECT_NE(o.out.find("T900-20"), std::string::npos) << o.out;
  EXPECT_NE(o.out.find("T800-20, T800-25, T800-30, T805-20"), std::string::npos) << o.out;
  EXPECT_NE(o.out.find("T414-20"), std::string::npos) << o.out;
}

// The op-count model stays as a faster level; both levels are reported.
TEST(InstructionModel, ComputeCostLevelIsSelectableAndReported) {
  const auto o = run("run configs/scenes/livermore7.toml --json --set fidelity.compute_cost=mix");
  ASSERT_EQ(o.exit_code, 0) << o.out;
  EXPECT_NE(o.out.find("\"compute_cost\": \"mix\""), std::string::npos) << o.out;
  const auto bad = run("run configs/scenes/livermore7.toml --set fidelity.compute_cost=exact 2>&1");
  EXPECT_EQ(bad.exit_code, 2) << bad.out;
  EXPECT_NE(bad.out.find("instructions"), std::string::npos) << bad.out;
}

// The listing shows the loop's code: the load-and-multiply forms, the lend, and each line's cycles.
TEST(InstructionModel, ListingShowsTheGeneratedCode) {
  const auto o = run("listing configs/scenes/livermore7.toml --kernel LOOP7");
  ASSERT_EQ(o.exit_code, 0) << o.out;
  for (const char* text : {"fpldnlmulsn", "fpldnladdsn", "lend", "u[i+3]", "T800-20", "2A FC"})
    EXPECT_NE(o.out.find(text), std::string::npos) << text;
  const auto table = run("listing configs/scenes/dynamics-farm.toml --set network.workers=3");
  ASSERT_EQ(table.exit_code, 0) << table.out;
  EXPECT_NE(table.out.find("D11"), std::string::npos);
  EXPECT_NE(table.out.find("MASTER.INPUT"), std::string::npos);
  const auto missing = run("listing configs/scenes/livermore7.toml --kernel NOPE 2>&1");
  EXPECT_EQ(missing.exit_code, 2) << missing.out;
  EXPECT_NE(missing.out.find("no such kernel"), std::string::npos) << missing.out;
}

}  // namespace
