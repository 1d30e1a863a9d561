#include "workloads/pipeline/pipeline_program.hpp"

#include <functional>
#include <memory>
#include <numeric>
#include <stdexcept>
#include <tuple>
#include <type_traits>

#include "sdk/realise.hpp"
#include "t800/link_timing.hpp"
#include "t800sim/pipeline.hpp"
#include "workloads/pipeline/levels/level1.hpp"
#include "workloads/pipeline/levels/level2.hpp"
#include "workloads/pipeline/levels/level3.hpp"
#include "workloads/pipeline/levels/level4.hpp"
#include "workloads/setting_error.hpp"

namespace workloads {

namespace {

using elimination::Rows;
using t800sim::Process;

int require_node(const network::Topology& t, const std::string& name, const std::string& role) {
  const int index = t.find(name);
  if (index < 0)
    throw SettingError({kNetworkKey}, "elimination: the topology " + t.name + " has no processor " +
                                          name + " (" + role +
                                          "); use configs/topologies/elimination-m<m>.toml");
  return index;
}

}  // namespace

int level2_count(const network::Topology& t) {
  int m = 0;
  while (t.find(PipelineNodes::level2_name(m)) >= 0) ++m;
  return m;
}

PipelineNodes find_pipeline_nodes(const network::Topology& t, int m) {
  PipelineNodes nodes;
  nodes.l1 = require_node(t, PipelineNodes::kLevel1, "level 1");
  nodes.l3 = require_node(t, PipelineNodes::kLevel3, "level 3");
  nodes.l4 = require_node(t, PipelineNodes::kLevel4, "level 4");
  for (int e = 0; e < m; ++e)
    nodes.e.push_back(require_node(t, PipelineNodes::level2_name(e), "a level-2 processor"));
  return nodes;
}

// The pipeline's processes (levels/level1.hpp .. level4.hpp, one object per process, each owning
// its state), declared through the SDK's pipeline skeleton (t800sim/pipeline.hpp) -- L1, L3 and L4
// process stages, level 2 a process group reached through the link processors X and Y where L1 or
// L3 has no link to it, the loop L3 -> L1 a channel of the program -- the report they write, and
// the client's side.
template <class T>
class PipelineProgram<T>::Levels {
  using M = levels::Messages<T>;
  using C = typename M::C;
  using System = typename M::System;
  using Packet = typename M::Packet;
  using SdkProcess = t800sim::Process;
  static constexpr const char* kClient = "client";

 public:
  Levels(const PipelineSettings& s, const PipelineNodes& n, int unknowns)
      : settings(s), shape{unknowns, s.m}, nodes(n) {}

  void build(network::Machine& machine, int client, Serve serve) {
    serve_ = serve;
    if (settings.overlap && serve != Serve::once)
      throw std::invalid_argument("elimination pipeline: overlap serves one system only");
    if (settings.recovery && serve != Serve::once)
      throw std::invalid_argument("elimination pipeline: recovery serves one system only");
    const levels::Context<T> context{settings, shape, nodes, report_, pieces_, serve};
    // Recovery: a message that has started arrives within twice the longest message's time on a
    // link, and 10 us.
    const t800::LinkTiming link(machine.options().link);
    typename M::CheckedRow longest;
    longest.values.resize(std::size_t(n() + 2));
    const std::int64_t longest_bytes =
        t800sim::protocol<typename M::Checked>::bytes(M::to_checked(longest));
    const double longest_message_us = 2 * link.arrival_ns(longest_bytes) / 1000 + 10;
    level1_ = std::make_unique<levels::Level1<T>>(context);
    for (int e = 0; e < shape.m; ++e)
      level2_.push_back(std::make_unique<levels::Level2<T>>(context, e));
    level3_ = std::make_unique<levels::Level3<T>>(context, longest_message_us);
    level4_ = std::make_unique<levels::Level4<T>>(context);
    builder_ = std::make_unique<t800sim::Builder>(machine.topology());
    builder_->attach(machine);
    // The client is the caller's process, spawned by it: declared so the channels reach it.
    t800sim::ProcessDecl& c = builder_->process(kClient, nullptr);
    if (client == network::Machine::kHost)
      c.placed_on_host();
    else
      c.placed_on(machine.node_name(client));
    // Recovery's messages carry checksums on the same boundaries (Messages::Checked).
    if (settings.recovery)
      declare<typename M::Checked>(*builder_);
    else
      declare<Packet>(*builder_);
    t800sim::detail::realise("elimination pipeline", *builder_, machine, {});
    declare_code(machine);
  }

