// A pipeline skeleton: stages in order, each a process (or a group of processes) on a processor,
// joined by typed channels, served in rounds: a client feeds an item per round into the first
// stage and takes the round's result from the last. Each stage's function turns one item into the
// next stage's item; the skeleton writes the processes and channels an occam programmer would:
//
//   SEQ r = 0 FOR rounds             -- a stage, unbuffered: takes, works, gives
//     in ? x; y := f(x); out ! y
//
//   PAR                              -- buffered: input, worker, output joined by one-item
//     SEQ r ... in ? x; take ! x     -- buffers (internal channels), so the next item comes in
//     SEQ r ... take ? x; give ! f(x)  -- and the last goes out while one is worked on
//     SEQ r ... give ? y; out ! y
//
// A group of k processes (a parallel stage, like the elimination's level 2) is dealt the rounds
// round-robin: member i works on rounds i, i + k, ...; the stages before and after it send to and
// take from the member whose round it is, so items stay in order.
//
// A stage whose rounds are not one item in, one item out -- a stage that takes several items per
// round, sends a round's items to chosen members of a group, or talks to a stage further on -- is
// written as a process: process_stage / process_group give the body its ends (StageEnds: a channel
// from every member of the stage before, one to every member of the stage after) and the body
// serves its rounds itself, as an occam programmer would write that process. A channel back to an
// earlier stage (a loop, like the elimination's reduced matrix returning to level 1) is an ordinary
// channel the program declares between the two processes by their names (Builder::channel).
// Process stages may serve until a stop (build(..., kUntilStop): each body ends on the message it
// recognises as one) and the last may keep its results (no collector), as the elimination's levels
// serve a trajectory's solves, or keep Table 6's q̈ on level 4.
//
//   const auto pipe = t800sim::pipeline<REAL64>()
//       .stage<REAL64>("square", [](Process& p, double x) { p.compute(500); return x * x; })
//       .on("P1")
//       .group<INT>("round", 2, [](Process& p, double x) { p.compute(900); return INT(x); })
//       .on({"P2", "P3"}).buffered()
//       .build(b, "client", "client", rounds);
//   b.process("client", [pipe, rounds](Process& p) {
//     for (int r = 0; r < rounds; ++r) {     // one item in flight; a feeder and a collector in
//       p.out(pipe.in(r), 1.5 * r);          // PAR keep every stage busy
//       INT y = p.in(pipe.out(r));
//     }
//   });
#pragma once

#include <algorithm>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <typeinfo>
#include <utility>
#include <vector>

#include "t800sim/channel.hpp"
#include "t800sim/kernel.hpp"
#include "t800sim/process.hpp"
#include "t800sim/program.hpp"
#include "t800sim/relay.hpp"

