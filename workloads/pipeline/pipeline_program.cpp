#include "workloads/pipeline/pipeline_program.hpp"

#include <algorithm>
#include <any>
#include <cmath>
#include <functional>
#include <numeric>
#include <optional>
#include <stdexcept>
#include <type_traits>

#include "workloads/setting_error.hpp"

#include <systemc>

#include "network/alt.hpp"
#include "network/reliable.hpp"
#include "t800/link_timing.hpp"
#include "t800/payload_bytes.hpp"
#include "workloads/pipeline/checksum.hpp"

#include "workloads/pipeline/costs.hpp"
#include "workloads/pipeline/piece_code.hpp"
#include "workloads/pipeline/relay.hpp"

namespace workloads {

namespace {

using elimination::Row;
using elimination::Rows;
using elimination::Status;
using network::Process;

// A channel out of L1 (into L3) and the level-2 processors whose rows it carries.
struct Port {
  network::Channel* channel = nullptr;
  std::vector<int> served;
};

// One INT32 word in front of every row or matrix: the row's number (or the step) and a status flag.
constexpr std::int64_t kHeaderBytes = 4;

std::int64_t real_bytes(t800::Precision precision) {
  return precision == t800::Precision::real64 ? 8 : 4;
}

int require_node(const network::Topology& t, const std::string& name, const std::string& role) {
  const int index = t.find(name);
  if (index < 0)
    throw SettingError({kNetworkKey}, "elimination: the topology " + t.name + " has no processor " +
                                          name + " (" + role +
                                          "); use configs/topologies/elimination-m<m>.toml");
  return index;
}

// Memory shared by the PAR branches of one level (L1's, L3's rows): a branch that needs a row
// another branch has not stored yet gives up the CPU until it has. An occam programmer would put a
// buffer process in front; here the rows stay where they are, so the wait itself costs nothing.
struct Shared {
  sc_core::sc_event changed;
  template <class Ready>
  void wait_until(Process& p, Ready ready) {
    if (ready()) return;
    p.deschedule();
    while (!ready()) sc_core::wait(changed);
    p.reschedule();
  }
  void notify() { changed.notify(sc_core::SC_ZERO_TIME); }
};

}  // namespace

int level2_count(const network::Topology& t) {
  int m = 0;
  while (t.find("E" + std::to_string(m + 1)) >= 0) ++m;
  return m;
}

PipelineNodes find_pipeline_nodes(const network::Topology& t, int m) {
  PipelineNodes nodes;
  nodes.l1 = require_node(t, "L1", "level 1");
  nodes.l3 = require_node(t, "L3", "level 3");
  nodes.l4 = require_node(t, "L4", "level 4");
  for (int e = 1; e <= m; ++e)
    nodes.e.push_back(require_node(t, "E" + std::to_string(e), "a level-2 processor"));
  return nodes;
}

// The processes of one pipeline, on scalar T (float = REAL32, double = REAL64). Values are carried
// as Counted<T>, which computes exactly what T computes.
template <class T>
class PipelineProgram<T>::Levels {
  using C = dynamics::Counted<T>;
  using Input = std::optional<elimination::LinearSystem<C>>;  // nullopt: finish

  struct PivotMessage {
    bool ok = true;
    bool finish = false;    // with ok = false: the client called finish(), not a failure
    bool unstable = false;  // set by L3 on its way to L4
    Row<C> row;
    C scale = C(0);  // step 0 only: level 3's growth check needs it

    static PivotMessage stop(bool finish) {
      PivotMessage m;
      m.ok = false;
      m.finish = finish;
      return m;
    }
  };
  struct RowMessage {
    std::size_t index = 0;  // position in the reduced system
    Row<C> values;
  };
  // The reduced matrix goes back to L1 one row per message, like every other row transfer; a
  // failed step sends one header instead.
  struct ReturnedRow {
    bool ok = true;
    Row<C> values;
    // Position in the next step's system (with overlap the rows come back as they are ready).
    std::size_t index = 0;
  };

  // Recovery's messages (PipelineSettings::recovery): each carries the step it belongs to and a
  // checksum of its header word and REALs (checksum.hpp).
  struct CheckedPivot {
    int step = 0;
    bool stop = false;     // the level-2 processor ends
    bool forward = false;  // it passes the pivot row on to L3
    Row<C> row;
    C scale = C(0);
    std::uint32_t checksum = 0;
    std::uint32_t header() const { return std::uint32_t(step); }
  };
  struct CheckedRow {
    int step = 0;
    std::size_t index = 0;  // 1-based, in the step's reduced system
    bool bad = false;       // its level-2 processor found its input damaged
    Row<C> values;
    std::uint32_t checksum = 0;
    std::uint32_t header() const { return std::uint32_t(step * 256 + int(index)); }
  };
  // L3 to L1: resend these rows of the step (0: the pivot row) through other level-2 processors.
  struct Resend {
    std::vector<std::size_t> rows;
    std::vector<int> lost;   // level-2 processors (0-based) L3 gave up on
    std::vector<int> avoid;  // and those whose rows arrived damaged
  };

 public:
  Levels(const PipelineSettings& s, const PipelineNodes& n, int unknowns)
      : settings(s), shape{unknowns, s.m}, nodes(n) {}

  void build(network::Machine& machine, int client, Serve serve) {
    serve_ = serve;
    if (settings.overlap && serve != Serve::once)
      throw std::invalid_argument("elimination pipeline: overlap serves one system only");
    if (settings.recovery && serve != Serve::once)
      throw std::invalid_argument("elimination pipeline: recovery serves one system only");
    register_payloads();
    input_ = &machine.channel("system", client, nodes.l1);
    plan_level1_side(machine);
    plan_level3_side(machine);
    back_ = &machine.channel("L3->L1", nodes.l3, nodes.l1);
    to_l4_ = &machine.channel("L3->L4", nodes.l3, nodes.l4);
    if (serve == Serve::until_finish) reply_ = &machine.channel("qdd", nodes.l4, client);
    const auto low = t800::Priority::low;
    for (int e = 0; e < shape.m; ++e) e_buffers_.push_back(std::make_unique<Shared>());
    l1_failed_.assign(std::size_t(shape.m), false);
    const t800::LinkTiming link(machine.options().link);
    longest_message_us_ = 2 * link.arrival_ns(checked_bytes(std::size_t(n() + 2))) / 1000 + 10;
    l1_unused_.assign(std::size_t(shape.m), false);
    machine.spawn(nodes.l1, "level1", low, [this](Process& p) { loop(p, &Levels::level1); });
    for (int e = 0; e < shape.m; ++e)
      machine.spawn(nodes.e[std::size_t(e)], "level2", low, [this, e](Process& p) {
        if (settings.recovery) return level2_checked(p, e);
        loop(p, [e](Levels& l, Process& q) { return l.level2(q, e); });
      });
    machine.spawn(nodes.l3, "level3", low, [this](Process& p) {
      if (settings.recovery) return void(level3_checked(p));
      loop(p, &Levels::level3);
    });
    machine.spawn(nodes.l4, "level4", low, [this](Process& p) { loop(p, &Levels::level4); });
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
    begin_round();
    outcome.input_start_us = p.now_us();
    const std::int64_t bytes =
        real_bytes(settings.precision) * static_cast<std::int64_t>(n() * (n() + 1));
    p.out(*input_, {bytes, Input(elimination::convert<C>(system)), "system"});
    if (serve_ == Serve::once) stopped_ = true;  // the levels take one system and end
  }

