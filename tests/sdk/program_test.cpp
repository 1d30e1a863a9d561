// Programs written with the SDK: typed values arrive intact over every kind of channel, each item
// of a protocol is its own communication, and mistakes in a program's declarations are clear errors
// before anything runs.
#include <gtest/gtest.h>

#include <algorithm>

#include "network/config_error.hpp"
#include "sdk_fixtures.hpp"
#include "t800sim/workload.hpp"

namespace {

using namespace t800sim;
using sdk_test::Lambda;

using Message = Sequential<INT, Counted<INT, REAL64>, Variant<Case<REAL32>, Case<>>>;

// The same message sent from P0 to a process on P0 (internal), P1 (a link) and P3 (routed through
// P1 and P2) arrives as it was sent.
TEST(SdkProgram, TypedValuesArriveIntactOnEveryKindOfChannel) {
  const value_of<Variant<Case<REAL32>, Case<>>> data{std::in_place_index<0>, Case<REAL32>{{0.25f}}};
  const value_of<Message> sent{42, {1.0, -2.5, 1e-300}, data};
  std::vector<value_of<Message>> got(3);
  auto* program = new Lambda([&](Builder& b) {
    const auto out = b.channels<Message>("c", 3, "sender", "receiver");
    b.process("sender", [out, sent](Process& p) {
      for (const auto& c : out) p.out(c, sent);
    });
    b.processes("receiver", 3, [out, &got](Process& p, int i) {
       got[std::size_t(i)] = p.in(out[std::size_t(i)]);
     }).placed_on(std::vector<std::string>{"P0", "P1", "P3"});
  });
  const auto outcome = sdk_test::run(program, sdk_test::chain(3));
  ASSERT_TRUE(outcome.blocked.empty());
  for (const auto& v : got) EXPECT_EQ(v, sent);
}

// Over a link, INT; INT is two communications and [2]INT one: the same eight bytes, but the
// sequential protocol pays a second output's set-up and link start.
TEST(SdkProgram, EachItemOfASequentialProtocolIsItsOwnCommunication) {
  // Two INTs as a sequential protocol are two link messages; as an array they are one. Both pairs
  // run side by side on links of their own, so only the protocol differs.
  double end_two = 0, end_one = 0;
  auto* program = new Lambda([&](Builder& b) {
    const auto two = b.channel<Sequential<INT, INT>>("two", "a", "b");
    const auto one = b.channel<Array<INT, 2>>("one", "c", "d");
    b.process("a", [two](Process& p) { p.out(two, {1, 2}); }).placed_on("P0");
    b.process("b", [two, &end_two](Process& p) {
       p.in(two);
       end_two = p.now_us();
     }).placed_on("P1");
    b.process("c", [one](Process& p) { p.out(one, {1, 2}); }).placed_on("P2");
    b.process("d", [one, &end_one](Process& p) {
       p.in(one);
       end_one = p.now_us();
     }).placed_on("P3");
  });
  ASSERT_TRUE(sdk_test::run(program, sdk_test::chain(3)).blocked.empty());
  EXPECT_GT(end_one, 0.0);
  EXPECT_GT(end_two, end_one);
}

TEST(SdkProgram, PlacementIsReportedWithWhatDecidedIt) {
  auto* program = new Lambda([](Builder& b) {
    const auto c = b.channel<INT>("c", "a", "b");
    b.process("a", [c](Process& p) { p.out(c, 1); });
    b.process("b", [c](Process& p) { p.in(c); }).placed_on("P1");
    b.processes("idle", 2, [](Process&, int) {});
  });
  const workloads::Placement scene{{"idle[1]", {"P2"}, {"scene.toml", 4, 1}}};
  const auto outcome = sdk_test::run(program, sdk_test::chain(2), scene);
  ASSERT_TRUE(outcome.blocked.empty());
  const auto& placement = outcome.results.get("placement")->items();
  ASSERT_EQ(placement.size(), 4u);
  auto field = [&](std::size_t i, const char* key) { return placement[i].get(key)->to_json(); };
  EXPECT_EQ(field(0, "processor"), "\"P0\"");
  EXPECT_NE(field(0, "placed_by").find("default"), std::string::npos);
  EXPECT_EQ(field(1, "processor"), "\"P1\"");
  EXPECT_EQ(field(1, "placed_by"), "\"the program\"");
  EXPECT_EQ(field(3, "process"), "\"idle[1]\"");
  EXPECT_EQ(field(3, "processor"), "\"P2\"");
  EXPECT_EQ(field(3, "placed_by"), "\"scene scene.toml:4\"");
}

// The error a build throws, or "" when it does not.
std::string build_error(std::function<void(Builder&)> build,
                        const workloads::Placement& placement = {}) {
  try {
    sdk_test::run(new Lambda(std::move(build)), sdk_test::chain(2), placement);
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

TEST(SdkProgram, AProtocolMismatchBetweenTheEndsIsAnError) {
  const std::string e = build_error([](Builder& b) {
    const auto out = b.output<INT>("c", "a");
    const auto in = b.input<REAL32>("c", "b");
    b.process("a", [out](Process& p) { p.out(out, 1); });
    b.process("b", [in](Process& p) { p.in(in); });
  });
  EXPECT_NE(e.find("channel c: protocol mismatch"), std::string::npos) << e;
  EXPECT_NE(e.find("as INT"), std::string::npos) << e;
  EXPECT_NE(e.find("as REAL32"), std::string::npos) << e;
}

TEST(SdkProgram, DeclarationMistakesAreErrors) {
  EXPECT_NE(build_error([](Builder& b) {
              b.output<INT>("c", "a");
              b.process("a", [](Process&) {});
            }).find("channel c has no reader (its writer is a)"),
            std::string::npos);
  EXPECT_NE(build_error([](Builder& b) {
              b.output<INT>("c", "a");
              b.output<INT>("c", "b");
            }).find("both a and b outputs to it"),
            std::string::npos);
  EXPECT_NE(build_error([](Builder& b) {
              b.channel<INT>("c", "a", "ghost");
              b.process("a", [](Process&) {});
            }).find("joined to process ghost, which the program does not declare"),
            std::string::npos);
  EXPECT_NE(build_error([](Builder& b) {
              b.channel<INT>("c", "a", "w");
              b.process("a", [](Process&) {});
              b.processes("w", 2, [](Process&, int) {});
            }).find("a group of 2: name one member, w[i]"),
            std::string::npos);
  EXPECT_NE(build_error([](Builder& b) {
              b.process("a", [](Process&) {});
              b.process("a", [](Process&) {});
            }).find("process a is declared twice"),
            std::string::npos);
}

TEST(SdkProgram, ScenePlacementMistakesNameTheSceneLine) {
  auto declare = [](Builder& b) { b.processes("w", 2, [](Process&, int) {}); };
  auto where = [&](const workloads::Placement& placement) {
    try {
      sdk_test::run(new Lambda(declare), sdk_test::chain(2), placement);
    } catch (const network::ConfigError& e) {
      return std::to_string(e.where().line) + ": " + e.message();
    }
    return std::string("no error");
  };
  EXPECT_EQ(
      where({{"v", {"P1"}, {"s.toml", 7, 1}}}),
      "7: [placement] names process v, which workload test does not declare; it declares w[0..1]");
  EXPECT_EQ(where({{"w", {"P1", "P2", "P0"}, {"s.toml", 8, 5}}}),
            "8: [placement] w: 2 processes, so one processor for all or a list of 2, not 3");
  EXPECT_EQ(
      where({{"w[1]", {"P9"}, {"s.toml", 9, 8}}}),
      "9: [placement] w[1] is placed on P9, which the network does not have; it has P0, P1, P2");
}

}  // namespace

TEST(SdkRegistration, AKindHasAtMostOnePrecision) {
  EXPECT_THROW(t800sim::register_workload({"two-precisions",
                                           "a kind that says twice what its arithmetic is",
                                           {t800sim::precision_param("a", "real32", "one"),
                                            t800sim::precision_param("b", "real64", "two")},
                                           [](const t800sim::Params&, const t800sim::Network&) {
                                             return std::unique_ptr<t800sim::Program>();
                                           }}),
               std::invalid_argument);
}

namespace {

// A group member marked not running is declared -- placed, and a channel may name it -- but its
// body never runs: a replicated PAR over the members that have work.
TEST(SdkProgram, AGroupMemberNotRunningIsDeclaredButNotRun) {
  std::vector<int> ran;
  auto* program = new sdk_test::Lambda([&](t800sim::Builder& b) {
    const auto c = b.channel<t800sim::INT>("c", "sender", "member[1]");
    b.process("sender", [](t800sim::Process&) {});
    b.processes("member", 3, [&ran](t800sim::Process&, int i) { ran.push_back(i); })
        .placed_on(std::vector<std::string>{"P1", "P2", "P3"})
        .running({true, false, true});
    (void)c;
  });
  const auto outcome = sdk_test::run(program, sdk_test::chain(3));
  ASSERT_TRUE(outcome.blocked.empty());
  std::sort(ran.begin(), ran.end());
  EXPECT_EQ(ran, (std::vector<int>{0, 2}));
}

}  // namespace