namespace t800sim {

namespace detail {

// Where a stage sits: the stage before it (or the feeder) and after it (or the collector), their
// sizes, the rounds. Channels are named after the stages they join.
struct StageWiring {
  std::string before, after;
  int before_count = 1, after_count = 1;
  int rounds = 0;
  // A process stage on either side of a boundary may talk to any member of the other: every pair
  // is joined. Otherwise member i is joined to the members that share one of its rounds.
  bool all_before = false, all_after = false;
  // Members reached through link processors (PipelineDecl::relayed): this stage's behind its own
  // fan-out / fan-in, the stage after's behind its fan-out, the stage before's behind its fan-in.
  std::vector<bool> via_fan_out, via_fan_in, after_via_fan_out, before_via_fan_in;
};

// A declared stage, its types erased: declares its processes and its ends of the channels.
struct StageSpec {
  std::string name;
  int count = 1;
  bool group = false;
  bool buffered = false;
  bool process = false;  // written as a process (process_stage / process_group)
  std::vector<std::string> on;
  std::vector<Kernel> code;
  std::function<void(Builder&, const StageSpec&, const StageWiring&)> declare;
  // Link processors (relayed): their processor names, and their declaration, typed.
  const std::type_info* input = nullptr;  // the protocols in and out, for relayed()'s check
  const std::type_info* output = nullptr;
  std::string fan_out, fan_in;
  std::vector<int> direct;  // members never behind them (RelayPlan::direct)
  std::function<void(Builder&, const StageSpec&, const StageWiring&)> declare_relays;
};

// The channel into member i of `stage` from member j of the stage before, and out of member i to
// member j of the stage after: direct, or through a link processor's relay.
std::string in_channel(const StageWiring& w, const std::string& stage, int j, int i);
std::string out_channel(const StageWiring& w, const std::string& stage, int i, int j);
std::string fan_out_name(const std::string& stage);
std::string fan_in_name(const std::string& stage);
// Which members of a stage on `members` (one per member) a stage on `neighbour` reaches only
// through `relay`: no link to it, and the relay linked to both. Throws std::logic_error when a
// processor is not in the network.
std::vector<bool> behind(const Network& network, const std::string& neighbour,
                         const std::string& relay, const std::vector<std::string>& members);

// A member's process name: name[i] in a group, name for one process.
std::string member(const std::string& name, bool group, int i);
// The channel between `from` (member j) and `to` (member i) of neighbouring stages.
std::string link_name(const std::string& from, const std::string& to, int j, int i);
// Member i of a stage of `count` talks to the members of a neighbour of `other` that share one of
// its rounds: round r is on member r % count here and r % other there.
std::vector<int> partners(int i, int count, int other, int rounds);
// Member i's partners across one boundary: every member of the other side, or partners().
std::vector<int> joined(bool all, int i, int count, int other, int rounds);
// A stage's processes: a group name[0..count-1], or one process `name`.
ProcessDecl& members(Builder& b, const std::string& name, int count, bool group,
                     Process::IndexedBody body);

// Member i's internal channel from process `from` to `to` of the same stage.
template <class P>
Chan<P> internal(Builder& b, const std::string& name, const std::string& from,
                 const std::string& to, bool group, int i) {
  return b.channel<P>(name + "[" + std::to_string(i) + "]", member(from, group, i),
                      member(to, group, i));
}

// Both ends' channels of member i, indexed by the neighbour's member (unused ones stay empty).
template <class P>
std::vector<In<P>> inputs_of(Builder& b, const StageWiring& w, const std::string& stage,
                             const std::string& process, bool group, int i, int count) {
  std::vector<In<P>> in(std::size_t(w.before_count));
  for (int j : joined(w.all_before, i, count, w.before_count, w.rounds))
    in[std::size_t(j)] = b.input<P>(in_channel(w, stage, j, i), member(process, group, i));
  return in;
}
template <class P>
std::vector<Out<P>> outputs_of(Builder& b, const StageWiring& w, const std::string& stage,
                               const std::string& process, bool group, int i, int count) {
  std::vector<Out<P>> out(std::size_t(w.after_count));
  for (int j : joined(w.all_after, i, count, w.after_count, w.rounds))
    out[std::size_t(j)] = b.output<P>(out_channel(w, stage, i, j), member(process, group, i));
  return out;
}

}  // namespace detail

// What a process stage's body is given: its member index (0 for a stage of one process), the
// rounds it serves (kUntilStop: until a message it recognises as a stop), and its channels:
// from[j] from member j of the stage before (the feeder: one), to[j] to member j of the stage
// after (the collector: one; none when the pipeline has no collector).
template <class In_, class Out_>
struct StageEnds {
  int member = 0;
  int rounds = 0;
  std::vector<In<In_>> from;
  std::vector<Out<Out_>> to;
  // A member of a relayed group (PipelineDecl::relayed): whether its channel from the stage before
  // comes through the fan-out, and its channel to the stage after goes through the fan-in (a
  // member behind the fan-in tells it of a stop, which it waits for; one with a channel of its own
  // may not need to).
  bool behind_fan_out = false, behind_fan_in = false;

  // Whether round r is one the stage serves: SEQ r = 0 FOR rounds, or WHILE not stopped.
  bool more(int r) const { return rounds == kUntilStop || r < rounds; }

  // A channel and the members of the neighbouring stage it joins this one to: one each, or the
  // members behind one relay (relayed), which share it -- a message for several of them is sent
  // once on it, the relay copies it.
  template <class End>
  struct Port {
    End channel;
    std::vector<int> members;
  };
  std::vector<Port<Out<Out_>>> to_ports() const { return ports(to); }
  std::vector<Port<In<In_>>> from_ports() const { return ports(from); }

