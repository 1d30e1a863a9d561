// The pipeline skeleton (t800sim/pipeline.hpp): every round's item passes every stage once and in
// order, through single stages, groups and buffered stages alike, whatever the number of rounds.
#include <gtest/gtest.h>

#include "sdk_fixtures.hpp"
#include "t800sim/pipeline.hpp"

namespace {

using namespace t800sim;
using sdk_test::Lambda;

struct Shape {
  int group = 1;  // the middle stage's processes
  bool buffered = false;
  int rounds = 7;
};
void PrintTo(const Shape& s, std::ostream* os) {
  *os << "group" << s.group << (s.buffered ? "_buffered" : "") << "_rounds" << s.rounds;
}

// Three stages, x -> 2x + 1 -> (x, member that did it) -> x * 10 + member, on P1.. of a chain; the
// client on P0 feeds and collects in PAR. Returns what the client got, round by round.
std::vector<INT> run_pipeline(const Shape& s, std::vector<double>* arrived = nullptr) {
  std::vector<INT> got(std::size_t(s.rounds), -1);
  auto* program = new Lambda([&](Builder& b) {
    std::vector<std::string> middle;
    for (int i = 0; i < s.group; ++i) middle.push_back("P" + std::to_string(2 + i));
    auto decl = pipeline<INT>()
                    .stage<INT>("double",
                                [](Process& p, INT x) {
                                  p.compute(100);
                                  return 2 * x + 1;
                                })
                    .on("P1")
                    .group<Sequential<INT, INT>>("tag", s.group,
                                                 [](Process& p, INT x) {
                                                   p.compute(300);
                                                   // which member: its processor's number
                                                   return std::tuple<INT, INT>(
                                                       x, INT(std::stoi(p.processor().substr(1))));
                                                 })
                    .on(middle)
                    .stage<INT>("merge",
                                [](Process& p, const std::tuple<INT, INT>& v) {
                                  p.compute(100);
                                  return std::get<0>(v) * 10 + std::get<1>(v);
                                })
                    .on("P" + std::to_string(2 + s.group));
    if (s.buffered) decl = std::move(decl).buffered();
    const auto pipe = decl.build(b, "feeder", "collector", s.rounds);
    b.process("feeder", [pipe, s](Process& p) {
       for (int r = 0; r < s.rounds; ++r) p.out(pipe.in(r), INT(r));
     }).placed_on("P0");
    b.process("collector", [pipe, s, &got, arrived](Process& p) {
       for (int r = 0; r < s.rounds; ++r) {
         got[std::size_t(r)] = p.in(pipe.out(r));
         if (arrived) arrived->push_back(p.now_us());
       }
     }).placed_on("P0");
  });
  const auto outcome = sdk_test::run(program, sdk_test::chain(2 + s.group));
  EXPECT_TRUE(outcome.blocked.empty()) << "a process was left waiting";
  return got;
}

// Round r: 2r + 1 from the first stage, tagged by member r mod g of the group (on P2 + r mod g).
INT expected(int r, int group) {
  return (2 * r + 1) * 10 + 2 + r % group;
}

// One simulation per test (SystemC runs one per process; ctest runs each test on its own).
class EveryShape : public ::testing::TestWithParam<Shape> {};

TEST_P(EveryShape, EveryRoundPassesEveryStageInOrder) {
  const Shape s = GetParam();
  const auto got = run_pipeline(s);
  ASSERT_EQ(got.size(), std::size_t(s.rounds));
  for (int r = 0; r < s.rounds; ++r) EXPECT_EQ(got[std::size_t(r)], expected(r, s.group)) << r;
}

INSTANTIATE_TEST_SUITE_P(PipelineSkeleton, EveryShape,
                         ::testing::Values(Shape{1, false, 7}, Shape{2, false, 7},
                                           Shape{3, false, 7}, Shape{1, true, 7}, Shape{2, true, 7},
                                           Shape{3, true, 7}, Shape{3, false, 1}, Shape{3, true, 2},
                                           Shape{3, true, 0}));

// The results come out one by one, each later than the one before (the collector takes them in
// round order from the member whose round it is).
TEST(PipelineSkeleton, ResultsArriveInRoundOrder) {
  std::vector<double> arrived;
  run_pipeline({2, false, 6}, &arrived);
  ASSERT_EQ(arrived.size(), 6u);
  for (std::size_t r = 1; r < arrived.size(); ++r) EXPECT_GT(arrived[r], arrived[r - 1]);
}

TEST(PipelineSkeleton, DeclarationMistakesAreClearErrors) {
  EXPECT_THROW(pipeline<INT>().group<INT>("g", 0, [](Process&, INT x) { return x; }),
               std::invalid_argument);
  EXPECT_THROW(pipeline<INT>().on("P1"), std::logic_error);
}

}  // namespace
