// Link processors for a group of processes a stage cannot reach directly. A T800 has four links and
// no hardware routing, so a stage that deals work to more processes than it has links reaches the
// rest through a transputer between them, running what an occam programmer of 1990 wrote for it:
//
//   PAR                                  -- a fan-out on the link processor X
//     SEQ r ...                          -- input: each message of the round, in the stage's
//       from ? m                         --   order, to the members it is for
//       SEQ e IN members.of.m            --   (several: a copy to each)
//         inner[e] ! m
//     PAR e = 0 FOR served               -- one output process per link, so the next message
//       SEQ r ...                        --   comes in while the last goes out
//         inner[e] ? m; to[e] ! m
//
// and the reverse, a fan-in, between the members and the stage after. The relays know the
// round's plan -- which messages go to which members, which come back from which -- so no routing
// header is needed: the bytes on the wire are the stage's own. A message `stops` says ends the
// relays (a failure or a finish): they pass it on to the members it is for and end. They run at
// high priority, as a router does, so forwarding never waits for a computation.
//
// The pipeline skeleton places them (t800sim/pipeline.hpp: PipelineDecl::relayed); a program may
// also declare them itself with declare_fan_out / declare_fan_in.
#pragma once

#include <algorithm>
#include <functional>
#include <string>
#include <vector>

#include "t800sim/channel.hpp"
#include "t800sim/process.hpp"
#include "t800sim/program.hpp"