 private:
  template <class End>
  static std::vector<Port<End>> ports(const std::vector<End>& ends) {
    std::vector<Port<End>> out;
    for (std::size_t j = 0; j < ends.size(); ++j) {
      if (!ends[j].slot()) continue;
      auto same = std::find_if(out.begin(), out.end(), [&](const Port<End>& p) {
        return p.channel.slot() == ends[j].slot();
      });
      if (same == out.end()) same = out.insert(out.end(), Port<End>{ends[j], {}});
      same->members.push_back(int(j));
    }
    return out;
  }
};

// The client's ends of a built pipeline: in(r) takes round r's item, out(r) gives its result (the
// member of the first / last stage whose round r is; of a process group, member r mod count).
template <class In_, class Out_>
class Pipeline {
 public:
  const Out<In_>& in(int round) const { return entry_.at(std::size_t(round) % entry_.size()); }
  const In<Out_>& out(int round) const {
    if (exit_.empty()) throw std::logic_error("pipeline: built without a collector, no out()");
    return exit_.at(std::size_t(round) % exit_.size());
  }

  std::vector<Out<In_>> entry_;  // one per member of the first stage
  std::vector<In<Out_>> exit_;   // one per member of the last
};

// A pipeline as it is declared: items enter as First; the stages so far give Last.
template <class First, class Last>
class PipelineDecl {
 public:
  PipelineDecl() = default;
  explicit PipelineDecl(std::vector<detail::StageSpec> stages) : stages_(std::move(stages)) {}

  // A stage of one process: f(process, item) -> the next stage's item.
  template <class Next, class F>
  PipelineDecl<First, Next> stage(const std::string& name, F f) && {
    return std::move(*this).template add<Next>(name, 1, false, std::move(f));
  }
  // A parallel stage of `count` processes, name[0..count-1], dealt the rounds round-robin.
  template <class Next, class F>
  PipelineDecl<First, Next> group(const std::string& name, int count, F f) && {
    check_count(name, count);
    return std::move(*this).template add<Next>(name, count, true, std::move(f));
  }
  // A stage written as a process: body(process, ends) serves every round; `Next` is the protocol
  // of what it sends on. The stages next to it are joined to it by every pair of members.
  template <class Next, class Body>
  PipelineDecl<First, Next> process_stage(const std::string& name, Body body) && {
    return std::move(*this).template add_process<Next>(name, 1, false, std::move(body));
  }
  // A group of `count` processes name[0..count-1] written as processes: body(process, ends) with
  // ends.member the member's index; which member gets which item is the bodies' business.
  template <class Next, class Body>
  PipelineDecl<First, Next> process_group(const std::string& name, int count, Body body) && {
    check_count(name, count);
    return std::move(*this).template add_process<Next>(name, count, true, std::move(body));
  }
  // The last stage (a process group) reaches the stage before through the link processor
  // plan.fan_out and the stage after through plan.fan_in where it has no link of its own to them
  // (t800sim/relay.hpp): which members go through them follows from the stages' processors (on(),
  // which the neighbours need too) and the network's links. The bodies are unchanged: a member's
  // ends are the relay's channels, and members behind one relay share the neighbour's channel to
  // it -- the neighbour sends each message once on it, in the plan's order.
  template <class In_>
  PipelineDecl relayed(RelayPlan<In_, Last> plan) && {
    detail::StageSpec& s = last();
    if (!s.process || !s.group)
      throw std::logic_error("pipeline stage " + s.name + ": only a process group is relayed");
    if (*s.input != typeid(value_of<In_>))
      throw std::logic_error("pipeline stage " + s.name +
                             ": the relay plan's input protocol is not the stage's");
    s.fan_out = plan.fan_out;
    s.fan_in = plan.fan_in;
    s.direct = plan.direct;
    s.declare_relays = [plan](Builder& b, const detail::StageSpec& stage,
                              const detail::StageWiring& w) {
      std::vector<int> out_served, in_served;
      std::vector<std::string> to, from;
      for (int e = 0; e < stage.count; ++e) {
        if (w.via_fan_out[std::size_t(e)]) {
          out_served.push_back(e);
          to.push_back(detail::in_channel(w, stage.name, 0, e));
        }
        if (w.via_fan_in[std::size_t(e)]) {
          in_served.push_back(e);
          from.push_back(detail::out_channel(w, stage.name, e, 0));
        }
      }
      const std::string fo = detail::fan_out_name(stage.name), fi = detail::fan_in_name(stage.name);
      if (!out_served.empty())
        declare_fan_out(b, fo, plan.fan_out, plan, out_served,
                        detail::link_name(w.before, fo, 0, 0), to);
      if (!in_served.empty())
        declare_fan_in(b, fi, plan.fan_in, plan, in_served, from,
                       detail::link_name(fi, w.after, 0, 0));
    };
    return std::move(*this);
  }
  // The last stage's processors: one, or one per member of a group (a scene's [placement]
  // overrides them by the processes' names).
  PipelineDecl on(std::vector<std::string> processors) && {
    last().on = std::move(processors);
    return std::move(*this);
  }
  PipelineDecl on(const std::string& processor) && {
    return std::move(*this).on(std::vector<std::string>{processor});
  }
  // The last stage as input, worker and output processes in PAR, joined by one-item buffers:
  // name_input, name, name_output, on the same processor.
  PipelineDecl buffered() && {
    if (last().process)
      throw std::logic_error("pipeline stage " + last().name +
                             ": a process stage buffers as its body does, not by buffered()");
    last().buffered = true;
    return std::move(*this);
  }
  // A kernel the last stage's worker runs, counted in its processor's memory (Builder::code).
  PipelineDecl code(const Kernel& kernel) && {
    last().code.push_back(kernel);
    return std::move(*this);
  }

