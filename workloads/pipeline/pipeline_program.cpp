#include "workloads/pipeline/pipeline_program.hpp"

#include <functional>
#include <memory>
#include <numeric>
#include <stdexcept>
#include <tuple>

#include "t800/link_timing.hpp"
#include "workloads/pipeline/levels/level1.hpp"
#include "workloads/pipeline/levels/level2.hpp"
#include "workloads/pipeline/levels/level3.hpp"
#include "workloads/pipeline/levels/level4.hpp"
#include "workloads/pipeline/relay.hpp"
#include "workloads/setting_error.hpp"

namespace workloads {

namespace {

using elimination::Rows;
using network::Process;

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
// its state), the channels between them, the report they write, and the client's side.
template <class T>
class PipelineProgram<T>::Levels {
  using M = levels::Messages<T>;
  using C = typename M::C;

 public:
  Levels(const PipelineSettings& s, const PipelineNodes& n, int unknowns)
      : settings(s), shape{unknowns, s.m}, nodes(n) {}

  void build(network::Machine& machine, int client, Serve serve) {
    serve_ = serve;
    if (settings.overlap && serve != Serve::once)
      throw std::invalid_argument("elimination pipeline: overlap serves one system only");
    if (settings.recovery && serve != Serve::once)
      throw std::invalid_argument("elimination pipeline: recovery serves one system only");
    wiring_ = levels::Wiring::plan(machine, shape, nodes, client, serve, spawn_fan_out<T>,
                                   spawn_fan_in<T>);
    const levels::Context<T> context{settings, shape, nodes, wiring_, report_, pieces_, serve};
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
    // Each level a process of the SDK (t800sim::Process) on its processor.
    auto spawn = [&machine](int node, const char* name,
                            std::function<void(t800sim::Process&)> body) {
      machine.spawn(node, name, t800::Priority::low, [body](Process& p) {
        t800sim::Process level(p);
        body(level);
      });
    };
    using SdkProcess = t800sim::Process;
    spawn(nodes.l1, "level1", [this](SdkProcess& p) {
      levels::loop(serve_, p, [this](SdkProcess& q) { return level1_->round(q); });
    });
    for (int e = 0; e < shape.m; ++e)
      spawn(nodes.e[std::size_t(e)], "level2", [this, e](SdkProcess& p) {
        levels::Level2<T>& level = *level2_[std::size_t(e)];
        if (settings.recovery) return level.checked(p);
        levels::loop(serve_, p, [&level](SdkProcess& q) { return level.round(q); });
      });
    spawn(nodes.l3, "level3", [this](SdkProcess& p) {
      if (settings.recovery) return void(level3_->checked(p));
      levels::loop(serve_, p, [this](SdkProcess& q) { return level3_->round(q); });
    });
    spawn(nodes.l4, "level4", [this](SdkProcess& p) {
      levels::loop(serve_, p, [this](SdkProcess& q) { return level4_->round(q); });
    });
    declare_code(machine);
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
    auto declare = [&](int node, const char* process, const t800::ComputeWork& work) {
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
    auto [row, eliminate] = pieces_.run(
        "eliminate", [](auto& r, auto& j1) { return elimination::eliminate(r, j1); },
        named("row", m[1]), named("pivot", step.normalised));
    for (int e : nodes.e) declare(e, "level2", eliminate);
    Rows<C> rows(std::size_t(n() - 1), row);
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
    t800sim::Process(p).out(system_out(), M::system(system), "system");
    if (serve_ == Serve::once) stopped_ = true;  // the levels take one system and end
  }

  void receive(Process& p) {
    if (!wiring_.reply)
      throw std::logic_error("elimination pipeline: solve() needs Serve::until_finish");
    const auto answer =
        t800sim::Process(p).in(t800sim::In<typename M::Packet>(wiring_.typed(wiring_.reply)));
    report_.outcome.returned_us = p.now_us();
    if (std::get<0>(answer) & levels::header::kStop) stopped_ = true;
  }

  void finish(Process& p) {
    if (stopped_) return;
    stopped_ = true;
    t800sim::Process(p).out(system_out(), M::finish(), "finish");
  }

  const PipelineOutcome& outcome() const { return report_.outcome; }

  PipelineSettings settings;
  PipelineShape shape;
  PipelineNodes nodes;

 private:
  int n() const { return shape.n; }
  t800sim::Out<typename M::System> system_out() const {
    return t800sim::Out<typename M::System>(wiring_.typed(wiring_.input));
  }

  Serve serve_ = Serve::once;
  bool stopped_ = false;  // the client's view: no more rounds
  levels::Wiring wiring_;
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