  // The levels as the skeleton's stages, each a process on its processor: Msg is the protocol
  // between L1, level 2 and L3 (and on the loop back to L1). Until finish, the levels serve until
  // the client's finish (a stop) passes through them and q̈ goes back to the client; once, they
  // serve one system and q̈ stays on L4.
  template <class Msg>
  void declare(t800sim::Builder& b) {
    const int rounds = serve_ == Serve::once ? 1 : t800sim::kUntilStop;
    const t800sim::Chan<Msg> back = b.channel<Msg>("level3->level1", "level3", "level1");
    std::vector<std::string> level2_on;
    for (int e = 0; e < shape.m; ++e) level2_on.push_back(PipelineNodes::level2_name(e));
    auto front =
        t800sim::pipeline<System>()
            .template process_stage<Msg>(
                "level1",
                [this, back](SdkProcess& p, const t800sim::StageEnds<System, Msg>& e) {
                  level1_->attach(levels::Ends::of(e, back.in().slot()));
                  levels::loop(e.rounds, p, [this](SdkProcess& q) { return level1_->round(q); });
                })
            .on(PipelineNodes::kLevel1)
            .template process_group<Msg>(
                "level2", shape.m,
                [this](SdkProcess& p, const t800sim::StageEnds<Msg, Msg>& e) {
                  levels::Level2<T>& level = *level2_[std::size_t(e.member)];
                  level.attach(levels::Ends::of(e));
                  if (settings.recovery) return level.checked(p);
                  levels::loop(e.rounds, p, [&level](SdkProcess& q) { return level.round(q); });
                })
            .on(level2_on);
    if constexpr (std::is_same_v<Msg, Packet>) {
      const t800sim::RelayPlan<Packet, Packet> plan = relay_plan(b.network());
      if (!plan.fan_out.empty() || !plan.fan_in.empty()) front = std::move(front).relayed(plan);
    }
    pipe_ =
        std::move(front)
            .template process_stage<Packet>(
                "level3",
                [this, back](SdkProcess& p, const t800sim::StageEnds<Msg, Packet>& e) {
                  level3_->attach(levels::Ends::of(e, back.out().slot()));
                  if (settings.recovery) return void(level3_->checked(p));
                  levels::loop(e.rounds, p, [this](SdkProcess& q) { return level3_->round(q); });
                })
            .on(PipelineNodes::kLevel3)
            .template process_stage<Packet>(
                "level4",
                [this](SdkProcess& p, const t800sim::StageEnds<Packet, Packet>& e) {
                  level4_->attach(levels::Ends::of(e));
                  levels::loop(e.rounds, p, [this](SdkProcess& q) { return level4_->round(q); });
                })
            .on(PipelineNodes::kLevel4)
            .build(b, kClient, serve_ == Serve::until_finish ? kClient : "", rounds);
  }

