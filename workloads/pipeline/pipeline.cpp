#include "workloads/pipeline/pipeline.hpp"

#include <algorithm>
#include <stdexcept>

#include "sdk/realise.hpp"
#include "workloads/setting_error.hpp"

namespace workloads {

// The pipeline on scalar T (float = REAL32, double = REAL64), fed once by the host.
class EliminationPipeline::Engine {
 public:
  virtual ~Engine() = default;
  virtual void build(network::Machine& machine) = 0;
  virtual ResultValue sequential_check() const = 0;
  virtual const PipelineOutcome& outcome() const = 0;
  virtual const PipelineSettings& settings() const = 0;
  virtual const PipelineShape& shape() const = 0;
};

namespace {

template <class T>
class EngineT : public EliminationPipeline::Engine {
 public:
  EngineT(const PipelineSettings& s, const elimination::LinearSystem<double>& system,
          const PipelineNodes& nodes)
      : system_(elimination::convert<T>(system)),
        program_(s, nodes, static_cast<int>(system.size())) {}

  // The host sends the system and is done: Tp ends on L4, and nothing moves after it.
  void build(network::Machine& machine) override {
    program_.build(machine, network::Machine::kHost, Serve::once);
    t800sim::detail::spawn("elimination pipeline", machine, network::Machine::kHost, "host",
                           [this](t800sim::Process& p) { program_.send(p, system_); });
  }

  ResultValue sequential_check() const override {
    const elimination::Solution<T> s = elimination::solve(system_.a, system_.b, settings().rule);
    const PipelineOutcome& o = outcome();
    bool same = s.status == o.status && s.x.size() == o.qdd.size();
    for (std::size_t i = 0; same && i < s.x.size(); ++i)
      same = static_cast<double>(s.x[i]) == o.qdd[i];
    return ResultValue(same);
  }

  const PipelineOutcome& outcome() const override { return program_.outcome(); }
  const PipelineSettings& settings() const override { return program_.settings(); }
  const PipelineShape& shape() const override { return program_.shape(); }

 private:
  elimination::LinearSystem<T> system_;
  PipelineProgram<T> program_;
};

}  // namespace

namespace {

// Recovery (PipelineSettings::recovery) runs on strict, unbuffered steps with every level-2
// processor L1's and L3's neighbour (no relays).
void check_recovery(const PipelineSettings& s, const PipelineNodes& nodes,
                    const network::Topology& topology) {
  if (s.overlap || s.buffered)
    throw SettingError({"workload.recovery", s.overlap ? "workload.overlap" : "workload.buffered"},
                       "workload.recovery needs strict, unbuffered steps (overlap = false, "
                       "buffered = false)");
  auto neighbours = [&](int a, int b) { return topology.shortest_path(a, b).size() == 2; };
  for (int e : nodes.e)
    if (!neighbours(nodes.l1, e) || !neighbours(nodes.l3, e))
      throw SettingError({"workload.recovery", kNetworkKey},
                         "workload.recovery needs every level-2 processor wired to L1 and L3 (no "
                         "fan-out X or fan-in Y: configs/topologies/elimination-m1..m3.toml)");
}

}  // namespace

EliminationPipeline::EliminationPipeline(const PipelineSettings& settings,
                                         const elimination::LinearSystem<double>& system,
                                         const network::Topology& topology) {
  if (system.size() < 1) throw SettingError({"workload.b"}, "elimination: empty system");
  PipelineSettings s = settings;
  const int available = level2_count(topology);
  if (s.m == 0) s.m = available;
  if (s.m < 1 || s.m > available)
    throw SettingError({"workload.m"},
                       "elimination: workload.m = " + std::to_string(settings.m) +
                           " but the topology " + topology.name + " has " +
                           std::to_string(available) +
                           " level-2 processors (E1, E2, ...); give workload.m from 1 to " +
                           std::to_string(available) + ", or a topology with more: " +
                           (settings.m >= 1 && settings.m <= 5
                                ? "--set network.topology=../topologies/elimination-m" +
                                      std::to_string(settings.m) + ".toml"
                                : std::string("topologies ship for m = 1..5 "
                                              "(configs/topologies/elimination-m1..m5.toml)")));
  const PipelineNodes nodes = find_pipeline_nodes(topology, s.m);
  if (s.recovery) check_recovery(s, nodes, topology);
  if (s.precision == t800::Precision::real64)
    engine_ = std::make_unique<EngineT<double>>(s, system, nodes);
  else
    engine_ = std::make_unique<EngineT<float>>(s, system, nodes);
}

EliminationPipeline::~EliminationPipeline() = default;

void EliminationPipeline::build(network::Machine& machine) {
  if (machine.options().precision != engine_->settings().precision)
    throw std::invalid_argument("elimination: the machine's precision differs from the workload's");
  engine_->build(machine);
}

const PipelineOutcome& EliminationPipeline::outcome() const {
  return engine_->outcome();
}
int EliminationPipeline::m() const {
  return engine_->settings().m;
}

ResultValue EliminationPipeline::results(const network::Machine& machine) const {
  const PipelineOutcome& o = engine_->outcome();
  const PipelineSettings& s = engine_->settings();
  ResultValue r;
  r.set("m", s.m);
  r.set("n", engine_->shape().n);
  r.set("precision", std::string(t800::to_string(s.precision)));
  r.set("pivoting", elimination::to_string(s.rule.pivoting));
  r.set("pivot_threshold", s.rule.threshold);
  r.set("growth_limit", s.rule.growth_limit);
  r.set("status", elimination::to_string(o.status));
  if (!o.failure.empty()) r.set("failure", o.failure);
  r.set("tp_ms", o.tp_us() / 1000.0);
  r.set("tp_us", o.tp_us());
  r.set("input_us", o.start_us - o.input_start_us);
  // Other windows one might read as Table 6's Tp: L1 having the system until L4 has every row of
  // U (Tp without the back substitution), and level 2's own window (the first pivot row reaching
  // a level-2 processor until the last row leaves one); 0 when the round failed before.
  r.set("elimination_us", o.eliminated_us > 0 ? o.eliminated_us - o.start_us : 0.0);
  r.set("level2_window_us",
        o.level2_first_us >= 0 ? std::max(0.0, o.level2_last_us - o.level2_first_us) : 0.0);
  r.set("buffered", s.buffered);
  r.set("overlap", s.overlap);
  if (machine.options().fidelity.skip_numerics)
    r.set("numerics",
          "computed: fidelity.skip_numerics does not apply -- the pipeline's schedule depends on "
          "the data "
          "(row interchanges, a failed pivot), and its arithmetic costs microseconds of wall time");
  ResultValue qdd = ResultValue::list();
  for (double v : o.qdd) qdd.push(v);
  r.set("qdd", qdd);
  ResultValue pivots = ResultValue::list();
  for (int row : o.pivot_rows) pivots.push(row + 1);
  r.set("pivot_rows", pivots);
  r.set("interchanges", o.interchanges);
  r.set("growth", o.growth);
  r.set("matches_sequential", engine_->sequential_check());
  ResultValue steps = ResultValue::list();
  for (double t : o.step_start_us) steps.push(t - o.start_us);
  r.set("step_start_us", steps);
  ResultValue channels = ResultValue::list();
  for (const auto& c : machine.channels()) {
    std::string path;
    for (int node : c->path) path += (path.empty() ? "" : "-") + machine.node_name(node);
    ResultValue ch;
    ch.set("name", c->name);
    ch.set("kind", c->transport->kind_name());
    ch.set("path", path);
    channels.push(ch);
  }
  r.set("channels", channels);
  return r;
}

}  // namespace workloads
