// Process stages of the pipeline skeleton (t800sim/pipeline.hpp): stages written as processes that
// deal a round's items to chosen members of a group and take them back, and a loop -- a channel the
// program declares from the last stage back to the first -- as the elimination's levels use them.
#include <gtest/gtest.h>

#include <map>
#include <memory>

#include "network/topology_file.hpp"
#include "sdk_fixtures.hpp"
#include "t800sim/pipeline.hpp"
#include "tests/test_paths.hpp"

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
  // On the elimination's m = 4 network (configs/topologies/elimination-m4.toml): spread on L1,
  // work on E1..E4, gather on L3, the client on L4; E3 and E4 reached through the link processors
  // X and Y (members = 4).
  bool relayed = false;
  // The last round stops at its second step: spread sends a stop header (index -2) and ends; each
  // member with elements sends a stop in their place and ends; gather sends an empty vector.
  bool stop = false;
  // Member 0 on E3 (behind both relays) and member 2 on E1, with member 0 listed as direct
  // (RelayPlan::direct): its channels are its own, routed through X and Y by the network.
  bool direct_first = false;
  // The relays name what they forward (RelayPlan::label_in / label_out): the header "header",
  // element j "element j".
  bool labelled = false;
};

network::Topology loop_network(const Loop& s) {
  if (!s.relayed) return sdk_test::chain(2 + s.members);
  return network::load_topology(test_paths::source_dir() +
                                "/configs/topologies/elimination-m4.toml");
}

// The relays' plan of one trip round the loop (relay round r: pipeline round r / steps, step
// r mod steps): the step's header to every member, then element j to member j mod members; back
// in the order of the elements.
RelayPlan<Element, Element> loop_plan(const Loop& s) {
  RelayPlan<Element, Element> plan;
  plan.fan_out = "X";
  plan.fan_in = "Y";
  plan.rounds = s.rounds * s.steps;
  plan.stops_in = [](const value_of<Element>& m) { return std::get<0>(m) == -2; };
  plan.stops_out = plan.stops_in;
  if (s.direct_first) plan.direct = {0};
  if (s.labelled) {
    plan.label_in = [](const value_of<Element>&, int, int index) {
      return index == 0 ? std::string("header") : "element " + std::to_string(index - 1);
    };
    plan.label_out = [](const value_of<Element>&, int, int index) {
      return "element " + std::to_string(index);
    };
  }
  plan.scatter = [s](int) {
    std::vector<std::vector<int>> messages(1);
    for (int e = 0; e < s.members; ++e) messages[0].push_back(e);
    for (int j = 0; j < s.length; ++j) messages.push_back({j % s.members});
    return messages;
  };
  plan.gather = [s](int) {
    std::vector<int> order;
    for (int j = 0; j < s.length; ++j) order.push_back(j % s.members);
    return order;
  };
  return plan;
}

// Round r's vector enters `spread` as v[j] = 100 r + j. Each step, spread deals element j to
// member j mod members of `work`, which adds j + 1 and tags it with its member index; `gather`
// reassembles the vector and sends it back to spread for the next step, and after the last step
// on to the collector. By hand: the result is v[j] + steps (j + 1), every element tagged by member
// j mod members. Returns the collector's vectors and the tags gather saw.
struct LoopOutcome {
  std::vector<std::vector<INT>> vectors;
  std::vector<std::vector<INT>> tags;         // per round, per element (the last step's)
  std::vector<std::pair<bool, bool>> behind;  // per member: behind the fan-out, the fan-in
  std::vector<network::BlockedProcess> blocked;
};