  // The link processors X (between L1 and the level-2 processors it has no link to) and Y
  // (between those and L3), where the topology has them. A relay round is one step k: the pivot
  // row to every level-2 processor that takes part, then rows 1 .. n-1-k each to its owner; back,
  // the rows in order from their owners. E1 forwards each pivot row to L3 outside that plan, so it
  // always has channels of its own; a failure a processor behind Y reports ends Y, and E1 tells L3.
  // Serving once, the relays serve the n steps of one system; until finish, until a stop.
  t800sim::RelayPlan<Packet, Packet> relay_plan(const t800sim::Network& network) const {
    t800sim::RelayPlan<Packet, Packet> plan;
    plan.fan_out = network.find("X") >= 0 ? "X" : "";
    plan.fan_in = network.find("Y") >= 0 ? "Y" : "";
    const PipelineShape s = shape;
    plan.rounds = serve_ == Serve::once ? s.n : t800sim::kUntilStop;
    plan.scatter = [s](int r) {
      const int k = r % s.n;
      std::vector<int> all(static_cast<std::size_t>(s.m));
      std::iota(all.begin(), all.end(), 0);
      std::vector<std::vector<int>> messages{s.takers(all, k)};
      for (int i = 1; i <= s.n - 1 - k; ++i) messages.push_back({s.owner(std::size_t(i))});
      return messages;
    };
    plan.gather = [s](int r) {
      std::vector<int> owners;
      for (int i = 1; i <= s.n - 1 - r % s.n; ++i) owners.push_back(s.owner(std::size_t(i)));
      return owners;
    };
    plan.stops_in = [](const typename M::PacketValue& m) {
      return (std::get<0>(m) & levels::header::kStop) != 0;
    };
    plan.stops_out = plan.stops_in;
    plan.fan_in_passes_stop = false;
    plan.direct = {0};
    plan.label_in = [stops = plan.stops_in](const typename M::PacketValue& m, int, int index) {
      return std::string(stops(m) ? levels::kFailLabel : index == 0 ? "pivot row" : "row");
    };
    plan.label_out = [stops = plan.stops_in](const typename M::PacketValue& m, int, int) {
      return std::string(stops(m) ? levels::kFailLabel : "row");
    };
    return plan;
  }

  // Each level's code, for the footprints of its processors: its pieces recorded on a
  // representative system of this size (diagonally dominant: no interchange), as the levels run
  // them.
  void declare_code(network::Machine& machine) {
    elimination::LinearSystem<C> s;
    for (int i = 0; i < n(); ++i) {
      s.a.emplace_back(std::size_t(n()), C(1));
      s.a.back()[std::size_t(i)] = C(T(n() + 1));
      s.b.push_back(C(1));
    }
    const auto& rule = settings.rule;
    auto declare = [&](int node, const std::string& process, const t800::ComputeWork& work) {
      machine.declare_code(node, process, work.code);
    };
    auto [m, augment] = pieces_.run(
        "augment", [](auto& a, auto& b) { return elimination::augment(a, b); }, named("A", s.a),
        named("b", s.b));
    declare(nodes.l1, "level1", augment);
    C scale(0);
    if (rule.needs_scale()) {
      auto [value, cost] = pieces_.run(
          "scale", [](auto& a) { return elimination::matrix_scale(a); }, named("m", m));
      scale = value;
      declare(nodes.l1, "level1", cost);
    }
    auto [limit, limit_cost] = pieces_.run(
        "limit", [&](auto& x) { return elimination::pivot_limit(x, rule); }, named("scale", scale));
    declare(nodes.l1, "level1", limit_cost);
    std::vector<int> order(static_cast<std::size_t>(n()));
    std::iota(order.begin(), order.end(), 0);
    auto [step, pivot] = pieces_.run(
        "pivot",
        [&](auto& rows, auto& o, auto& l) { return elimination::pivot_step(rows, o, rule, l); },
        named("m", m), named("order", order), named("limit", limit));
    declare(nodes.l1, "level1", pivot);
    // One unknown (a 1x1 system) has no row below the pivot: level 2 eliminates nothing and L3
    // checks no rows.
    Rows<C> rows;
    if (n() > 1) {
      auto [row, eliminate] = pieces_.run(
          "eliminate", [](auto& r, auto& j1) { return elimination::eliminate(r, j1); },
          named("row", m[1]), named("pivot", step.normalised));
      for (int e = 0; e < shape.m; ++e)
        declare(nodes.e[std::size_t(e)], "level2[" + std::to_string(e) + "]", eliminate);
      rows.assign(std::size_t(n() - 1), row);
    }
    C bound = elimination::growth_bound(scale, rule);
    declare(nodes.l3, "level3",
            pieces_
                .run(
                    "check", [&](auto& r, auto& b) { return elimination::check_step(r, b, rule); },
                    named("rows", rows), named("bound", bound))
                .second);
    Rows<C> upper;
    for (int k = 0; k < n(); ++k) upper.emplace_back(std::size_t(n() - k), C(T(0.5)));
    declare(nodes.l4, "level4",
            pieces_
                .run(
                    "back substitution", [](auto& u) { return elimination::back_substitute(u); },
                    named("U", upper))
                .second);
  }

