#include "workloads/farm/dynamics_farm.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "workloads/setting_error.hpp"

#include "workloads/farm/farm_program.hpp"
#include "workloads/registry.hpp"

namespace workloads {

namespace {

using dynamics::JointVector;

JointVector joint_vector(const Params& p, const std::string& name) {
  const std::vector<double>& v = p.real_list(name);
  if (v.size() != dynamics::kJoints)
    throw SettingError({"workload." + name}, "workload." + name + " needs " +
                                                 std::to_string(dynamics::kJoints) +
                                                 " values, got " + std::to_string(v.size()));
  JointVector out;
  for (int i = 0; i < dynamics::kJoints; ++i) {
    if (!std::isfinite(v[i]))
      throw SettingError({"workload." + name}, "workload." + name + " has a non-finite value");
    out(i) = v[i];
  }
  return out;
}

// The master is the processor wired to the host; every other processor is a worker.
std::vector<int> workers_of(const network::Topology& t) {
  std::vector<int> workers;
  for (int i = 0; i < int(t.processors.size()); ++i)
    if (i != t.host_processor()) workers.push_back(i);
  return workers;
}

int master_of(const network::Topology& t) {
  if (t.host_processor() < 0)
    throw SettingError({kNetworkKey}, "the farm's master must be wired to the host");
  return t.host_processor();
}

// One evaluation: the host sends (q, q̇) to the master, the farm computes D, C, c, h. Tp is the
// window the scene chose (workload.tp_window); both windows are reported.
template <class S>
class DynamicsFarm : public Workload {
 public:
  DynamicsFarm(const WorkloadContext& c)
      : program_(require_robot(c), settings(c.params), master_of(c.topology),
                 workers_of(c.topology)),
        farm_window_(c.params.text("tp_window") == "farm"),
        precision_(c.params.text("precision")),
        q_(joint_vector(c.params, "q")),
        qd_(joint_vector(c.params, "qd")) {
    if (!dynamics::within_limits(require_robot(c), q_))
      throw SettingError({"workload.q"},
                         "workload.q is outside the joint limits of " + require_robot(c).name);
  }

  void build(network::Machine& m) override {
    // A timing-only scene (Table 4 needs Tp alone) may skip the values: the farm's schedule,
    // message sizes and costs do not depend on them (FarmSettings::skip_numerics).
    program_.set_skip_numerics(m.options().fidelity.skip_numerics);
    program_.build(m);
    host_ =
        spawn_host_and_master<S>(m, master_of(m.topology()), "state", [this](t800sim::Process& p) {
          round_ = program_.evaluate(p, q_, qd_, data_);
          program_.finish(p);
        });
  }

  ResultValue results(const network::Machine& m) const override {
    ResultValue r;
    r.set("model", dynamics::to_string(settings_.variant));
    r.set("schedule", settings_.schedule);
    r.set("precision", precision_);
    r.set("subtasks", std::int64_t(program_.work().tasks.size()));
    r.set("workers", std::int64_t(program_.workers().size()));
    const double origin = farm_window_ ? round_.farm_start_us : round_.start_us;
    const double tp_us =
        farm_window_ ? round_.farm_end_us - round_.farm_start_us : round_.end_us - round_.start_us;
    r.set("tp_window", farm_window_ ? "farm" : "evaluation");
    r.set("tp_us", tp_us);
    r.set("tp_ms", tp_us / 1000.0);
    r.set("evaluation_us", round_.end_us - round_.start_us);
    r.set("farm_us", round_.farm_end_us - round_.farm_start_us);
    r.set("per_worker", per_worker(m, origin, tp_us));
    if (program_.skips_numerics()) {
      r.set("numerics",
            "skipped (fidelity.skip_numerics): no subtask was evaluated, so D, c and h are "
            "absent; the timing is the same, from the costs counted when the farm was built");
      return r;
    }
    r.set("D", matrix_value());
    r.set("c", vector_value(data_.c));
    r.set("h", vector_value(data_.h));
    return r;
  }

 private:
  FarmSettings settings(const Params& p) {
    settings_.variant = *dynamics::parse_model_variant(p.text("model"));
    settings_.schedule = p.text("schedule");
    settings_.allocation = p.text("allocation");
    settings_.buffer = int(p.integer("buffer"));
    settings_.recovery = p.flag("recovery");
    settings_.timeout_us = p.real("recovery_timeout_us");
    return settings_;
  }