// The loop's processes, declared on a Builder (the test of the relays' placement reads them).
void build_loop(Builder& b, const Loop& s, std::shared_ptr<LoopOutcome> out) {
  const auto on = [&](const char* relayed, const std::string& chained) {
    return s.relayed ? std::string(relayed) : chained;
  };
  // The loop: an ordinary channel between the two stages' processes, by their names.
  const Chan<Vector> back = b.channel<Vector>("gather->spread", "gather", "spread");
  std::vector<std::string> work_on;
  for (int i = 0; i < s.members; ++i)
    work_on.push_back(s.relayed ? "E" + std::to_string(1 + i) : "P" + std::to_string(2 + i));
  if (s.direct_first) std::swap(work_on[0], work_on[2]);
  auto spread = [s, back](Process& p, const StageEnds<Vector, Element>& e) {
    for (int r = 0; r < e.rounds; ++r) {
      std::vector<INT> v = p.in(e.from[0]);
      for (int k = 0; k < s.steps; ++k) {
        if (k > 0) v = p.in(back.in());
        const bool stop = s.stop && r + 1 == e.rounds && k == 1;
        // The step's header: once on each channel (a relay copies it to the members behind it).
        for (const auto& port : e.to_ports()) p.out(port.channel, {stop ? -2 : -1, k, -1});
        if (stop) return;
        for (int j = 0; j < s.length; ++j)
          p.out(e.to[std::size_t(j % s.members)], {j, v[std::size_t(j)], -1});
      }
    }
  };
  auto work = [s, out](Process& p, const StageEnds<Element, Element>& e) {
    if (out) out->behind[std::size_t(e.member)] = {e.behind_fan_out, e.behind_fan_in};
    int mine = 0;  // this member's elements per step: j = member, member + members, ...
    for (int j = e.member; j < s.length; j += s.members) ++mine;
    for (int r = 0; r < e.rounds * s.steps; ++r) {
      const auto [kind, step, unused] = p.in(e.from[0]);  // the header
      (void)unused;
      if (kind == -2) {
        if (mine > 0) p.out(e.to[0], {-2, 0, e.member});
        return;
      }
      for (int n = 0; n < mine; ++n) {
        const auto [j, x, tag] = p.in(e.from[0]);
        (void)tag;
        p.compute(200);
        p.out(e.to[0], {j, x + j + 1 + step, e.member});
      }
    }
  };
  auto gather = [s, back, out](Process& p, const StageEnds<Element, Vector>& e) {
    for (int r = 0; r < e.rounds; ++r)
      for (int k = 0; k < s.steps; ++k) {
        std::vector<INT> v(std::size_t(s.length));
        for (int j = 0; j < s.length; ++j) {  // element j from member j mod members, in order
          const In<Element>& from = e.from[std::size_t(j % s.members)];
          const auto [index, x, tag] = p.in(from);
          if (index == -2) {  // a stop: every other channel with elements brings one
            for (const auto& port : e.from_ports())
              if (port.channel.slot() != from.slot() && port.members.front() < s.length)
                p.in(port.channel);
            p.out(e.to[0], {});
            return;
          }
          v[std::size_t(index)] = x;
          if (out) out->tags[std::size_t(r)][std::size_t(index)] = tag;
        }
        if (k + 1 < s.steps)
          p.out(back.out(), v);
        else
          p.out(e.to[0], v);
      }
  };
  auto decl = pipeline<Vector>()
                  .process_stage<Element>("spread", spread)
                  .on(on("L1", "P1"))
                  .process_group<Element>("work", s.members, work)
                  .on(work_on);
  if (s.relayed) decl = std::move(decl).relayed(loop_plan(s));
  const auto pipe = std::move(decl)
                        .process_stage<Vector>("gather", gather)
                        .on(on("L3", "P" + std::to_string(2 + s.members)))
                        .build(b, "client", "client", s.rounds);
  b.process("client", [pipe, s, out](Process& p) {
     for (int r = 0; r < s.rounds; ++r) {
       std::vector<INT> v;
       for (int j = 0; j < s.length; ++j) v.push_back(100 * r + j);
       p.out(pipe.in(r), v);
       const std::vector<INT> result = p.in(pipe.out(r));
       if (out) out->vectors[std::size_t(r)] = result;
     }
   }).placed_on(on("L4", "P0"));
}

LoopOutcome run_loop(const Loop& s, const std::vector<network::FaultSpec>& faults = {},
                     std::vector<network::FaultRecord>* records = nullptr) {
  auto out = std::make_shared<LoopOutcome>();
  out->vectors.assign(std::size_t(s.rounds), {});
  out->tags.assign(std::size_t(s.rounds), std::vector<INT>(std::size_t(s.length), -1));
  out->behind.assign(std::size_t(s.members), {true, true});
  auto* program = new Lambda([s, out](Builder& b) { build_loop(b, s, out); });
  const sdk_test::Outcome o = sdk_test::run(program, loop_network(s), {}, faults);
  out->blocked = o.blocked;
  if (records) *records = o.faults;
  return *out;
}

void PrintTo(const Loop& s, std::ostream* os) {
  *os << "length" << s.length << "_members" << s.members << "_steps" << s.steps << "_rounds"
      << s.rounds << (s.relayed ? "_relayed" : "") << (s.direct_first ? "_direct" : "")
      << (s.labelled ? "_labelled" : "");
}

class EveryLoop : public ::testing::TestWithParam<Loop> {};