  // ---- the client's side ----
  void send(Process& p, const elimination::LinearSystem<T>& system) {
    if (stopped_)
      throw std::logic_error("elimination pipeline: send after a failed round or finish");
    report_.begin_round();
    report_.outcome.input_start_us = p.now_us();
    p.out(pipe_.in(0), M::system(system), "system");
    if (serve_ == Serve::once) stopped_ = true;  // the levels take one system and end
  }

  void receive(Process& p) {
    if (serve_ != Serve::until_finish)
      throw std::logic_error("elimination pipeline: solve() needs Serve::until_finish");
    const auto answer = p.in(pipe_.out(0));
    report_.outcome.returned_us = p.now_us();
    if (std::get<0>(answer) & levels::header::kStop) stopped_ = true;
  }

  void finish(Process& p) {
    if (stopped_) return;
    stopped_ = true;
    p.out(pipe_.in(0), M::finish(), "finish");
  }

  const PipelineOutcome& outcome() const { return report_.outcome; }

  PipelineSettings settings;
  PipelineShape shape;
  PipelineNodes nodes;

 private:
  int n() const { return shape.n; }

  Serve serve_ = Serve::once;
  bool stopped_ = false;                       // the client's view: no more rounds
  std::unique_ptr<t800sim::Builder> builder_;  // owns the channels the levels' ends name
  t800sim::Pipeline<System, Packet> pipe_;     // the client's ends
  levels::Report report_;
  PieceCode<T> pieces_;  // each piece's recorded T800 code, for the cost model
  std::unique_ptr<levels::Level1<T>> level1_;
  std::vector<std::unique_ptr<levels::Level2<T>>> level2_;
  std::unique_ptr<levels::Level3<T>> level3_;
  std::unique_ptr<levels::Level4<T>> level4_;
};

template <class T>
PipelineProgram<T>::PipelineProgram(const PipelineSettings& settings, const PipelineNodes& nodes,
                                    int n)
    : levels_(std::make_unique<Levels>(settings, nodes, n)) {}

template <class T>
PipelineProgram<T>::~PipelineProgram() = default;

template <class T>
void PipelineProgram<T>::build(network::Machine& machine, int client, Serve serve) {
  levels_->build(machine, client, serve);
}

template <class T>
void PipelineProgram<T>::send(Process& client, const elimination::LinearSystem<T>& system) {
  levels_->send(client, system);
}

template <class T>
const PipelineOutcome& PipelineProgram<T>::solve(Process& client,
                                                 const elimination::LinearSystem<T>& system) {
  send(client, system);
  levels_->receive(client);
  return levels_->outcome();
}

template <class T>
void PipelineProgram<T>::finish(Process& client) {
  levels_->finish(client);
}

template <class T>
const PipelineOutcome& PipelineProgram<T>::outcome() const {
  return levels_->outcome();
}
template <class T>
const PipelineSettings& PipelineProgram<T>::settings() const {
  return levels_->settings;
}
template <class T>
const PipelineShape& PipelineProgram<T>::shape() const {
  return levels_->shape;
}

template class PipelineProgram<float>;
template class PipelineProgram<double>;

}  // namespace workloads