namespace t800sim {

// Rounds served until a stop message ends them (RelayPlan::rounds, PipelineDecl::build).
inline constexpr int kUntilStop = -1;

// What the relays of one group know of its rounds.
template <class In_, class Out_>
struct RelayPlan {
  static constexpr int kUntilStop = t800sim::kUntilStop;
  std::string fan_out, fan_in;  // the link processors ("": that side needs none)
  // Round r's messages into the group, in the order the stage before sends them, each with the
  // members it is for.
  std::function<std::vector<std::vector<int>>(int round)> scatter;
  // Round r's messages out of the group, in the order the stage after takes them: each one's
  // member.
  std::function<std::vector<int>(int round)> gather;
  int rounds = kUntilStop;  // rounds served, or until a stop
  std::function<bool(const value_of<In_>&)> stops_in = [](const value_of<In_>&) { return false; };
  std::function<bool(const value_of<Out_>&)> stops_out = [](const value_of<Out_>&) {
    return false;
  };
  // A stop from a member: every other member with messages due in that round sends a stop in their
  // place; the fan-in takes them and ends. With this false it does not pass the stop on (the
  // stage after learns of it from a member it reaches directly).
  bool fan_in_passes_stop = true;
  // Members the relays never serve, on either side: joined to the neighbouring stages by channels
  // of their own (routed by the network where there is no link) -- a member whose messages the
  // plan's scatter / gather leave out, such as one that also sends the stage after something
  // outside the round's plan.
  std::vector<int> direct;
  // How traces and fault reports name message `index` of round r's scatter (label_in) or gather
  // (label_out) as a relay forwards it -- as its sender named it, say. Unset: the channel's name.
  std::function<std::string(const value_of<In_>&, int round, int index)> label_in;
  std::function<std::string(const value_of<Out_>&, int round, int index)> label_out;
};

namespace detail {

inline bool relay_more(int rounds, int r) {
  return rounds < 0 || r < rounds;
}
inline bool has(const std::vector<int>& members, int e) {
  return std::find(members.begin(), members.end(), e) != members.end();
}
inline std::size_t position(const std::vector<int>& served, int e) {
  return std::size_t(std::find(served.begin(), served.end(), e) - served.begin());
}
template <class Label, class V>
std::string relay_label(const Label& label, const V& m, int round, int index) {
  return label ? label(m, round, index) : std::string();
}

}  // namespace detail

// A fan-out named `name` on `processor`: takes the messages for the `served` members (group
// member indices, ascending) from `from` and gives member served[k] its own on to[k].
template <class In_, class Out_>
void declare_fan_out(Builder& b, const std::string& name, const std::string& processor,
                     const RelayPlan<In_, Out_>& plan, const std::vector<int>& served,
                     const std::string& from, const std::vector<std::string>& to) {
  using V = value_of<In_>;
  std::vector<Chan<In_>> inner;
  for (int e : served)
    inner.push_back(b.channel<In_>(name + ".inner[" + std::to_string(e) + "]", name,
                                   name + "_to" + std::to_string(e)));
  const In<In_> input = b.input<In_>(from, name);
  b.process(name,
            [plan, served, inner, input](Process& p) {
              for (int r = 0; detail::relay_more(plan.rounds, r); ++r) {
                const std::vector<std::vector<int>> messages = plan.scatter(r);
                for (std::size_t i = 0; i < messages.size(); ++i) {
                  std::vector<int> here;
                  for (int e : messages[i])
                    if (detail::has(served, e)) here.push_back(e);
                  if (here.empty()) continue;
                  const V m = p.in(input);
                  const std::string label = detail::relay_label(plan.label_in, m, r, int(i));
                  for (int e : here) p.out(inner[detail::position(served, e)].out(), m, label);
                  if (plan.stops_in(m)) return;
                }
              }
            })
      .placed_on(processor)
      .high();
  for (std::size_t k = 0; k < served.size(); ++k) {
    const int e = served[k];
    const std::string out_name = name + "_to" + std::to_string(e);
    const Out<In_> out = b.output<In_>(to[k], out_name);
    b.process(out_name,
              [plan, e, from_inner = inner[k].in(), out](Process& p) {
                for (int r = 0; detail::relay_more(plan.rounds, r); ++r) {
                  const std::vector<std::vector<int>> messages = plan.scatter(r);
                  for (std::size_t i = 0; i < messages.size(); ++i) {
                    if (!detail::has(messages[i], e)) continue;
                    const V m = p.in(from_inner);
                    p.out(out, m, detail::relay_label(plan.label_in, m, r, int(i)));
                    if (plan.stops_in(m)) return;
                  }
                }
              })
        .placed_on(processor)
        .high();
  }
}

// A fan-in named `name` on `processor`: member served[k]'s messages come in on from[k]; they go on
// to the stage after on `to`, in the order of the plan's gather.
template <class In_, class Out_>
void declare_fan_in(Builder& b, const std::string& name, const std::string& processor,
                    const RelayPlan<In_, Out_>& plan, const std::vector<int>& served,
                    const std::vector<std::string>& from, const std::string& to) {
  using V = value_of<Out_>;
  std::vector<Chan<Out_>> inner;
  for (int e : served)
    inner.push_back(b.channel<Out_>(name + ".inner[" + std::to_string(e) + "]",
                                    name + "_from" + std::to_string(e), name));
  for (std::size_t k = 0; k < served.size(); ++k) {
    const int e = served[k];
    const std::string in_name = name + "_from" + std::to_string(e);
    const In<Out_> in = b.input<Out_>(from[k], in_name);
    b.process(in_name,
              [plan, e, in, to_inner = inner[k].out()](Process& p) {
                for (int r = 0; detail::relay_more(plan.rounds, r); ++r) {
                  const std::vector<int> order = plan.gather(r);
                  for (std::size_t i = 0; i < order.size(); ++i) {
                    if (order[i] != e) continue;
                    const V m = p.in(in);
                    p.out(to_inner, m, detail::relay_label(plan.label_out, m, r, int(i)));
                    if (plan.stops_out(m)) return;
                  }
                }
              })
        .placed_on(processor)
        .high();
  }
  const Out<Out_> output = b.output<Out_>(to, name);
  b.process(name,
            [plan, served, inner, output](Process& p) {
              for (int r = 0; detail::relay_more(plan.rounds, r); ++r) {
                const std::vector<int> order = plan.gather(r);
                for (std::size_t i = 0; i < order.size(); ++i) {
                  const int source = order[i];
                  if (!detail::has(served, source)) continue;
                  const V m = p.in(inner[detail::position(served, source)].in());
                  const std::string label = detail::relay_label(plan.label_out, m, r, int(i));
                  if (!plan.stops_out(m)) {
                    p.out(output, m, label);
                    continue;
                  }
                  // Every other member with messages in this round sends one stop in their place.
                  for (int e : served)
                    if (e != source && detail::has(order, e))
                      p.in(inner[detail::position(served, e)].in());
                  if (plan.fan_in_passes_stop) p.out(output, m, label);
                  return;
                }
              }
            })
      .placed_on(processor)
      .high();
}

}  // namespace t800sim