  // Utilisation as the paper defines it: the worker's busy time within Tp, over Tp.
  ResultValue per_worker(const network::Machine& m, double origin, double tp_us) const {
    ResultValue rows = ResultValue::list();
    const auto& workers = program_.workers();
    for (std::size_t w = 0; w < workers.size(); ++w) {
      const t800::ProcessorActivity& a = m.transputer(workers[w]).activity();
      const double busy = farm_window_ ? round_.busy_in_farm_us[w] : a.busy_us();
      ResultValue row;
      row.set("name", m.node_name(workers[w]));
      row.set("busy_us", a.busy_us());
      row.set("compute_us", a.compute_us());
      row.set("busy_in_tp_us", busy);
      row.set("utilisation_pct", 100.0 * busy / tp_us);
      // When it last stopped working, from the start of Tp; a worker that did nothing in Tp (no
      // subtask, nothing to route) was done when Tp began.
      row.set("end_us", std::max(0.0, a.last_busy_us() - origin));
      ResultValue names = ResultValue::list();
      for (int t : program_.done_by()[w]) names.push(program_.work().tasks[t].subtask.name);
      row.set("subtasks", names);
      rows.push(row);
    }
    return rows;
  }

  ResultValue matrix_value() const {
    ResultValue rows = ResultValue::list();
    for (int i = 0; i < dynamics::kJoints; ++i) {
      ResultValue row = ResultValue::list();
      for (int j = 0; j < dynamics::kJoints; ++j) row.push(double(data_.D(i, j)));
      rows.push(row);
    }
    return rows;
  }

  static ResultValue vector_value(const dynamics::JointVectorT<S>& v) {
    ResultValue out = ResultValue::list();
    for (int i = 0; i < dynamics::kJoints; ++i) out.push(double(v(i)));
    return out;
  }

  FarmSettings settings_;
  FarmProgram<S> program_;
  bool farm_window_;
  std::string precision_;
  JointVector q_, qd_;
  FarmRound round_;
  dynamics::DynamicsData<S> data_;
  std::unique_ptr<t800sim::Builder> host_;  // the state's channel, host -> master
};

}  // namespace

std::unique_ptr<Workload> make_dynamics_farm(const WorkloadContext& c) {
  if (c.params.text("precision") == "real64") return std::make_unique<DynamicsFarm<double>>(c);
  return std::make_unique<DynamicsFarm<float>>(c);
}

namespace {
using T = ParamType;
// clang-format off
const Registration registered_dynamics_farm{
    WorkloadInfo{"dynamics-farm",
     "one forward-dynamics evaluation (D, C, h of the robot) farmed from a master to workers",
     {
         {"robot", T::robot_file, std::string{"../robots/stanford.toml"}, "robot model file, relative to the scene",
          {}, {}, {}},
         {"model", T::text, std::string{"paper"},
          "\"paper\" (64 subtasks, joint-6 Coriolis terms dropped) or \"full\" (every non-zero term)", {}, {},
          {"paper", "full"}},
         {"schedule", T::text, std::string{"static"},
          "\"static\" (pre-computed list schedule), \"on-demand\" (workers ask for work) or \"explicit\" "
          "(workload.allocation)",
          {}, {}, {"static", "on-demand", "explicit"}},
         {"allocation", T::text, std::string{}, "explicit allocation: \"P1: D11 D12 h2; P2: C1_23 ...\"", {},
          {}, {}},
         {"precision", T::precision, std::string{"real32"}, "occam REAL32 or REAL64 arithmetic", {}, {}, {}},
         {"tp_window", T::text, std::string{"farm"},
          "what Tp covers: \"farm\" (first input sent to last result received) or \"evaluation\" (state "
          "received to D, C, c, h assembled, with the master's sin/cos and assembly)",
          {}, {}, {"farm", "evaluation"}},
         {"buffer", T::integer, std::int64_t{2}, "on-demand: subtasks in flight per worker (1 = no buffering)",
          1, 8, {}},
         {"recovery", T::flag, false,
          "recover from a halted or unreachable worker: the master's exchanges with each worker give up "
          "at a deadline and its subtasks go to the others (README \"Faults\")", {}, {}, {}},
         {"recovery_timeout_us", T::real, 0.0,
          "recovery: how long past a worker's predicted time the master waits (0: that time again + 50 us)",
          0, 1e9, {}},
         {"q", T::real_list, std::vector<double>{0.1, 0.2, 0.5, 0.3, 0.4, 0.5},
          "joint positions (rad, q3 in m); default: the README's reference state", {}, {}, {}},
         {"qd", T::real_list, std::vector<double>{0.1, -0.2, 0.05, 0.3, -0.1, 0.2}, "joint rates", {}, {}, {}},
     }},
    make_dynamics_farm};
// clang-format on
}  // namespace

}  // namespace workloads