  // Declares every stage's processes and channels: `feeder` sends round r's item into the first
  // stage, `collector` takes its result from the last (both names of processes the program
  // declares; they may be one, and may be processes the simulator's caller spawns, declared
  // without a body). Every stage serves `rounds` items and ends. Pipelines of process stages only
  // may also serve until a stop (kUntilStop: each body ends on the message it recognises as one)
  // and may have no collector ("": the last stage keeps its results; StageEnds::to is empty).
  Pipeline<First, Last> build(Builder& b, const std::string& feeder, const std::string& collector,
                              int rounds) const {
    if (stages_.empty()) throw std::invalid_argument("a pipeline needs at least one stage");
    if (rounds < 0 && rounds != kUntilStop)
      throw std::invalid_argument("a pipeline serves zero or more rounds, or kUntilStop");
    for (const detail::StageSpec& s : stages_)
      if (!s.process && rounds == kUntilStop)
        throw std::invalid_argument("pipeline stage " + s.name +
                                    ": serves a number of rounds; only process stages serve "
                                    "until a stop (kUntilStop)");
    if (collector.empty() && !stages_.back().process)
      throw std::invalid_argument("pipeline stage " + stages_.back().name +
                                  ": gives every result to the collector; only a process stage "
                                  "ends a pipeline without one");
    std::vector<std::vector<bool>> via_out, via_in;
    for (std::size_t s = 0; s < stages_.size(); ++s) {
      via_out.push_back(behind(b, s, -1, stages_[s].fan_out));
      via_in.push_back(behind(b, s, +1, stages_[s].fan_in));
    }
    std::vector<detail::StageWiring> wiring;
    for (std::size_t s = 0; s < stages_.size(); ++s) {
      detail::StageWiring w;
      w.via_fan_out = via_out[s];
      w.via_fan_in = via_in[s];
      w.before_via_fan_in = s == 0 ? std::vector<bool>(1, false) : via_in[s - 1];
      w.after_via_fan_out = s + 1 == stages_.size() ? std::vector<bool>(1, false) : via_out[s + 1];
      w.rounds = rounds;
      w.before = s == 0 ? feeder : stages_[s - 1].name;
      w.before_count = s == 0 ? 1 : stages_[s - 1].count;
      const bool last_stage = s + 1 == stages_.size();
      w.after = last_stage ? collector : stages_[s + 1].name;
      w.after_count = !last_stage ? stages_[s + 1].count : collector.empty() ? 0 : 1;
      w.all_before = stages_[s].process || (s > 0 && stages_[s - 1].process);
      w.all_after = stages_[s].process || (!last_stage && stages_[s + 1].process);
      stages_[s].declare(b, stages_[s], w);
      wiring.push_back(w);
    }
    for (std::size_t s = 0; s < stages_.size(); ++s)
      if (stages_[s].declare_relays) stages_[s].declare_relays(b, stages_[s], wiring[s]);
    Pipeline<First, Last> ends;
    const detail::StageSpec &head = stages_.front(), &tail = stages_.back();
    // Members beyond the rounds' number take nothing: no channel to them (a process group's
    // members are all joined: its body deals the rounds).
    const int entries = head.process ? head.count : std::min(head.count, rounds);
    const int exits = collector.empty() ? 0
                      : tail.process    ? tail.count
                                        : std::min(tail.count, rounds);
    for (int i = 0; i < entries; ++i)
      ends.entry_.push_back(b.output<First>(detail::link_name(feeder, head.name, 0, i), feeder));
    for (int i = 0; i < exits; ++i)
      ends.exit_.push_back(b.input<Last>(detail::link_name(tail.name, collector, i, 0), collector));
    return ends;
  }

