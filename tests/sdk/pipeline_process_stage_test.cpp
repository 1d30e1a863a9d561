// Process stages of the pipeline skeleton (t800sim/pipeline.hpp): stages written as processes that
// deal a round's items to chosen members of a group and take them back, and a loop -- a channel the
// program declares from the last stage back to the first -- as the elimination's levels use them.
#include <gtest/gtest.h>

#include "sdk_fixtures.hpp"
#include "t800sim/pipeline.hpp"

namespace {

using namespace t800sim;
using sdk_test::Lambda;

using Vector = Counted<INT, INT>;           // a round's vector: INT::[]INT
using Element = Sequential<INT, INT, INT>;  // (index, value, member that worked on it)

struct Loop {
  int length = 5;   // elements per vector
  int members = 2;  // the work group
  int steps = 3;    // trips round the loop per round
  int rounds = 4;
};

// Round r's vector enters `spread` as v[j] = 100 r + j. Each step, spread deals element j to
// member j mod members of `work`, which adds j + 1 and tags it with its member index; `gather`
// reassembles the vector and sends it back to spread for the next step, and after the last step
// on to the collector. By hand: the result is v[j] + steps (j + 1), every element tagged by member
// j mod members. Returns the collector's vectors and the tags gather saw.
struct LoopOutcome {
  std::vector<std::vector<INT>> vectors;
  std::vector<std::vector<INT>> tags;  // per round, per element (the last step's)
  std::vector<network::BlockedProcess> blocked;
};

LoopOutcome run_loop(const Loop& s) {
  auto out = std::make_shared<LoopOutcome>();
  out->vectors.assign(std::size_t(s.rounds), {});
  out->tags.assign(std::size_t(s.rounds), std::vector<INT>(std::size_t(s.length), -1));
  auto* program = new Lambda([s, out](Builder& b) {
    // The loop: an ordinary channel between the two stages' processes, by their names.
    const Chan<Vector> back = b.channel<Vector>("gather->spread", "gather", "spread");
    std::vector<std::string> work_on;
    for (int i = 0; i < s.members; ++i) work_on.push_back("P" + std::to_string(2 + i));
    const auto pipe =
        pipeline<Vector>()
            .process_stage<Element>(
                "spread",
                [s, back](Process& p, const StageEnds<Vector, Element>& e) {
                  for (int r = 0; r < e.rounds; ++r) {
                    std::vector<INT> v = p.in(e.from[0]);
                    for (int k = 0; k < s.steps; ++k) {
                      if (k > 0) v = p.in(back.in());
                      for (int j = 0; j < s.length; ++j)
                        p.out(e.to[std::size_t(j % s.members)], {j, v[std::size_t(j)], -1});
                    }
                  }
                })
            .on("P1")
            .process_group<Element>("work", s.members,
                                    [s](Process& p, const StageEnds<Element, Element>& e) {
                                      // This member's elements per step: j = member, member +
                                      // members, ...
                                      int mine = 0;
                                      for (int j = e.member; j < s.length; j += s.members) ++mine;
                                      for (int r = 0; r < e.rounds * s.steps; ++r)
                                        for (int n = 0; n < mine; ++n) {
                                          auto [j, x, tag] = p.in(e.from[0]);
                                          (void)tag;
                                          p.compute(200);
                                          p.out(e.to[0], {j, x + j + 1, e.member});
                                        }
                                    })
            .on(work_on)
            .process_stage<Vector>("gather",
                                   [s, back, out](Process& p, const StageEnds<Element, Vector>& e) {
                                     for (int r = 0; r < e.rounds; ++r)
                                       for (int k = 0; k < s.steps; ++k) {
                                         std::vector<INT> v(std::size_t(s.length));
                                         // Element j comes from member j mod members, in order.
                                         for (int j = 0; j < s.length; ++j) {
                                           auto [index, x, tag] =
                                               p.in(e.from[std::size_t(j % s.members)]);
                                           v[std::size_t(index)] = x;
                                           out->tags[std::size_t(r)][std::size_t(index)] = tag;
                                         }
                                         if (k + 1 < s.steps)
                                           p.out(back.out(), v);
                                         else
                                           p.out(e.to[0], v);
                                       }
                                   })
            .on("P" + std::to_string(2 + s.members))
            .build(b, "client", "client", s.rounds);
    b.process("client", [pipe, s, out](Process& p) {
       for (int r = 0; r < s.rounds; ++r) {
         std::vector<INT> v;
         for (int j = 0; j < s.length; ++j) v.push_back(100 * r + j);
         p.out(pipe.in(r), v);
         out->vectors[std::size_t(r)] = p.in(pipe.out(r));
       }
     }).placed_on("P0");
  });
  out->blocked = sdk_test::run(program, sdk_test::chain(2 + s.members)).blocked;
  return *out;
}

void PrintTo(const Loop& s, std::ostream* os) {
  *os << "length" << s.length << "_members" << s.members << "_steps" << s.steps << "_rounds"
      << s.rounds;
}

class EveryLoop : public ::testing::TestWithParam<Loop> {};

TEST_P(EveryLoop, EachElementGoesRoundTheLoopStepsTimesOnItsMember) {
  const Loop s = GetParam();
  const LoopOutcome o = run_loop(s);
  EXPECT_TRUE(o.blocked.empty()) << "a process was left waiting";
  for (int r = 0; r < s.rounds; ++r) {
    ASSERT_EQ(o.vectors[std::size_t(r)].size(), std::size_t(s.length)) << r;
    for (int j = 0; j < s.length; ++j) {
      EXPECT_EQ(o.vectors[std::size_t(r)][std::size_t(j)], 100 * r + j + s.steps * (j + 1))
          << "round " << r << " element " << j;
      EXPECT_EQ(o.tags[std::size_t(r)][std::size_t(j)], j % s.members);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(PipelineProcessStages, EveryLoop,
                         ::testing::Values(Loop{5, 2, 3, 4}, Loop{5, 1, 1, 2}, Loop{6, 3, 4, 3},
                                           Loop{2, 3, 2, 2}));

TEST(PipelineProcessStages, AProcessStageIsNotBufferedByTheSkeleton) {
  auto body = [](Process&, const StageEnds<INT, INT>&) {};
  EXPECT_THROW(pipeline<INT>().process_stage<INT>("s", body).buffered(), std::logic_error);
  EXPECT_THROW(pipeline<INT>().process_group<INT>("g", 0, body), std::invalid_argument);
}

}  // namespace