TEST_P(EveryLoop, EachElementGoesRoundTheLoopStepsTimesOnItsMember) {
  const Loop s = GetParam();
  const LoopOutcome o = run_loop(s);
  EXPECT_TRUE(o.blocked.empty()) << "a process was left waiting";
  for (int r = 0; r < s.rounds; ++r) {
    ASSERT_EQ(o.vectors[std::size_t(r)].size(), std::size_t(s.length)) << r;
    for (int j = 0; j < s.length; ++j) {
      // Each trip adds j + 1 and the step's number: steps (j + 1) + 0 + 1 + ... + (steps - 1).
      EXPECT_EQ(o.vectors[std::size_t(r)][std::size_t(j)],
                100 * r + j + s.steps * (j + 1) + s.steps * (s.steps - 1) / 2)
          << "round " << r << " element " << j;
      EXPECT_EQ(o.tags[std::size_t(r)][std::size_t(j)], j % s.members);
    }
  }
  // On the m = 4 network the members on E3 and E4 are behind both relays, unless listed direct.
  for (int i = 0; i < s.members; ++i) {
    const bool on_e3_or_e4 = s.relayed && (s.direct_first ? i == 3 || i == 0 : i >= 2);
    const bool behind = on_e3_or_e4 && !(s.direct_first && i == 0);
    EXPECT_EQ(o.behind[std::size_t(i)], std::make_pair(behind, behind)) << "member " << i;
  }
}

INSTANTIATE_TEST_SUITE_P(PipelineProcessStages, EveryLoop,
                         ::testing::Values(Loop{5, 2, 3, 4}, Loop{5, 1, 1, 2}, Loop{6, 3, 4, 3},
                                           Loop{2, 3, 2, 2}, Loop{7, 4, 3, 3, true},
                                           Loop{3, 4, 2, 2, true},
                                           Loop{7, 4, 3, 3, true, false, true},
                                           Loop{7, 4, 2, 2, true, false, false, true}));

// A stop in the last round ends every process -- the relays included, which would otherwise wait
// for the rest of their plan -- and the rounds before it are complete. Length 3: member 3 (behind
// the relays) has no elements, so only member 2 sends the fan-in a stop.
class Stopped : public ::testing::TestWithParam<int> {};

TEST_P(Stopped, AStopEndsTheRelaysAndTheMembers) {
  const Loop s{GetParam(), 4, 3, 3, true, true};
  const LoopOutcome o = run_loop(s);
  EXPECT_TRUE(o.blocked.empty()) << "a process was left waiting";
  for (int r = 0; r + 1 < s.rounds; ++r)
    EXPECT_EQ(o.vectors[std::size_t(r)].size(), std::size_t(s.length));
  EXPECT_TRUE(o.vectors.back().empty());
}

INSTANTIATE_TEST_SUITE_P(PipelineProcessStages, Stopped, ::testing::Values(7, 3));

// On the m = 4 network L1 has links to E1 and E2 only: E3 and E4 are served by a fan-out on X and a
// fan-in on Y (high priority, as routers), and their channels go through them.
TEST(PipelineProcessStages, MembersWithoutALinkAreReachedThroughTheRelays) {
  const Loop s{7, 4, 3, 3, true};
  const network::Topology topology = loop_network(s);
  Builder b(topology);
  build_loop(b, s, nullptr);
  std::map<std::string, std::string> placed;
  for (const ProcessDecl& d : b.declared_processes()) {
    placed[d.name] = d.on.empty() ? "" : d.on.front();
    if (d.name.rfind("work_fan_", 0) == 0) {
      EXPECT_TRUE(d.high_priority) << d.name;
    }
  }
  for (const char* relay : {"work_fan_out", "work_fan_out_to2", "work_fan_out_to3"})
    EXPECT_EQ(placed[relay], "X") << relay;
  for (const char* relay : {"work_fan_in", "work_fan_in_from2", "work_fan_in_from3"})
    EXPECT_EQ(placed[relay], "Y") << relay;
  EXPECT_EQ(placed.count("work_fan_out_to0"), 0u);   // E1 is L1's neighbour
  EXPECT_EQ(placed.count("work_fan_in_from1"), 0u);  // E2 is L3's
  std::map<std::string, std::pair<std::string, std::string>> ends;
  for (const auto& c : b.declared_channels()) ends[c.name] = {c.writer, c.reader};
  EXPECT_EQ(ends["spread->work_fan_out[0][0]"],
            std::make_pair(std::string("spread"), std::string("work_fan_out")));
  EXPECT_EQ(ends["work_fan_out->work[0][3]"],
            std::make_pair(std::string("work_fan_out_to3"), std::string("work[3]")));
  EXPECT_EQ(ends["work->work_fan_in[2][0]"],
            std::make_pair(std::string("work[2]"), std::string("work_fan_in_from2")));
  EXPECT_EQ(ends["spread->work[0][0]"],
            std::make_pair(std::string("spread"), std::string("work[0]")));
}