 private:
  template <class, class>
  friend class PipelineDecl;

  detail::StageSpec& last() {
    if (stages_.empty()) throw std::logic_error("a pipeline's settings follow a stage");
    return stages_.back();
  }

  // Stage s's members behind its relay on the side `side` (-1: before, +1: after); all false when
  // it has none there.
  std::vector<bool> behind(Builder& b, std::size_t s, int side, const std::string& relay) const {
    const detail::StageSpec& stage = stages_[s];
    if (relay.empty()) return std::vector<bool>(std::size_t(stage.count), false);
    const bool edge = side < 0 ? s == 0 : s + 1 == stages_.size();
    const detail::StageSpec* neighbour = edge ? nullptr : &stages_[std::size_t(int(s) + side)];
    if (!neighbour || neighbour->count != 1 || neighbour->on.empty() ||
        stage.on.size() != std::size_t(stage.count))
      throw std::logic_error("pipeline stage " + stage.name + ": a relay through " + relay +
                             " needs a stage of one process " + (side < 0 ? "before" : "after") +
                             " it, and on() for both (one processor per member)");
    std::vector<bool> out = detail::behind(b.network(), neighbour->on.front(), relay, stage.on);
    for (int e : stage.direct)
      if (e >= 0 && e < stage.count) out[std::size_t(e)] = false;
    return out;
  }

  static void check_count(const std::string& name, int count) {
    if (count < 1)
      throw std::invalid_argument("pipeline stage " + name +
                                  ": a group needs at least one process");
  }

  template <class Next, class Body>
  PipelineDecl<First, Next> add_process(const std::string& name, int count, bool group,
                                        Body body) && {
    detail::StageSpec spec;
    spec.name = name;
    spec.count = count;
    spec.group = group;
    spec.process = true;
    spec.input = &typeid(value_of<Last>);
    spec.output = &typeid(value_of<Next>);
    using Ends = StageEnds<Last, Next>;
    using Work = std::function<void(Process&, const Ends&)>;
    spec.declare = [work = Work(std::move(body))](Builder& b, const detail::StageSpec& s,
                                                  const detail::StageWiring& w) {
      std::vector<Ends> ends(std::size_t(s.count));
      for (int i = 0; i < s.count; ++i) {
        Ends& e = ends[std::size_t(i)];
        e.member = i;
        e.rounds = w.rounds;
        e.from = detail::inputs_of<Last>(b, w, s.name, s.name, s.group, i, s.count);
        e.to = detail::outputs_of<Next>(b, w, s.name, s.name, s.group, i, s.count);
        e.behind_fan_out = w.via_fan_out[std::size_t(i)];
        e.behind_fan_in = w.via_fan_in[std::size_t(i)];
        for (const Kernel& k : s.code) b.code(detail::member(s.name, s.group, i), k);
      }
      ProcessDecl& d = detail::members(b, s.name, s.count, s.group,
                                       [=](Process& p, int i) { work(p, ends[std::size_t(i)]); });
      if (!s.on.empty()) d.placed_on(s.on);
    };
    stages_.push_back(std::move(spec));
    return PipelineDecl<First, Next>(std::move(stages_));
  }