  void receive(Process& p) {
    if (!reply_) throw std::logic_error("elimination pipeline: solve() needs Serve::until_finish");
    const t800::Message m = p.in(*reply_);
    outcome.returned_us = p.now_us();
    if (m.label == kFailLabel) stopped_ = true;
  }

  void finish(Process& p) {
    if (stopped_) return;
    stopped_ = true;
    p.out(*input_, {kHeaderBytes, Input(), "finish"});
  }

  PipelineOutcome outcome;
  PipelineSettings settings;
  PipelineShape shape;
  PipelineNodes nodes;

 private:
  // Runs a piece of numerical work, then charges its cost to the process's CPU (after the work is
  // tallied: compute() lets the simulation switch to other processes).
  template <class Kernel, class... Inputs>
  auto run_piece(Process& p, const char* label, Kernel kernel, Named<Inputs>... inputs) {
    auto [result, cost] = pieces_.run(label, kernel, inputs...);
    p.compute(cost, label);
    return std::move(result);
  }
  PieceCode<T> pieces_;

  std::int64_t reals(std::size_t count) const {
    return kHeaderBytes + real_bytes(settings.precision) * static_cast<std::int64_t>(count);
  }
  int n() const { return shape.n; }

  void fail(int step, Status status, const std::string& what) {
    if (outcome.failure.empty()) {
      outcome.status = status;
      outcome.failed_step = step;
      outcome.failure = what;
    }
  }

  // ---- wiring: which channel reaches each level-2 processor ----

  // A level-2 processor that is L1's (L3's) neighbour gets a channel of its own; one behind the
  // fan-out X (fan-in Y) shares X's (Y's) channel; any other gets a channel the network routes.
  void plan_level1_side(network::Machine& machine) {
    Relay fan_out;
    fan_out.node = machine.topology().find("X");
    for (int e = 0; e < shape.m; ++e) {
      const int node = nodes.e[std::size_t(e)];
      const std::string name = "E" + std::to_string(e + 1);
      if (!machine.link_between(nodes.l1, node) && behind(machine, fan_out.node, nodes.l1, node)) {
        fan_out.served.push_back(e);
        fan_out.outputs.push_back(&machine.channel("X->" + name, fan_out.node, node));
        e_in_.push_back(fan_out.outputs.back());
        continue;
      }
      e_in_.push_back(&machine.channel("L1->" + name, nodes.l1, node));
      out_ports_.push_back({e_in_.back(), {e}});
    }
    if (fan_out.served.empty()) return;
    fan_out.inputs.push_back(&machine.channel("L1->X", nodes.l1, fan_out.node));
    out_ports_.push_back({fan_out.inputs.back(), fan_out.served});
    fan_out.rounds = serve_ == Serve::once ? 1 : Relay::kUntilStopped;
    spawn_fan_out(machine, shape, fan_out);
  }

  void plan_level3_side(network::Machine& machine) {
    Relay fan_in;
    fan_in.node = machine.topology().find("Y");
    for (int e = 0; e < shape.m; ++e) {
      const int node = nodes.e[std::size_t(e)];
      const std::string name = "E" + std::to_string(e + 1);
      // E1 also forwards the pivot rows, which the fan-in's schedule does not carry.
      if (e > 0 && !machine.link_between(nodes.l3, node) &&
          behind(machine, fan_in.node, nodes.l3, node)) {
        fan_in.served.push_back(e);
        fan_in.inputs.push_back(&machine.channel(name + "->Y", node, fan_in.node));
        e_out_.push_back(fan_in.inputs.back());
        e_behind_fan_in_.push_back(true);
        continue;
      }
      e_out_.push_back(&machine.channel(name + "->L3", node, nodes.l3));
      e_behind_fan_in_.push_back(false);
      in_ports_.push_back({e_out_.back(), {e}});
    }
    if (fan_in.served.empty()) return;
    fan_in.outputs.push_back(&machine.channel("Y->L3", fan_in.node, nodes.l3));
    in_ports_.push_back({fan_in.outputs.back(), fan_in.served});
    fan_in.rounds = serve_ == Serve::once ? 1 : Relay::kUntilStopped;
    spawn_fan_in(machine, shape, fan_in);
  }

  static bool behind(const network::Machine& machine, int relay, int level, int node) {
    return relay >= 0 && machine.link_between(relay, level) && machine.link_between(relay, node);
  }

  // Once: one round. Until finish: rounds until a level sees the finish (or a failure) and stops.
  template <class Round>
  void loop(Process& p, Round round) {
    for (int r = 0; serve_ == Serve::until_finish || r < 1; ++r)
      if (!std::invoke(round, *this, p)) return;
  }

  // The state one round leaves behind; the client starts a round only when the last one ended.
  void begin_round() {
    outcome = PipelineOutcome();
    largest_ = 0;
    first_unstable_ = -1;
  }

  // ---- level 1 ----
  // One system; false when the pipeline stops (finish, or a failure every level is told of).
  bool level1(Process& p) {
    auto input = std::any_cast<Input>(p.in(*input_).payload);
    if (!input) {
      send_stop(p, 0, true);
      return false;
    }
    const elimination::LinearSystem<C>& system = *input;
    input_scale_ = elimination::largest_magnitude(elimination::augment(system.a, system.b));
    outcome.start_us = p.now_us();
    const auto& rule = settings.rule;
    Rows<C> m = run_piece(
        p, "augment", [](auto& a, auto& b) { return elimination::augment(a, b); },
        named("A", system.a), named("b", system.b));
    const C scale =
        rule.needs_scale()
            ? run_piece(
                  p, "scale", [](auto& a) { return elimination::matrix_scale(a); }, named("m", m))
            : C(0);
    const C limit = run_piece(
        p, "limit", [&](auto& s) { return elimination::pivot_limit(s, rule); },
        named("scale", scale));
    if (!settings.overlap) return steps(p, std::move(m), scale, limit);
    // Overlap: a receiver stores the rows L3 streams back while the steps go on.
    bool go = true;
    p.par({[&](Process& q) { go = steps(q, std::move(m), scale, limit); },
           [this](Process& q) { receive_streamed(q); }});
    return go;
  }

