// A pipeline of process stages that serves until a stop and keeps its results on its last stage
// (t800sim/pipeline.hpp: build(..., kUntilStop) and no collector), as the elimination's levels
// serve a trajectory's solves until its master finishes, or keep Table 6's q̈ on level 4.
#include <gtest/gtest.h>

#include <memory>

#include "sdk_fixtures.hpp"
#include "t800sim/pipeline.hpp"

namespace {

using namespace t800sim;
using sdk_test::Lambda;

constexpr INT kStop = -1;

struct Kept {
  std::vector<INT> items;    // what the last stage kept, in order
  std::size_t last_to = 99;  // the last stage's channels on (none without a collector)
  int rounds_seen = 0;
};

// The client on P0 sends 1..count then a stop; "add" (P1) adds 10 to each item and passes the stop
// on; "keep" (P2) keeps what it gets until the stop. Every process ends.
void build_chain(Builder& b, int count, std::shared_ptr<Kept> kept) {
  auto add = [](Process& p, const StageEnds<INT, INT>& e) {
    for (int r = 0; e.more(r); ++r) {
      const INT x = p.in(e.from[0]);
      p.out(e.to[0], x == kStop ? kStop : x + 10);
      if (x == kStop) return;
    }
  };
  auto keep = [kept](Process& p, const StageEnds<INT, INT>& e) {
    kept->last_to = e.to.size();
    kept->rounds_seen = e.rounds;
    for (int r = 0; e.more(r); ++r) {
      const INT x = p.in(e.from[0]);
      if (x == kStop) return;
      kept->items.push_back(x);
    }
  };
  const auto pipe = pipeline<INT>()
                        .process_stage<INT>("add", add)
                        .on("P1")
                        .process_stage<INT>("keep", keep)
                        .on("P2")
                        .build(b, "client", "", kUntilStop);
  b.process("client", [pipe, count](Process& p) {
     for (int r = 0; r < count; ++r) p.out(pipe.in(r), INT(r + 1));
     p.out(pipe.in(count), kStop);
   }).placed_on("P0");
}

class UntilStop : public ::testing::TestWithParam<int> {};

// By hand: the last stage keeps 11, 12, ..., count + 10, and nothing waits at the end.
TEST_P(UntilStop, EveryStageServesUntilTheStopAndTheLastKeepsItsResults) {
  const int count = GetParam();
  auto kept = std::make_shared<Kept>();
  const auto o = sdk_test::run(new Lambda([=](Builder& b) { build_chain(b, count, kept); }),
                               sdk_test::chain(2));
  EXPECT_TRUE(o.blocked.empty()) << "a process was left waiting";
  std::vector<INT> expected;
  for (int r = 0; r < count; ++r) expected.push_back(r + 11);
  EXPECT_EQ(kept->items, expected);
  EXPECT_EQ(kept->last_to, 0u);
  EXPECT_EQ(kept->rounds_seen, kUntilStop);
}

INSTANTIATE_TEST_SUITE_P(PipelineUntilStop, UntilStop, ::testing::Values(0, 1, 5));

// No channel leaves the last stage without a collector: the program's channels are the client's
// into add and add's into keep.
TEST(PipelineUntilStop, WithoutACollectorTheLastStageHasNoChannelOut) {
  const network::Topology topology = sdk_test::chain(2);
  Builder b(topology);
  build_chain(b, 1, std::make_shared<Kept>());
  std::vector<std::string> names;
  for (const auto& c : b.declared_channels()) names.push_back(c.name);
  EXPECT_EQ(names, (std::vector<std::string>{"client->add[0][0]", "add->keep[0][0]"}));
}

// Only process stages recognise a stop or keep their results; a stage of the skeleton's own serves
// a number of rounds and gives each result on.
TEST(PipelineUntilStop, OnlyProcessStagesServeUntilAStopOrEndWithoutACollector) {
  const network::Topology topology = sdk_test::chain(2);
  auto twice = [](Process&, INT x) { return 2 * x; };
  auto body = [](Process&, const StageEnds<INT, INT>&) {};
  {
    Builder b(topology);
    EXPECT_THROW(pipeline<INT>().stage<INT>("s", twice).build(b, "c", "c", kUntilStop),
                 std::invalid_argument);
  }
  {
    Builder b(topology);
    EXPECT_THROW(pipeline<INT>().stage<INT>("s", twice).build(b, "c", "", 3),
                 std::invalid_argument);
  }
  {
    Builder b(topology);
    EXPECT_THROW(pipeline<INT>().process_stage<INT>("s", body).build(b, "c", "c", -2),
                 std::invalid_argument);
  }
  {
    Builder b(topology);
    const auto pipe = pipeline<INT>().process_stage<INT>("s", body).build(b, "c", "", 3);
    EXPECT_THROW(pipe.out(0), std::logic_error);
  }
}

}  // namespace