  template <class Next, class F>
  PipelineDecl<First, Next> add(const std::string& name, int count, bool group, F f) && {
    detail::StageSpec spec;
    spec.name = name;
    spec.count = count;
    spec.group = group;
    using Work = std::function<value_of<Next>(Process&, const value_of<Last>&)>;
    spec.declare = [work = Work(std::move(f))](Builder& b, const detail::StageSpec& s,
                                               const detail::StageWiring& w) {
      declare_stage<Last, Next>(b, s, w, work);
    };
    stages_.push_back(std::move(spec));
    return PipelineDecl<First, Next>(std::move(stages_));
  }

  template <class In_, class Out_, class Work>
  static void declare_stage(Builder& b, const detail::StageSpec& s, const detail::StageWiring& w,
                            const Work& work) {
    auto placed = [&](ProcessDecl& d) {
      if (!s.on.empty()) d.placed_on(s.on);
    };
    std::vector<std::vector<In<In_>>> in;
    std::vector<std::vector<Out<Out_>>> out;
    for (int i = 0; i < s.count; ++i) {
      const std::string end = s.buffered ? s.name + "_input" : s.name;
      const std::string start = s.buffered ? s.name + "_output" : s.name;
      in.push_back(detail::inputs_of<In_>(b, w, s.name, end, s.group, i, s.count));
      out.push_back(detail::outputs_of<Out_>(b, w, s.name, start, s.group, i, s.count));
    }
    // Member i's rounds: i, i + count, ...; round r comes from the member of the stage before
    // whose round it is, and goes to the one after.
    const auto rounds_of = [count = s.count, rounds = w.rounds, bc = w.before_count,
                            ac = w.after_count](int i, auto each) {
      for (int r = i; r < rounds; r += count) each(r, std::size_t(r % bc), std::size_t(r % ac));
    };
    for (int i = 0; i < s.count; ++i)
      for (const Kernel& k : s.code) b.code(detail::member(s.name, s.group, i), k);
    const auto stage = [&](const std::string& name, Process::IndexedBody body) {
      placed(detail::members(b, name, s.count, s.group, std::move(body)));
    };
    if (!s.buffered) {
      stage(s.name, [=](Process& p, int i) {
        rounds_of(i, [&](int, std::size_t from, std::size_t to) {
          p.out(out[std::size_t(i)][to], work(p, p.in(in[std::size_t(i)][from])));
        });
      });
      return;
    }
    std::vector<Chan<In_>> take;
    std::vector<Chan<Out_>> give;
    for (int i = 0; i < s.count; ++i) {
      take.push_back(
          detail::internal<In_>(b, s.name + ".take", s.name + "_input", s.name, s.group, i));
      give.push_back(
          detail::internal<Out_>(b, s.name + ".give", s.name, s.name + "_output", s.group, i));
    }
    stage(s.name + "_input", [=](Process& p, int i) {
      rounds_of(i, [&](int, std::size_t from, std::size_t) {
        p.out(take[std::size_t(i)], p.in(in[std::size_t(i)][from]));
      });
    });
    stage(s.name, [=](Process& p, int i) {
      rounds_of(i, [&](int, std::size_t, std::size_t) {
        p.out(give[std::size_t(i)], work(p, p.in(take[std::size_t(i)])));
      });
    });
    stage(s.name + "_output", [=](Process& p, int i) {
      rounds_of(i, [&](int, std::size_t, std::size_t to) {
        p.out(out[std::size_t(i)][to], p.in(give[std::size_t(i)]));
      });
    });
  }

  std::vector<detail::StageSpec> stages_;
};

// A pipeline whose items enter as protocol First (no stages yet).
template <class First>
PipelineDecl<First, First> pipeline() {
  return {};
}

}  // namespace t800sim