  // The n steps of one system on L1; false when the pipeline stops.
  bool steps(Process& p, Rows<C> first, C scale, C limit) {
    const auto& rule = settings.rule;
    matrices_.assign(std::size_t(n()), Rows<C>());
    for (int k = 1; k < n(); ++k) matrices_[std::size_t(k)].resize(std::size_t(n() - k));
    arrived_.assign(std::size_t(n()), 0);
    handed_ = 0;
    l1_stopped_ = false;
    matrices_[0] = std::move(first);
    arrived_[0] = n();
    std::vector<int> order(static_cast<std::size_t>(n()));
    std::iota(order.begin(), order.end(), 0);
    for (int k = 0; k < n(); ++k) {
      Rows<C>& m = matrices_[std::size_t(k)];
      if (k > 0 && !(settings.recovery ? next_matrix_checked(p, k) : next_matrix(p, k, limit)))
        return stop_level1(p, k);
      outcome.step_start_us.push_back(p.now_us());
      auto step = run_piece(
          p, "pivot",
          [&](auto& rows, auto& rows_order, auto& l) {
            return elimination::pivot_step(rows, rows_order, rule, l);
          },
          named("m", m), named("order", order), named("limit", limit));
      if (!step.found) {
        fail(k, elimination::pivot_failure(m),
             "level 1: no usable pivot at step " + std::to_string(k));
        return stop_level1(p, k);
      }
      outcome.pivot_rows.push_back(order[0]);
      if (step.interchanged) ++outcome.interchanges;
      if (settings.recovery) {
        pivot_ = CheckedPivot{k, false, false, std::move(step.normalised), k == 0 ? scale : C(0)};
        hand_out_checked(p, k, all_rows(k), {});
      } else {
        hand_out(
            p, k,
            PivotMessage{true, false, false, std::move(step.normalised), k == 0 ? scale : C(0)}, m);
      }
      ++handed_;
      l1_.notify();
      order.erase(order.begin());
    }
    if (settings.recovery) {
      if (!next_matrix_checked(p, n())) return stop_level1(p, n());  // resends of the last step
      stop_level2(p);
    }
    return true;
  }

  bool stop_level1(Process& p, int k) {
    l1_stopped_ = true;
    l1_.notify();
    if (settings.recovery) {
      stop_level2(p);
      return false;
    }
    return send_stop(p, k, false);
  }

  // Step k's matrix: strict, all of it from L3; overlap, the rows the pivot choice reads (simple
  // interchange with a usable first pivot: that row only; otherwise every row).
  bool next_matrix(Process& p, int k, C limit) {
    Rows<C>& m = matrices_[std::size_t(k)];
    if (!settings.overlap) return receive_reduced(p, std::size_t(n() - k), m);
    const int rows = n() - k;
    l1_.wait_until(p, [&] { return !m[0].empty(); });
    if (settings.rule.pivoting == elimination::Pivoting::partial || !usable(m[0][0], limit))
      l1_.wait_until(p, [&] { return arrived_[std::size_t(k)] == rows; });
    return true;
  }

  // The simple-interchange test of elimination::first_usable_pivot, on values (no work counted:
  // pivot_step repeats it and is charged for it).
  bool usable(const C& lead, const C& limit) const {
    const long double v = elimination::value_of(lead);
    return settings.rule.threshold > 0 ? std::abs(v) > elimination::value_of(limit) : v != 0;
  }

  // Overlap: L1's receiver. Step s's rows come back once step s - 1 was handed out, in any order.
  void receive_streamed(Process& p) {
    for (int s = 1; s < n(); ++s) {
      l1_.wait_until(p, [&] { return handed_ >= s || l1_stopped_; });
      if (handed_ < s) return;
      Rows<C>& m = matrices_[std::size_t(s)];
      for (int r = 0; r < n() - s; ++r) {
        auto row = std::any_cast<ReturnedRow>(p.in(*back_).payload);
        if (row.index >= m.size())
          p.stop("row number " + std::to_string(row.index) + " out of range");
        m[row.index] = std::move(row.values);
        ++arrived_[std::size_t(s)];
        l1_.notify();
      }
    }
  }

  // Overlap: step k's row i is in L1's memory (strict: always).
  void await_row(Process& p, int k, std::size_t i) {
    if (settings.overlap) l1_.wait_until(p, [&] { return !matrices_[std::size_t(k)][i].empty(); });
  }

  // The n - k rows of the reduced matrix from L3 (the first tells whether the step failed).
  bool receive_reduced(Process& p, std::size_t rows, Rows<C>& m) {
    Rows<C> reduced;
    for (std::size_t i = 0; i < rows; ++i) {
      auto row = std::any_cast<ReturnedRow>(p.in(*back_).payload);
      if (!row.ok) return false;  // strict: rows come in order
      reduced.push_back(std::move(row.values));
    }
    m = std::move(reduced);
    return true;
  }

  // Every level-2 processor waiting in step k gets a stop (failed) pivot message; E1 passes it on,
  // so L3 and L4 stop too and nobody is left blocked. Serving system after system, the processors
  // with no rows left in step k already wait for the next system's step 0: they get one too.
  // Returns false: L1 stops.
  bool send_stop(Process& p, int k, bool finish) {
    std::vector<Process::Body> branches;
    const bool next_round_waits = serve_ == Serve::until_finish && k > 0;
    for (const Port& port : out_ports_)
      if (!takers(port, k).empty() || next_round_waits)
        branches.push_back([&port, finish](Process& q) {
          q.out(*port.channel, {kHeaderBytes, PivotMessage::stop(finish), kFailLabel});
        });
    par(p, branches);
    return false;
  }

  // The pivot row and the rows of step k down every channel at once (one branch per channel).
  void hand_out(Process& p, int k, const PivotMessage& pivot, const Rows<C>& m) {
    std::vector<Process::Body> branches;
    for (const Port& port : out_ports_) {
      if (takers(port, k).empty()) continue;
      branches.push_back([this, k, &port, &pivot, &m](Process& q) {
        const std::size_t extra = k == 0 && settings.rule.growth_check() ? 1 : 0;  // the scale
        q.out(*port.channel, {reals(pivot.row.size() + extra), pivot, "pivot row"});
        for (std::size_t i : relay_rows(shape, port.served, k)) {
          await_row(q, k, i);
          q.out(*port.channel, {reals(m[i].size()), RowMessage{i, m[i]}, "row"});
        }
      });
    }
    par(p, branches);
  }