TEST(PipelineProcessStages, AProcessStageIsNotBufferedByTheSkeleton) {
  auto body = [](Process&, const StageEnds<INT, INT>&) {};
  EXPECT_THROW(pipeline<INT>().process_stage<INT>("s", body).buffered(), std::logic_error);
  EXPECT_THROW(pipeline<INT>().process_group<INT>("g", 0, body), std::invalid_argument);
  RelayPlan<INT, INT> plan;
  EXPECT_THROW(pipeline<INT>().process_stage<INT>("s", body).relayed(plan), std::logic_error);
  RelayPlan<REAL64, INT> wrong;
  auto group = [](Process&, const StageEnds<INT, INT>&) {};
  EXPECT_THROW(pipeline<INT>().process_group<INT>("g", 2, group).relayed(wrong), std::logic_error);
}

}  // namespace

namespace {

using namespace t800sim;

std::map<std::string, std::pair<std::string, std::string>> channel_ends(const Builder& b) {
  std::map<std::string, std::pair<std::string, std::string>> ends;
  for (const auto& c : b.declared_channels()) ends[c.name] = {c.writer, c.reader};
  return ends;
}

// A member listed as direct is never behind a relay, even where it has no link to the stage next
// to it: member 0 on E3 (linked to X and Y only) gets channels of its own to spread and from
// gather, and the relays serve member 3 (E4) alone. (Member 2 is on E1, L1's and L3's neighbour.)
TEST(PipelineProcessStages, ADirectMemberIsNeverBehindARelay) {
  const Loop s{7, 4, 3, 3, true, false, true};
  const network::Topology topology = loop_network(s);
  Builder b(topology);
  build_loop(b, s, nullptr);
  std::map<std::string, std::vector<std::string>> on;
  std::map<std::string, std::string> placed;
  for (const ProcessDecl& d : b.declared_processes()) {
    on[d.name] = d.on;
    placed[d.name] = d.on.front();
  }
  EXPECT_EQ(on["work"], (std::vector<std::string>{"E3", "E2", "E1", "E4"}));
  EXPECT_EQ(placed.count("work_fan_out_to0"), 0u);
  EXPECT_EQ(placed.count("work_fan_in_from0"), 0u);
  EXPECT_EQ(placed["work_fan_out_to3"], "X");
  EXPECT_EQ(placed["work_fan_in_from3"], "Y");
  const auto ends = channel_ends(b);
  EXPECT_EQ(ends.at("spread->work[0][0]"),
            std::make_pair(std::string("spread"), std::string("work[0]")));
  EXPECT_EQ(ends.at("work->gather[0][0]"),
            std::make_pair(std::string("work[0]"), std::string("gather")));
  EXPECT_EQ(ends.count("work_fan_out->work[0][0]"), 0u);
  EXPECT_EQ(ends.count("work->work_fan_in[0][0]"), 0u);
}

// What a relay forwards is named by the plan's labels, else by the channel it goes out on. A fault
// on the first byte through X -> E4 hits the step's header, the first message E4 gets; on Y -> L3
// it hits element 2, the first message gather takes through Y (element j comes from member j mod 4;
// members 2 and 3 are behind Y). An element is Sequential<INT, INT, INT>: three communications of
// 4 bytes, the first hit (a part whose value the simulation carries with the last).
struct LabelCase {
  bool labelled;
  const char* from;
  const char* to;
  const char* message;
};

void PrintTo(const LabelCase& c, std::ostream* os) {
  *os << (c.labelled ? "labelled_" : "unlabelled_") << c.from << "_" << c.to;
}

class RelayLabels : public ::testing::TestWithParam<LabelCase> {};

TEST_P(RelayLabels, TheRelaysNameWhatTheyForwardAsThePlanSays) {
  const LabelCase c = GetParam();
  Loop s{7, 4, 2, 2, true};
  s.labelled = c.labelled;
  network::FaultSpec f;
  f.kind = network::FaultSpec::Kind::corrupt;
  f.from = c.from;
  f.to = c.to;
  std::vector<network::FaultRecord> records;
  run_loop(s, {f}, &records);
  ASSERT_EQ(records.size(), 1u);
  EXPECT_EQ(records[0].hit, std::string("byte 1 of 4 of message '") + c.message +
                                "' changed (its value is not modelled)");
}

INSTANTIATE_TEST_SUITE_P(
    PipelineProcessStages, RelayLabels,
    ::testing::Values(LabelCase{true, "X", "E4", "header"}, LabelCase{true, "Y", "L3", "element 2"},
                      LabelCase{false, "X", "E4", "work_fan_out->work[0][3]"},
                      LabelCase{false, "Y", "L3", "work_fan_in->gather[0][0]"}));

}  // namespace
