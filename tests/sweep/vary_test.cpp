// --vary syntax and the cartesian product of a sweep's axes.
#include <gtest/gtest.h>

#include <stdexcept>

#include "tools/sweep_spec.hpp"

using tools::parse_vary;
using tools::sweep_points;
using Values = std::vector<std::string>;

TEST(Vary, IntegerRangeStepsByOne) {
  const auto axis = parse_vary("network.workers=1..5");
  EXPECT_EQ(axis.key, "network.workers");
  EXPECT_EQ(axis.values, (Values{"1", "2", "3", "4", "5"}));
}

TEST(Vary, GeometricRangeMultipliesAndStopsAtTheEnd) {
  EXPECT_EQ(parse_vary("k=1..64:x2").values, (Values{"1", "2", "4", "8", "16", "32", "64"}));
  EXPECT_EQ(parse_vary("k=3..100:x3").values, (Values{"3", "9", "27", "81"}));
}

TEST(Vary, ArithmeticRangeAddsItsStep) {
  EXPECT_EQ(parse_vary("k=1..10:+3").values, (Values{"1", "4", "7", "10"}));
  EXPECT_EQ(parse_vary("k=-2..2:+2").values, (Values{"-2", "0", "2"}));
}

TEST(Vary, ListKeepsTextsAsGiven) {
  EXPECT_EQ(parse_vary("k=10,20").values, (Values{"10", "20"}));
  EXPECT_EQ(parse_vary("network.family=tree,chain").values, (Values{"tree", "chain"}));
  EXPECT_EQ(parse_vary("k=0.5").values, (Values{"0.5"}));
}

// Every malformed flag is an error that quotes the flag and lists the valid forms.
TEST(Vary, BadSyntaxNamesTheFlagAndTheValidForms) {
  for (const char* bad :
       {"workers", "=1..4", "k=", "k=1..", "k=a..b", "k=5..1", "k=1..8:x1", "k=1..8:y2",
        "k=1..8:+0", "k=0..8:x2", "k=1,,2", "k=1.5..3", "k=1-8", "k=2,4-8"}) {
    try {
      parse_vary(bad);
      ADD_FAILURE() << bad << " was accepted";
    } catch (const std::invalid_argument& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find(std::string("--vary ") + bad), std::string::npos) << what;
      EXPECT_NE(what.find("A..B:xF"), std::string::npos) << what;
    }
  }
}

// "1-8" is a range written the wrong way: the message shows the right way.
TEST(Vary, ADashedRangeIsShownAsARange) {
  try {
    parse_vary("network.workers=1-8");
    FAIL() << "1-8 accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("write 1..8"), std::string::npos) << e.what();
  }
}

// Paths have two dots in a row too: a list of topology files is a list, not a range.
TEST(Vary, TopologyFilesAreAList) {
  EXPECT_EQ(parse_vary("network.topology=../topologies/a.toml,../topologies/b.toml").values,
            (Values{"../topologies/a.toml", "../topologies/b.toml"}));
  EXPECT_EQ(parse_vary("network.topology=../topologies/a.toml").values,
            (Values{"../topologies/a.toml"}));
}

TEST(Vary, HugeRangesAreRefused) {
  EXPECT_THROW(parse_vary("k=1..1000000"), std::invalid_argument);
}

TEST(SweepPoints, CartesianProductWithTheLastAxisFastest) {
  const auto points = sweep_points({parse_vary("a=1,2"), parse_vary("b=x,y,z")});
  ASSERT_EQ(points.size(), 6u);
  EXPECT_EQ(tools::point_text(points[0]), "a=1 b=x");
  EXPECT_EQ(tools::point_text(points[2]), "a=1 b=z");
  EXPECT_EQ(tools::point_text(points[3]), "a=2 b=x");
  EXPECT_EQ(tools::point_text(points[5]), "a=2 b=z");
}

TEST(SweepPoints, TheSameKeyTwiceIsAnError) {
  EXPECT_THROW(sweep_points({parse_vary("a=1,2"), parse_vary("a=3")}), std::invalid_argument);
}

TEST(SweepPoints, ProductsBeyondTheLimitAreRefused) {
  EXPECT_THROW(sweep_points({parse_vary("a=1..1000"), parse_vary("b=1..1000")}),
               std::invalid_argument);
}