  std::vector<int> takers(const Port& port, int k) const {
    std::vector<int> out;
    for (int e : port.served)
      if (shape.participates(k, e)) out.push_back(e);
    return out;
  }

  // occam PAR; a single branch runs in place.
  static void par(Process& p, const std::vector<Process::Body>& branches) {
    if (branches.size() == 1) return branches.front()(p);
    p.par(branches);
  }

  // ---- level 2 ----
  bool level2(Process& p, int e) {
    network::Channel& in = *e_in_[std::size_t(e)];
    network::Channel& out = *e_out_[std::size_t(e)];
    for (int k = 0; k < n(); ++k) {
      if (!shape.participates(k, e)) continue;
      t800::Message pivot_message = p.in(in);
      const auto& pivot = std::any_cast<const PivotMessage&>(pivot_message.payload);
      const std::vector<std::size_t> rows = shape.rows_for(k, e);
      if (!pivot.ok) {
        // E1 tells L3; one behind the fan-in tells the fan-in, which waits for its rows.
        if (e == 0 || e_behind_fan_in_[std::size_t(e)]) p.out(out, pivot_message);
        return false;
      }
      note_level2(p.now_us(), true);
      if (settings.buffered) {
        eliminate_buffered(p, e, pivot_message, rows);
        continue;
      }
      std::vector<t800::Message> first(1);
      if (e == 0) {
        // E1 forwards the pivot row to L3 while it takes its first row.
        std::vector<Process::Body> branches{[&](Process& q) { q.out(out, pivot_message); }};
        if (!rows.empty()) branches.push_back([&](Process& q) { first[0] = q.in(in); });
        par(p, branches);
      }
      for (std::size_t r = 0; r < rows.size(); ++r) {
        t800::Message message = (r == 0 && e == 0) ? std::move(first[0]) : p.in(in);
        const auto& row = std::any_cast<const RowMessage&>(message.payload);
        Row<C> done = run_piece(
            p, "eliminate", [](auto& r, auto& j1) { return elimination::eliminate(r, j1); },
            named("row", row.values), named("pivot", pivot.row));
        p.out(out, {reals(done.size()), RowMessage{row.index, std::move(done)}, "row"});
        note_level2(p.now_us(), false);
      }
    }
    return true;
  }

  // Buffered level 2, one step: input, eliminator and output in PAR, joined by one-row buffers.
  // The input process takes row r once the eliminator has started on row r - 1 (it then holds one
  // row), and the eliminator hands row r on once the output process has taken row r - 1; the
  // buffers are the processes' own variables, so handing a row on costs nothing here (as Shared).
  void eliminate_buffered(Process& p, int e, const t800::Message& pivot_message,
                          const std::vector<std::size_t>& rows) {
    network::Channel& in = *e_in_[std::size_t(e)];
    network::Channel& out = *e_out_[std::size_t(e)];
    const auto& pivot = std::any_cast<const PivotMessage&>(pivot_message.payload);
    Shared& buffer = *e_buffers_[std::size_t(e)];
    const std::size_t count = rows.size();
    std::vector<t800::Message> taken(count);
    std::vector<RowMessage> done(count);
    std::size_t received = 0, started = 0, finished = 0, sent = 0;
    std::vector<Process::Body> branches;
    if (count > 0) {
      branches.push_back([&](Process& q) {  // input
        for (std::size_t r = 0; r < count; ++r) {
          buffer.wait_until(q, [&] { return started >= r; });
          taken[r] = q.in(in);
          ++received;
          buffer.notify();
        }
      });
      branches.push_back([&](Process& q) {  // eliminator
        for (std::size_t r = 0; r < count; ++r) {
          buffer.wait_until(q, [&] { return received > r; });
          ++started;
          buffer.notify();
          const auto& row = std::any_cast<const RowMessage&>(taken[r].payload);
          Row<C> values = run_piece(
              q, "eliminate", [](auto& r, auto& j1) { return elimination::eliminate(r, j1); },
              named("row", row.values), named("pivot", pivot.row));
          buffer.wait_until(q, [&] { return sent >= r; });
          done[r] = RowMessage{row.index, std::move(values)};
          ++finished;
          buffer.notify();
        }
      });
    }
    branches.push_back([&](Process& q) {  // output; E1 forwards the pivot row first
      if (e == 0) q.out(out, pivot_message);
      for (std::size_t r = 0; r < count; ++r) {
        buffer.wait_until(q, [&] { return finished > r; });
        ++sent;
        buffer.notify();
        RowMessage row = std::move(done[r]);
        const std::int64_t bytes = reals(row.values.size());
        q.out(out, {bytes, std::move(row), "row"});
        note_level2(q.now_us(), false);
      }
    });
    par(p, branches);
  }

  // Level 2's window (PipelineOutcome::level2_first_us, level2_last_us).
  void note_level2(double now_us, bool first) {
    if (first) {
      if (outcome.level2_first_us < 0 || now_us < outcome.level2_first_us)
        outcome.level2_first_us = now_us;
    } else {
      outcome.level2_last_us = std::max(outcome.level2_last_us, now_us);
    }
  }

  // ---- level 3 ----
  bool level3(Process& p) {
    C bound = C(0);
    bool unstable = false;
    for (int k = 0; k < n(); ++k) {
      auto pivot = std::any_cast<PivotMessage>(p.in(*e_out_[0]).payload);
      if (!pivot.ok) {
        p.out(*to_l4_, {kHeaderBytes, pivot, kFailLabel});
        return false;
      }
      if (k == 0 && settings.rule.growth_check())
        bound = run_piece(
            p, "bound", [&](auto& s) { return elimination::growth_bound(s, settings.rule); },
            named("scale", pivot.scale));
      const std::size_t r = static_cast<std::size_t>(n() - 1 - k);
      if (settings.overlap) {
        stream(p, k, pivot, bound, unstable);
        continue;
      }
      Rows<C> rows(r);
      collect(p, k, pivot, unstable, rows);
      if (r == 0) continue;
      // A non-finite value: L1 now stops everybody; E1's failed pivot row ends this loop.
      return_reduced(p, k, rows, bound, unstable);
    }
    return true;
  }

  // Step k's rows checked and, unless one is not finite (false: L1 is told to stop), sent back to
  // L1 as the next step's matrix.
  bool return_reduced(Process& p, int k, Rows<C>& rows, C bound, bool& unstable) {
    const auto check = run_piece(
        p, "check", [&](auto& r, auto& b) { return elimination::check_step(r, b, settings.rule); },
        named("rows", rows), named("bound", bound));
    largest_ = std::max(largest_, elimination::largest_magnitude(rows));  // diagnostic only
    if (check.status == Status::non_finite) {
      fail(k, Status::non_finite,
           "level 3: a non-finite value in row " + std::to_string(check.row + 1) + " of step " +
               std::to_string(k));
      p.out(*back_, {kHeaderBytes, ReturnedRow{false, {}}, kFailLabel});
      return false;
    }
    if (check.status == Status::unstable && !unstable) {
      unstable = true;
      first_unstable_ = k;
    }
    for (std::size_t i = 0; i < rows.size(); ++i)
      p.out(*back_,
            {reals(rows[i].size()), ReturnedRow{true, std::move(rows[i]), i}, "reduced row"});
    return true;
  }

  // One step's rows from every level-2 processor (their order on the wire is known), while the
  // pivot row goes on to L4.
  void collect(Process& p, int k, PivotMessage& pivot, bool unstable, Rows<C>& rows) {
    pivot.unstable = unstable;
    std::vector<Process::Body> branches{[&](Process& q) {
      q.out(*to_l4_, {reals(pivot.row.size()), pivot, "U row"});
    }};
    std::vector<int> arrived(rows.size(), 0);
    for (const Port& port : in_ports_) {
      const std::vector<std::size_t> expected = relay_rows(shape, port.served, k);
      if (expected.empty()) continue;
      branches.push_back([&port, expected, &rows, &arrived](Process& q) {
        for (std::size_t count = expected.size(); count > 0; --count) {
          auto row = std::any_cast<RowMessage>(q.in(*port.channel).payload);
          if (row.index < 1 || row.index > rows.size())
            q.stop("row number " + std::to_string(row.index) + " out of range");
          rows[row.index - 1] = std::move(row.values);
          ++arrived[row.index - 1];
        }
      });
    }
    par(p, branches);
    for (int a : arrived)
      if (a != 1) throw std::logic_error("elimination pipeline: a row did not arrive exactly once");
  }

  // Overlap: step k's rows go back to L1 one by one as they arrive, each checked on its own (the
  // same check, row by row). A non-finite row is reported but still sent: the pipeline drains
  // (L4 then gives no q̈) instead of stopping level 2 mid-step.
  void stream(Process& p, int k, PivotMessage& pivot, C bound, bool& unstable) {
    const std::size_t r = static_cast<std::size_t>(n() - 1 - k);
    Rows<C> rows(r);
    std::vector<std::size_t> ready;  // indices in arrival order
    std::vector<Process::Body> branches{[&](Process& q) {
      pivot.unstable = unstable;
      q.out(*to_l4_, {reals(pivot.row.size()), pivot, "U row"});
    }};
    for (const Port& port : in_ports_) {
      const std::vector<std::size_t> expected = relay_rows(shape, port.served, k);
      if (expected.empty()) continue;
      branches.push_back([this, &port, expected, &rows, &ready](Process& q) {
        for (std::size_t count = expected.size(); count > 0; --count) {
          auto row = std::any_cast<RowMessage>(q.in(*port.channel).payload);
          if (row.index < 1 || row.index > rows.size())
            q.stop("row number " + std::to_string(row.index) + " out of range");
          rows[row.index - 1] = std::move(row.values);
          ready.push_back(row.index - 1);
          l3_.notify();
        }
      });
    }
    if (r > 0)
      branches.push_back([&](Process& q) {
        for (std::size_t sent = 0; sent < r; ++sent) {
          l3_.wait_until(q, [&] { return ready.size() > sent; });
          forward(q, k, rows[ready[sent]], ready[sent], bound, unstable);
        }
      });
    par(p, branches);
  }

  void forward(Process& p, int k, Row<C>& row, std::size_t i, C bound, bool& unstable) {
    const Rows<C> one{row};
    const auto check = run_piece(
        p, "check", [&](auto& r, auto& b) { return elimination::check_step(r, b, settings.rule); },
        named("rows", one), named("bound", bound));
    largest_ = std::max(largest_, elimination::largest_magnitude(one));  // diagnostic only
    if (check.status == Status::non_finite)
      fail(k, Status::non_finite,
           "level 3: a non-finite value in row " + std::to_string(i + 1) + " of step " +
               std::to_string(k));
    if (check.status == Status::unstable && !unstable) {
      unstable = true;
      first_unstable_ = k;
    }
    p.out(*back_, {reals(row.size()), ReturnedRow{true, std::move(row), i}, "reduced row"});
  }

  // ---- level 4 ----
  bool level4(Process& p) {
    Rows<C> upper;
    bool unstable = false;
    for (int k = 0; k < n(); ++k) {
      auto pivot = std::any_cast<PivotMessage>(p.in(*to_l4_).payload);
      if (!pivot.ok) {
        if (pivot.finish) return false;
        outcome.end_us = p.now_us();
        if (reply_) p.out(*reply_, {kHeaderBytes, {}, kFailLabel});
        return false;
      }
      unstable = unstable || pivot.unstable;
      upper.push_back(std::move(pivot.row));
    }
    outcome.eliminated_us = p.now_us();
    const Row<C> x = run_piece(
        p, "back substitution", [](auto& u) { return elimination::back_substitute(u); },
        named("U", upper));
    outcome.end_us = p.now_us();
    record(x, unstable);
    if (reply_) p.out(*reply_, {reals(outcome.qdd.size()), outcome.qdd, "qdd"});
    return true;
  }

  void record(const Row<C>& x, bool unstable) {
    if (outcome.status == Status::non_finite) return;  // overlap: L3 saw it, the pipeline drained
    for (const C& v : x) {
      if (elimination::is_finite(v)) continue;
      fail(n(), Status::non_finite, "level 4: back substitution overflowed");
      return;
    }
    for (const C& v : x) outcome.qdd.push_back(static_cast<double>(v.value()));
    if (input_scale_ > 0 && largest_ > input_scale_)
      outcome.growth = static_cast<double>(largest_ / input_scale_);
    if (unstable)
      fail(first_unstable_, Status::unstable,
           "level 3: pivot growth above the limit from step " + std::to_string(first_unstable_));
  }

  Serve serve_ = Serve::once;
  bool stopped_ = false;  // the client's view: no more rounds
  network::Channel* input_ = nullptr;
  network::Channel* reply_ = nullptr;
  network::Channel* back_ = nullptr;
  network::Channel* to_l4_ = nullptr;
  std::vector<network::Channel*> e_in_, e_out_;  // each level-2 processor's input and output
  std::vector<bool> e_behind_fan_in_;
  std::vector<Port> out_ports_, in_ports_;  // L1's output channels, L3's input channels
  long double input_scale_ = 0;             // max |a_ij| of the input (diagnostic)
  long double largest_ = 0;                 // max |a(k)_ij| seen by L3 (diagnostic)
  int first_unstable_ = -1;
  // L1's matrices, one per step (overlap: filled as rows stream back), and what has arrived.
  std::vector<Rows<C>> matrices_;
  std::vector<int> arrived_;
  int handed_ = 0;           // steps L1 has handed out
  bool l1_stopped_ = false;  // L1 gave up before handing out step handed_
  Shared l1_, l3_;
  std::vector<std::unique_ptr<Shared>> e_buffers_;  // buffered level 2: one per processor
  // recovery
  CheckedPivot pivot_;             // L1's pivot row of the step it is in
  std::vector<bool> l1_failed_;    // level-2 processors L1's output to failed
  std::vector<bool> l1_unused_;    // and those L1 no longer gives rows (failed, or given up by L3)
  std::vector<bool> l3_lost_;      // level-2 processors L3 no longer listens to
  int resends_ = 0;                // rows resent
  double longest_message_us_ = 0;  // twice the longest message's time on a link, and 10 us

  // ---- recovery (PipelineSettings::recovery) ----

  std::int64_t checked_bytes(std::size_t count) const { return reals(count) + 4; }
  std::int64_t pivot_bytes(const CheckedPivot& m) const {
    const std::size_t extra = m.step == 0 && settings.rule.growth_check() ? 1 : 0;  // the scale
    return checked_bytes(m.row.size() + extra);
  }
  static std::uint32_t sum_of(const CheckedPivot& m) {
    std::uint32_t sum = checksum(m.header(), m.row);
    add_words(sum, m.scale.value());
    return sum;
  }
  static std::uint32_t sum_of(const CheckedRow& m) {
    return checksum(m.header() + (m.bad ? 0x80000000u : 0u), m.values);
  }
  // The checksum loop over a message of `count` REALs and its header, on p's processor.
  void charge_checksum(Process& p, std::size_t count) {
    const std::int64_t words = 1 + std::int64_t(count) * (real_bytes(settings.precision) / 4);
    p.compute(p.machine().compute_model(p.node()).process_cycles(checksum_code(words)), "checksum");
  }
  // L1's outputs wait for a level-2 processor that may itself be waiting, up to the timeout, for
  // level 3 to take its output; twice the timeout, and L1 gives it up.
  double l1_deadline(const Process& p) const { return p.now_us() + 2 * settings.timeout_us; }
  // Step k's pivot row (0) and rows 1 .. n - 1 - k.
  std::vector<std::size_t> all_rows(int k) const {
    std::vector<std::size_t> rows;
    for (int i = 0; i <= n() - 1 - k; ++i) rows.push_back(std::size_t(i));
    return rows;
  }
  std::vector<int> path_through(int e) const {
    return {nodes.l1, nodes.e[std::size_t(e)], nodes.l3};
  }

  // L1: step k's `rows` (of matrices_[k]; 0 = the pivot row, for L3) through the level-2
  // processors it still uses, avoiding `avoid` if it can. First handing-out: the round-robin of
  // the shape while no processor has failed; a resend, or after a failure: round-robin over the
  // others. The pivot row goes to each that gets rows, and to the first, which forwards it to L3.
  void hand_out_checked(Process& p, int k, std::vector<std::size_t> rows,
                        const std::vector<int>& avoid) {
    std::vector<int> live, preferred;
    for (int e = 0; e < shape.m; ++e)
      if (!l1_unused_[std::size_t(e)]) live.push_back(e);
    for (int e : live)
      if (std::find(avoid.begin(), avoid.end(), e) == avoid.end()) preferred.push_back(e);
    if (!preferred.empty()) live = preferred;
    if (live.empty()) return;  // nobody left: level 3 gives up
    const bool forward = std::find(rows.begin(), rows.end(), 0) != rows.end();
    rows.erase(std::remove(rows.begin(), rows.end(), 0), rows.end());
    const bool as_shaped =
        avoid.empty() && std::find(l1_unused_.begin(), l1_unused_.end(), true) == l1_unused_.end();
    std::vector<std::vector<std::size_t>> given(std::size_t(shape.m));
    for (std::size_t j = 0; j < rows.size(); ++j)
      given[std::size_t(as_shaped ? shape.owner(rows[j]) : live[j % live.size()])].push_back(
          rows[j]);
    pivot_.step = k;
    pivot_.checksum = sum_of(pivot_);
    charge_checksum(p, pivot_.row.size() + 1);
    std::vector<Process::Body> branches;
    for (int e : live) {
      const bool forwarder = forward && e == live.front();
      if (given[std::size_t(e)].empty() && !forwarder) continue;
      branches.push_back([this, e, k, forwarder, &given](Process& q) {
        CheckedPivot pivot = pivot_;
        pivot.forward = forwarder;
        network::Channel& c = *e_in_[std::size_t(e)];
        if (!network::out_or_fail(q, c, {pivot_bytes(pivot), pivot, "pivot row"}, l1_deadline(q)))
          return lose_from_l1(e);
        for (std::size_t i : given[std::size_t(e)]) {
          CheckedRow row{k, i, false, matrices_[std::size_t(k)][i], 0};
          row.checksum = sum_of(row);
          charge_checksum(q, row.values.size());
          if (!network::out_or_fail(q, c, {checked_bytes(row.values.size()), row, "row"},
                                    l1_deadline(q)))
            return lose_from_l1(e);
        }
      });
    }
    par(p, branches);
  }

  void lose_from_l1(int e) {
    l1_failed_[std::size_t(e)] = true;
    l1_unused_[std::size_t(e)] = true;
  }

  // L1: step k's matrix from L3, serving L3's requests to resend step k - 1's rows first.
  bool next_matrix_checked(Process& p, int k) {
    for (;;) {
      t800::Message m = p.in(*back_);
      if (const auto* request = std::any_cast<Resend>(&m.payload)) {
        for (int e : request->lost) l1_unused_[std::size_t(e)] = true;
        resends_ += int(request->rows.size());
        hand_out_checked(p, k - 1, request->rows, request->avoid);
        continue;
      }
      auto first = std::any_cast<ReturnedRow>(std::move(m.payload));
      if (!first.ok) return false;
      if (k == n()) return true;  // L3's word that the last step is complete
      Rows<C>& reduced = matrices_[std::size_t(k)];
      reduced = {std::move(first.values)};
      for (int i = 1; i < n() - k; ++i) {
        auto row = std::any_cast<ReturnedRow>(p.in(*back_).payload);
        if (!row.ok) return false;
        reduced.push_back(std::move(row.values));
      }
      return true;
    }
  }

  // L1: every level-2 processor ends, also one L1 gave up (it may only have been slow). One that
  // does not take its stop is unreachable: a fault nothing depended on any more.
  void stop_level2(Process& p) {
    std::vector<Process::Body> branches;
    for (int e = 0; e < shape.m; ++e)
      branches.push_back([this, e](Process& q) {
        CheckedPivot stop;
        stop.stop = true;
        if (network::out_or_fail(q, *e_in_[std::size_t(e)], {kHeaderBytes, stop, "stop"},
                                 l1_deadline(q)))
          return;
        network::Machine& m = q.machine();
        const std::vector<int> path{nodes.l1, nodes.e[std::size_t(e)]};
        if (m.faults().detected(m, path, "level 1 (its stop was not taken)") > 0)
          m.faults().recovered(m, path, "none needed: the solve no longer depended on it");
      });
    par(p, branches);
  }

  // A level-2 processor: checks each message's checksum, eliminates the intact rows with an intact
  // pivot row, marks the others damaged, and sends every row on with its own checksum. An output
  // level 3 does not take within the timeout is given up (level 3 asks for the row again), so the
  // processor always comes back to take what L1 sends.
  void level2_checked(Process& p, int e) {
    network::Channel& in = *e_in_[std::size_t(e)];
    network::Channel& out = *e_out_[std::size_t(e)];
    auto send = [&](t800::Message m) {
      network::out_or_fail(p, out, std::move(m), p.now_us() + settings.timeout_us);
    };
    // L1 may give up a message half-way (this processor was slow, or a fault): each message says
    // what it is, so a pivot row may come where a row was due.
    CheckedPivot pivot;
    bool pivot_intact = false;
    for (;;) {
      t800::Message m = p.in(in);
      if (const auto* next = std::any_cast<CheckedPivot>(&m.payload)) {
        pivot = *next;
        if (pivot.stop) return;
        note_level2(p.now_us(), true);
        charge_checksum(p, pivot.row.size() + 1);
        pivot_intact = sum_of(pivot) == pivot.checksum;
        if (pivot.forward) send({pivot_bytes(pivot), pivot, "pivot row"});
        continue;
      }
      const auto& row = std::any_cast<const CheckedRow&>(m.payload);
      charge_checksum(p, row.values.size());
      CheckedRow done{row.step, row.index, true, {}, 0};
      if (pivot_intact && row.step == pivot.step && sum_of(row) == row.checksum) {
        done.bad = false;
        done.values = run_piece(
            p, "eliminate", [](auto& x, auto& j1) { return elimination::eliminate(x, j1); },
            named("row", row.values), named("pivot", pivot.row));
        charge_checksum(p, done.values.size());
      }
      done.checksum = sum_of(done);
      send({checked_bytes(done.values.size()), done, "row"});
      note_level2(p.now_us(), false);
    }
  }

  // Level 3: each step's pivot row and rows, checked, with resends of what is missing or damaged;
  // then as in strict steps. A step it cannot complete ends the pipeline (Status::lost).
  bool level3_checked(Process& p) {
    l3_lost_.assign(std::size_t(shape.m), false);
    C bound = C(0);
    bool unstable = false;
    for (int k = 0; k < n(); ++k) {
      const std::size_t r = std::size_t(n() - 1 - k);
      CheckedPivot pivot;
      Rows<C> rows(r);
      if (!collect_checked(p, k, pivot, rows)) {
        fail(k, Status::lost,
             "level 3: step " + std::to_string(k) + "'s rows did not all arrive intact after " +
                 std::to_string(shape.m + 1) +
                 " requests in a row to resend them (a fault no other level-2 processor could get "
                 "round, or workload.recovery_timeout_us shorter than the pipeline's own pauses)");
        p.out(*back_, {kHeaderBytes, ReturnedRow{false, {}}, kFailLabel});
        p.out(*to_l4_, {kHeaderBytes, PivotMessage::stop(false), kFailLabel});
        return false;
      }
      PivotMessage u{true, false, unstable, pivot.row, pivot.scale};
      p.out(*to_l4_, {reals(u.row.size()), u, "U row"});
      if (k == 0 && settings.rule.growth_check())
        bound = run_piece(
            p, "bound", [&](auto& s) { return elimination::growth_bound(s, settings.rule); },
            named("scale", pivot.scale));
      if (r > 0 && !return_reduced(p, k, rows, bound, unstable)) {
        p.out(*to_l4_, {kHeaderBytes, PivotMessage::stop(false), kFailLabel});
        return false;
      }
    }
    p.out(*back_, {kHeaderBytes, ReturnedRow{true, {}, 0}, "done"});  // L1 resends no more
    return true;
  }

  // Step k's messages until every row (and the pivot row) is in intact, asking L1 to resend what
  // is not; it gives up after m + 1 requests in a row that brought nothing.
  bool collect_checked(Process& p, int k, CheckedPivot& pivot, Rows<C>& rows) {
    std::vector<bool> have(rows.size() + 1, false);  // [0]: the pivot row
    int idle = 0;                                    // resend rounds in a row that brought nothing
    std::optional<Resend> request;
    for (int round = 0;; ++round) {
      std::vector<int> damaged;
      const auto before = std::count(have.begin(), have.end(), true);
      // The request goes to L1 while the rows still coming are taken: L1 may be waiting for a
      // level-2 processor that waits for level 3.
      // The first wait of a step is longer: L1 has a pivot to find before it sends anything.
      const double first_wait_us = (round == 0 ? 4 : 1) * settings.timeout_us;
      auto receive = [&](Process& q) {
        receive_step(q, k, pivot, rows, have, damaged, first_wait_us);
      };
      if (request) {
        const std::int64_t words =
            std::int64_t(request->rows.size() + request->lost.size() + request->avoid.size()) + 1;
        par(p, {[&](Process& q) { q.out(*back_, {4 * words, *request, "resend"}); }, receive});
      } else {
        receive(p);
      }
      idle = std::count(have.begin(), have.end(), true) > before ? 0 : idle + 1;
      std::vector<std::size_t> missing;
      for (std::size_t i = 0; i < have.size(); ++i)
        if (!have[i]) missing.push_back(i);
      network::Machine& machine = p.machine();
      if (missing.empty()) {
        if (round > 0)
          for (int e = 0; e < shape.m; ++e)
            machine.faults().recovered(machine, path_through(e),
                                       "level 1 resent step " + std::to_string(k) +
                                           "'s rows through other level-2 processors");
        return true;
      }
      const std::string what = std::to_string(missing.size()) + " of step " + std::to_string(k) +
                               "'s messages " +
                               (damaged.empty() ? "missing" : "damaged or missing");
      for (int e = 0; e < shape.m; ++e)
        machine.faults().detected(machine, path_through(e),
                                  "level 3 (" + what + ": checksum, ALT timeout)");
      if (idle > shape.m) return false;
      request = Resend{missing, {}, damaged};
      for (int e = 0; e < shape.m; ++e)
        if (l3_lost_[std::size_t(e)]) request->lost.push_back(e);
    }
  }

  // Level 3's ALT over the level-2 processors it still listens to, with a timer guard that ends
  // the wait settings.timeout_us after the last message (first_wait_us after the start); a
  // message that stops half-way (InputOrFail) is given up with its processor.
  void receive_step(Process& p, int k, CheckedPivot& pivot, Rows<C>& rows, std::vector<bool>& have,
                    std::vector<int>& damaged, double first_wait_us) {
    const auto ticks = std::int64_t(std::ceil(settings.timeout_us / p.tick_us()));
    std::int64_t after = p.clock() + std::int64_t(std::ceil(first_wait_us / p.tick_us()));
    while (std::find(have.begin(), have.end(), false) != have.end()) {
      std::vector<network::Guard> guards;
      for (int e = 0; e < shape.m; ++e)
        guards.push_back(
            {network::Guard::Kind::input, e_out_[std::size_t(e)], 0, !l3_lost_[std::size_t(e)]});
      guards.push_back({network::Guard::Kind::timer, nullptr, after, true});
      const int g = network::alternate(p, guards);
      if (g == shape.m) return;  // the timer: nothing more is coming
      // A message that has started arrives within its time on the wire, unless a fault stops it.
      auto m = network::in_or_fail(p, *e_out_[std::size_t(g)], p.now_us() + longest_message_us_);
      if (!m) {
        l3_lost_[std::size_t(g)] = true;
        continue;
      }
      after = p.clock() + ticks;
      if (const auto* piv = std::any_cast<CheckedPivot>(&m->payload)) {
        if (piv->step != k) continue;  // a late message of an earlier step
        charge_checksum(p, piv->row.size() + 1);
        if (sum_of(*piv) != piv->checksum) {
          damaged.push_back(g);
          continue;
        }
        pivot = *piv;
        have[0] = true;
        continue;
      }
      const auto& row = std::any_cast<const CheckedRow&>(m->payload);
      if (row.step != k) continue;
      charge_checksum(p, row.values.size());
      if (row.bad || sum_of(row) != row.checksum || row.index < 1 || row.index > rows.size()) {
        damaged.push_back(g);
        continue;
      }
      rows[row.index - 1] = row.values;
      have[row.index] = true;
    }
  }

  // How each message's value changes when a byte of it arrives changed (a corrupting link
  // fault): the header word, the REALs (little-endian words, as the T800 stores them), the
  // checksum. A header of a message without a step (the original protocol's flags) is not
  // modelled.
  static void register_payloads() {
    using t800::flip_byte;
    constexpr std::int64_t size = sizeof(T);
    auto flip_reals = [](Row<C>& values, std::int64_t byte, std::uint8_t mask) {
      const std::size_t i = std::size_t(byte / size);
      if (i >= values.size()) return false;
      values[i] = C(flip_byte(values[i].value(), byte % size, mask));
      return true;
    };
    // A row: its number in the header word, then its REALs.
    auto row_flip = [=](auto* type) {
      using Message = std::remove_pointer_t<decltype(type)>;
      return [=](std::any& a, std::int64_t b, std::uint8_t x) {
        auto& m = std::any_cast<Message&>(a);
        if (b >= kHeaderBytes) return flip_reals(m.values, b - kHeaderBytes, x);
        m.index = std::size_t(flip_byte(std::uint32_t(m.index), b, x));
        return true;
      };
    };
    t800::register_payload_bytes(typeid(RowMessage), row_flip(static_cast<RowMessage*>(nullptr)));
    t800::register_payload_bytes(typeid(ReturnedRow), row_flip(static_cast<ReturnedRow*>(nullptr)));
    t800::register_payload_bytes(
        typeid(PivotMessage), [=](std::any& a, std::int64_t b, std::uint8_t x) {
          auto& m = std::any_cast<PivotMessage&>(a);
          return b >= kHeaderBytes && flip_reals(m.row, b - kHeaderBytes, x);
        });
    t800::register_payload_bytes(
        typeid(CheckedRow), [=](std::any& a, std::int64_t b, std::uint8_t x) {
          auto& m = std::any_cast<CheckedRow&>(a);
          const std::int64_t end = kHeaderBytes + size * std::int64_t(m.values.size());
          if (b < kHeaderBytes) {
            const std::uint32_t header = flip_byte(m.header(), b, x);
            m.step = int(header / 256);
            m.index = header % 256;
          } else if (b < end) {
            flip_reals(m.values, b - kHeaderBytes, x);
          } else {
            m.checksum = flip_byte(m.checksum, b - end, x);
          }
          return true;
        });
    t800::register_payload_bytes(
        typeid(CheckedPivot), [=](std::any& a, std::int64_t b, std::uint8_t x) {
          auto& m = std::any_cast<CheckedPivot&>(a);
          const std::int64_t reals_end = kHeaderBytes + size * std::int64_t(m.row.size());
          if (b < kHeaderBytes) {
            m.step = int(flip_byte(m.header(), b, x));
          } else if (b < reals_end) {
            flip_reals(m.row, b - kHeaderBytes, x);
          } else if (m.step == 0 && b < reals_end + size) {
            m.scale = C(flip_byte(m.scale.value(), b - reals_end, x));
          } else {
            const std::int64_t at = b - reals_end - (m.step == 0 ? size : 0);
            if (at < 0 || at >= 4) return false;
            m.checksum = flip_byte(m.checksum, at, x);
          }
          return true;
        });
  }
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
  return levels_->outcome;
}

template <class T>
void PipelineProgram<T>::finish(Process& client) {
  levels_->finish(client);
}

template <class T>
const PipelineOutcome& PipelineProgram<T>::outcome() const {
  return levels_->outcome;
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
