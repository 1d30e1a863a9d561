#include "workloads/trajectory/trajectory.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "network/input_file.hpp"
#include "t800sim/kernel.hpp"
#include "t800sim/process.hpp"
#include "workloads/setting_error.hpp"

#include "workloads/dynamics/counted.hpp"
#include "workloads/elimination/system.hpp"
#include "workloads/farm/farm_program.hpp"
#include "workloads/integration/integrators.hpp"
#include "workloads/integration/torque.hpp"
#include "workloads/pipeline/pipeline_program.hpp"
#include "workloads/registry.hpp"
#include "workloads/run/operation_mix.hpp"
#include "workloads/run/table_file.hpp"
#include "workloads/trajectory/step_reuse.hpp"

namespace workloads {

namespace {

using dynamics::JointVector;
using t800sim::Process;

struct TrajectorySettings {
  integration::Method method = integration::Method::rk4;
  double dt = 1e-3;
  int steps = 100;
  bool stop_at_limits = false;
  std::string torque = "zero";  // zero | csv | pd
  std::optional<integration::TorqueTable> table;
  integration::PdGains pd;
  JointVector q0 = JointVector::Zero(), qd0 = JointVector::Zero();
  std::string output_csv;
  FarmSettings farm;
  PipelineSettings pipeline;
};

JointVector joint_vector(const Params& p, const std::string& name, bool broadcast = false) {
  const std::vector<double>& v = p.real_list(name);
  const bool one = broadcast && v.size() == 1;
  if (v.size() != dynamics::kJoints && !one)
    throw SettingError({"workload." + name}, "trajectory: workload." + name + " needs " +
                                                 std::to_string(dynamics::kJoints) + " values" +
                                                 (broadcast ? " (or one for every joint)" : "") +
                                                 ", got " + std::to_string(v.size()));
  JointVector out;
  for (int i = 0; i < dynamics::kJoints; ++i) {
    out(i) = v[one ? 0 : std::size_t(i)];
    if (!std::isfinite(out(i)))
      throw SettingError({"workload." + name},
                         "trajectory: workload." + name + " has a non-finite value");
  }
  return out;
}

// A torque table is a few numbers a row; a bound far past any real trajectory's keeps a mistaken
// path (a log, an image) from being read into memory whole.
constexpr std::size_t kMaxTorqueTableBytes = std::size_t(256) << 20;

std::optional<integration::TorqueTable> torque_table(const Params& p) {
  if (p.text("torque") != "csv") return std::nullopt;
  if (p.text("torque_csv").empty())
    throw SettingError({"workload.torque"},
                       "trajectory: workload.torque = \"csv\" needs workload.torque_csv");
  const auto how = p.text("interpolation") == "hold" ? integration::TorqueInterpolation::hold
                                                     : integration::TorqueInterpolation::linear;
  const std::string& path = p.text("torque_csv");
  std::istringstream text;
  try {
    text.str(network::read_input_file(path, kMaxTorqueTableBytes));
  } catch (const network::InputFileError& e) {
    throw SettingError({"workload.torque_csv"},
                       "workload.torque_csv: " + path + ": " + e.what() + " (a torque table, CSV)");
  }
  return integration::TorqueTable::parse(text, path, how);
}

PipelineSettings pipeline_settings(const Params& p) {
  PipelineSettings s;
  s.m = int(p.integer("m"));
  s.precision = *t800::parse_precision(p.text("precision"));
  s.rule.pivoting = *elimination::parse_pivoting(p.text("pivoting"));
  s.rule.threshold = p.real("pivot_threshold");
  return s;
}

TrajectorySettings settings_from(const Params& p) {
  TrajectorySettings s;
  s.method = *integration::parse_method(p.text("integrator"));
  s.dt = p.real("dt");
  s.steps = int(p.integer("steps"));
  s.stop_at_limits = p.flag("stop_at_limits");
  s.torque = p.text("torque");
  s.table = torque_table(p);
  s.pd = {joint_vector(p, "kp", true), joint_vector(p, "kd", true), joint_vector(p, "target")};
  s.q0 = joint_vector(p, "q");
  s.qd0 = joint_vector(p, "qd");
  s.output_csv = p.text("output_csv");
  s.farm.variant = *dynamics::parse_model_variant(p.text("model"));
  s.farm.schedule = "static";
  s.pipeline = pipeline_settings(p);
  return s;
}

// The farm's master is the processor wired to the host; its workers are the P<i> (the pipeline's
// processors have the names PipelineNodes looks for).
int master_of(const network::Topology& t) {
  if (t.host_processor() < 0)
    throw SettingError({kNetworkKey}, "trajectory: the farm's master must be wired to the host");
  return t.host_processor();
}

std::vector<int> farm_workers(const network::Topology& t) {
  std::vector<int> workers;
  for (int i = 0; i < int(t.processors.size()); ++i) {
    const std::string& name = t.processors[std::size_t(i)].name;
    if (i != t.host_processor() && name.size() > 1 && name[0] == 'P') workers.push_back(i);
  }
  return workers;
}

PipelineNodes pipeline_nodes(const network::Topology& t, int m) {
  const int available = level2_count(t);
  if (m < 1 || m > available)
    throw SettingError({"workload.m"}, "trajectory: workload.m = " + std::to_string(m) +
                                           " but the topology " + t.name + " has " +
                                           std::to_string(available) +
                                           " level-2 processors (E1, E2, ...)");
  return find_pipeline_nodes(t, m);
}

// Simulated microseconds from an instant to now, from their exact difference (so that a step of
// the same length gives the same number wherever it lies in time).
double us_since(const Process& p, Process::Instant from) {
  return Process::us_between(from, p.instant());
}

// What results() reports of the steps, gathered as they go: a run's memory does not grow with its
// steps (10^7 may be asked for). The sums are taken in step order, so the means are those of the
// whole list of steps.
struct StepSummary {
  std::int64_t steps = 0;
  StepTimes sum;
  double largest_us = 0;

  void add(const StepTimes& s) {
    ++steps;
    sum.step_us += s.step_us;
    sum.dynamics_us += s.dynamics_us;
    sum.solve_us += s.solve_us;
    sum.integration_us += s.integration_us;
    sum.communication_us += s.communication_us;
    largest_us = std::max(largest_us, s.step_us);
  }
};

// workload.output_csv's columns: t, q, q̇, τ, and the simulated time and split of the step that
// starts at that row (zero on the last row, the final state).
std::vector<std::string> trajectory_columns() {
  std::vector<std::string> columns{"t"};
  for (const char* name : {"q", "qd", "tau"})
    for (int i = 1; i <= dynamics::kJoints; ++i) columns.push_back(name + std::to_string(i));
  for (const char* name :
       {"step_us", "dynamics_us", "solve_us", "integration_us", "communication_us"})
    columns.emplace_back(name);
  return columns;
}

struct LimitViolation {
  int joint = 0;  // 1-based
  int step = 0;   // the step after which the joint was first outside (1-based)
  double value = 0;
};

// A failed solve ends the run; the levels have stopped already.
struct SolveFailed : std::runtime_error {
  using std::runtime_error::runtime_error;
};

template <class S>
class Trajectory : public Workload {
  using C = dynamics::Counted<S>;
  using Vec = dynamics::JointVectorT<S>;

 public:
  Trajectory(const WorkloadContext& c, TrajectorySettings s)
      : model_(require_robot(c)),
        s_(std::move(s)),
        master_(master_of(c.topology)),
        farm_(model_, s_.farm, master_, farm_workers(c.topology)),
        pipeline_(s_.pipeline, pipeline_nodes(c.topology, s_.pipeline.m), dynamics::kJoints) {
    if (!(s_.dt > 0))
      throw SettingError({"workload.dt"}, "trajectory: workload.dt must be positive");
  }

  void build(network::Machine& m) override {
    farm_.build(m);  // never skips numerics: a trajectory integrates its numbers
    pipeline_.build(m, master_, Serve::until_finish);
    integrator_.emplace(t800::ComputeWork{to_operation_mix(integrator_ops()), record_integrator()});
    rhs_.emplace(right_hand_side_work());
    m.declare_code(master_, "master", integrator_->work().code);
    m.declare_code(master_, "master", rhs_->work().code);
    progress_ = m.options().progress;
    skip_numerics_asked_ = m.options().fidelity.skip_numerics;
    reuse_.emplace(m);
    host_ = spawn_host_and_master<S>(m, master_, "initial state", [this](Process& p) { run(p); });
  }

  ResultValue results(const network::Machine&) const override;
  std::vector<OutputTable> tables() const override;

 private:
  // The master's PROC for one integration step, recorded: the state's arrays in, the next state's
  // out (the evaluations of f are the farm's and the pipeline's, not this PROC's).
  std::shared_ptr<const t800::codegen::Recording> record_integrator() const {
    auto recording = std::make_shared<t800::codegen::Recording>("INTEGRATE", sizeof(S) == 8);
    const t800::codegen::RecordingScope scope(*recording);
    integration::State<C> x, next;
    occam::declare(x.q.data(), dynamics::kJoints, "q");
    occam::declare(x.qd.data(), dynamics::kJoints, "qdot");
    occam::declare(next.q.data(), dynamics::kJoints, "q.next");
    occam::declare(next.qd.data(), dynamics::kJoints, "qdot.next");
    const dynamics::JointVectorT<C> zero = dynamics::JointVectorT<C>::Zero();
    const integration::State<C> result = integration::step(
        s_.method, x, C(S(s_.dt)), [&](const auto&, const auto&) { return zero; });
    for (int i = 0; i < dynamics::kJoints; ++i) {
      next.q(i) = result.q(i);
      next.qd(i) = result.qd(i);
    }
    return recording;
  }

  // tau (the PD law, or a table's value) and tau - c - h, the system's right-hand side: the same
  // operations at every evaluation, counted and recorded once.
  t800::ComputeWork right_hand_side_work() const {
    auto recording = std::make_shared<t800::codegen::Recording>("RIGHT.HAND.SIDE", sizeof(S) == 8);
    dynamics::OpTally tally;
    const t800::codegen::RecordingScope scope(*recording);
    dynamics::JointVectorT<C> q, qd, tau, c, h, rhs;
    for (auto* v : {&q, &qd, &tau, &c, &h, &rhs}) v->setConstant(C(S(0.25)));
    occam::declare(q.data(), dynamics::kJoints, "q");
    occam::declare(qd.data(), dynamics::kJoints, "qdot");
    occam::declare(c.data(), dynamics::kJoints, "c");
    occam::declare(h.data(), dynamics::kJoints, "h");
    occam::declare(tau.data(), dynamics::kJoints, "tau");
    occam::declare(rhs.data(), dynamics::kJoints, "rhs");
    if (s_.torque == "pd") {
      const dynamics::JointVectorT<C> law = integration::pd_torque<C>(s_.pd, q, qd);
      for (int i = 0; i < dynamics::kJoints; ++i) tau(i) = law(i);
    }
    for (int i = 0; i < dynamics::kJoints; ++i) rhs(i) = tau(i) - c(i) - h(i);
    return {to_operation_mix(tally.counts()), recording};
  }

  // The integrator's arithmetic does not depend on the data: count one step with an f that costs
  // nothing.
  dynamics::OpCounts integrator_ops() const {
    dynamics::OpTally tally;
    const integration::State<C> x;
    const dynamics::JointVectorT<C> zero = dynamics::JointVectorT<C>::Zero();
    integration::step(s_.method, x, C(S(s_.dt)), [&](const auto&, const auto&) { return zero; });
    return tally.counts();
  }

  void run(Process& p) {
    // Rows go to the file as the steps go (tools/ commits it once the run has ended well).
    if (!s_.output_csv.empty())
      csv_ = std::make_shared<TableFile>(s_.output_csv, "output_csv", trajectory_columns());
    integration::State<S> x{s_.q0.cast<S>(), s_.qd0.cast<S>()};
    check_limits(wide(x.q), 0);  // a start outside the limits is reported as step 0
    try {
      for (int n = 1; n <= s_.steps; ++n) {
        const double t = (n - 1) * s_.dt;
        const integration::State<S> start = x;
        StepTimes times;
        x = advance(p, t, x, times);
        totals_.add(times);
        write_row(t, start, times);
        if (progress_) progress_(n, s_.steps);
        if (!check_limits(wide(x.q), n) && s_.stop_at_limits) break;
      }
    } catch (const SolveFailed& e) {
      failure_ = e.what();
    }
    final_ = x;
    write_row(double(totals_.steps) * s_.dt, x, StepTimes{});
    StepReuse::boundary(p);  // the end is a step boundary too
    farm_.finish(p);
    pipeline_.finish(p);
  }

  // One row of workload.output_csv: the state at t, τ there, the step that starts there.
  void write_row(double t, const integration::State<S>& x, const StepTimes& s) {
    if (!csv_) return;
    const JointVector q = wide(x.q), qd = wide(x.qd), tau = torque(t, q, qd);
    std::vector<double> row{t};
    for (const JointVector* v : {&q, &qd, &tau})
      for (int i = 0; i < dynamics::kJoints; ++i) row.push_back((*v)(i));
    row.insert(row.end(),
               {s.step_us, s.dynamics_us, s.solve_us, s.integration_us, s.communication_us});
    csv_->add(row);
  }

  static JointVector wide(const Vec& v) { return v.template cast<double>(); }

  // The sequential numerics of one step (bit-identical to the farm's and the pipeline's: the same
  // functions in the same order, tests/trajectory) and the step's signature: per evaluation, the
  // solver's status and the original row of every pivot. Those fix every data-dependent cost and
  // branch of a step: the rows simple pivoting tests and the interchanges (both follow from the
  // pivot rows), a failure; the farm (a fixed allocation, costs counted once), τ, the right-hand
  // side and the integrator have none.
  struct Sequential {
    bool solved = true;
    integration::State<S> next;
    std::vector<int> signature;
  };

  // One step, simulated or reused (step_reuse.hpp). The master takes the CPU afresh at every step
  // boundary (a zero-time deschedule and reschedule: its timeslice starts there, whatever came
  // before), so a reused step leaves the scheduler as a simulated one does.
  integration::State<S> advance(Process& p, double t, const integration::State<S>& x,
                                StepTimes& times) {
    StepReuse::boundary(p);
    std::optional<Sequential> seq;
    if (reuse_->enabled()) {
      // The step's numbers by the sequential numerics, and with them its signature: every
      // data-dependent branch of the step.
      seq = sequential(t, x);
      if (reuse_->replay(p, seq->signature, seq->solved ? "" : "the sequential solve failed",
                         times))
        return seq->next;
    }
    reuse_->simulating();
    simulated_signature_.clear();
    integration::State<S> next;
    try {
      next = step(p, t, x, times);
    } catch (const SolveFailed&) {
      reuse_->failed("the pipeline's solve failed");
      throw;
    }
    if (seq) reuse_->simulated(seq->signature, disagreement(*seq, next), times);
    return next;
  }

  // Why the simulated step's numbers may not stand for its signature: empty when they are the
  // sequential numerics' (the pivots and the state).
  std::string disagreement(const Sequential& seq, const integration::State<S>& next) const {
    if (simulated_signature_ != seq.signature)
      return "the pipeline's pivots differ from the sequential solver's";
    for (int i = 0; i < dynamics::kJoints; ++i)
      if (!(next.q(i) == seq.next.q(i) && next.qd(i) == seq.next.qd(i)))
        return "the simulated state differs from the sequential numerics'";
    return {};
  }

  // The farm's numbers come from its host-side evaluation (FarmProgram::evaluate_on_host: the
  // workers' values, bit for bit), the solve from the sequential solver.
  Sequential sequential(double t, const integration::State<S>& x) {
    Sequential out;
    const double* offsets = integration::stage_offsets(s_.method);
    int stage = 0;
    auto f = [&](const Vec& q, const Vec& qd) {
      const double at = t + offsets[stage++] * s_.dt;
      const JointVector qw = wide(q), qdw = wide(qd);
      dynamics::DynamicsData<S> data;
      farm_.evaluate_on_host(qw, qdw, data);
      const elimination::LinearSystem<S> system =
          elimination::dynamics_system<S>(data, torque(at, qw, qdw));
      const elimination::Solution<S> solution =
          elimination::solve(system.a, system.b, s_.pipeline.rule);
      append_signature(out.signature, solution.status, solution.pivot_rows);
      Vec qdd = Vec::Zero();
      if (!elimination::solved(solution.status)) {
        out.solved = false;
        return qdd;
      }
      for (int i = 0; i < dynamics::kJoints; ++i) qdd(i) = solution.x[std::size_t(i)];
      return qdd;
    };
    out.next = integration::step(s_.method, x, S(s_.dt), f);
    return out;
  }

  static void append_signature(std::vector<int>& signature, elimination::Status status,
                               const std::vector<int>& pivot_rows) {
    signature.push_back(int(status));
    signature.insert(signature.end(), pivot_rows.begin(), pivot_rows.end());
  }

  integration::State<S> step(Process& p, double t, const integration::State<S>& x,
                             StepTimes& times) {
    const Process::Instant start = p.instant();
    const double* offsets = integration::stage_offsets(s_.method);
    int stage = 0;
    auto f = [&](const Vec& q, const Vec& qd) {
      return acceleration(p, t + offsets[stage++] * s_.dt, q, qd, times);
    };
    const integration::State<S> next = integration::step(s_.method, x, S(s_.dt), f);
    const Process::Instant before = p.instant();
    p.compute(*integrator_, "integrate");
    times.integration_us += us_since(p, before);
    times.step_us = us_since(p, start);
    times.communication_us =
        times.step_us - times.dynamics_us - times.solve_us - times.integration_us;
    return next;
  }

  // One evaluation: τ, the farm's D, c, h, the right-hand side, the pipeline's q̈.
  Vec acceleration(Process& p, double t, const Vec& q, const Vec& qd, StepTimes& times) {
    const Process::Instant round_start = p.instant();
    farm_.evaluate(p, wide(q), wide(qd), data_);
    times.dynamics_us += us_since(p, round_start);
    Vec rhs;
    const dynamics::JointVectorT<C> tau = counted_torque(t, wide(q), wide(qd));
    const dynamics::JointVectorT<C> r =
        tau - data_.c.template cast<C>() - data_.h.template cast<C>();
    for (int i = 0; i < dynamics::kJoints; ++i) rhs(i) = r(i).value();
    const Process::Instant before = p.instant();
    p.compute(*rhs_, "right-hand side");
    times.integration_us += us_since(p, before);
    return solve(p, rhs, times);
  }

  Vec solve(Process& p, const Vec& rhs, StepTimes& times) {
    const PipelineOutcome& o = pipeline_.solve(p, elimination::from_eigen<S>(data_.D, rhs));
    if (!elimination::solved(o.status))
      throw SolveFailed("the pipeline failed at t = " + std::to_string(p.now_us()) +
                        " us: " + o.failure);
    times.solve_us += o.tp_us();
    append_signature(simulated_signature_, o.status, o.pivot_rows);
    Vec qdd;
    for (int i = 0; i < dynamics::kJoints; ++i) qdd(i) = S(o.qdd[std::size_t(i)]);
    return qdd;
  }

  // τ rounded to S, as elimination::dynamics_system rounds it; the PD law counts its operations.
  dynamics::JointVectorT<C> counted_torque(double t, const JointVector& q,
                                           const JointVector& qd) const {
    if (s_.torque != "pd") return torque(t, q, qd).template cast<S>().template cast<C>();
    using D = dynamics::Counted<double>;
    const dynamics::JointVectorT<D> tau =
        integration::pd_torque<D>(s_.pd, q.template cast<D>(), qd.template cast<D>());
    dynamics::JointVectorT<C> out;
    for (int i = 0; i < dynamics::kJoints; ++i) out(i) = C(S(tau(i).value()));
    return out;
  }

  JointVector torque(double t, const JointVector& q, const JointVector& qd) const {
    if (s_.torque == "pd") return integration::pd_torque<double>(s_.pd, q, qd);
    if (s_.torque == "csv") return s_.table->at(t);
    return JointVector::Zero();
  }

  // Records each joint's exit from its limits (not every step it stays out); true when inside.
  bool check_limits(const JointVector& q, int n) {
    bool inside = true;
    for (int i = 0; i < dynamics::kJoints; ++i) {
      const dynamics::JointLimits& l = model_.joints[std::size_t(i)].limits;
      const bool out = !(q(i) >= l.min && q(i) <= l.max);
      if (out && !outside_[std::size_t(i)]) violations_.push_back({i + 1, n, q(i)});
      outside_[std::size_t(i)] = out;
      inside = inside && !out;
    }
    if (!inside) ++steps_outside_;
    return inside;
  }

  ResultValue split() const;

  const dynamics::RobotModel& model_;
  TrajectorySettings s_;
  int master_;
  FarmProgram<S> farm_;
  PipelineProgram<S> pipeline_;
  std::optional<t800sim::Kernel> integrator_, rhs_;  // recorded at build()
  dynamics::DynamicsData<S> data_;
  bool skip_numerics_asked_ = false;
  std::optional<StepReuse> reuse_;          // from the machine's options, at build()
  std::unique_ptr<t800sim::Builder> host_;  // the initial state's channel, host -> master
  std::vector<int> simulated_signature_;    // the pipeline's pivots in the step being simulated
  StepSummary totals_;                      // of the steps run
  integration::State<S> final_;             // the state after the last step run
  std::shared_ptr<TableFile> csv_;          // workload.output_csv, when asked for
  std::vector<LimitViolation> violations_;
  std::array<bool, dynamics::kJoints> outside_{};
  int steps_outside_ = 0;
  std::string failure_;
  std::function<void(std::int64_t, std::int64_t)> progress_;
};

ResultValue joint_values(const JointVector& v) {
  ResultValue out = ResultValue::list();
  for (int i = 0; i < dynamics::kJoints; ++i) out.push(v(i));
  return out;
}

// The mean of each part of the step time.
template <class S>
ResultValue Trajectory<S>::split() const {
  const double n = std::max<double>(1, double(totals_.steps));
  ResultValue out;
  out.set("dynamics_us", totals_.sum.dynamics_us / n);
  out.set("solve_us", totals_.sum.solve_us / n);
  out.set("integration_us", totals_.sum.integration_us / n);
  out.set("communication_us", totals_.sum.communication_us / n);
  return out;
}

template <class S>
ResultValue Trajectory<S>::results(const network::Machine&) const {
  const double mean = totals_.steps ? totals_.sum.step_us / double(totals_.steps) : 0;
  ResultValue r;
  r.set("integrator", integration::to_string(s_.method));
  r.set("evaluations_per_step", integration::evaluations_per_step(s_.method));
  r.set("torque", s_.torque);
  r.set("model", dynamics::to_string(s_.farm.variant));
  r.set("precision", std::string(t800::to_string(s_.pipeline.precision)));
  r.set("pivoting", elimination::to_string(s_.pipeline.rule.pivoting));
  r.set("m", pipeline_.settings().m);
  r.set("workers", std::int64_t(farm_.workers().size()));
  r.set("steps", totals_.steps);
  r.set("steps_requested", s_.steps);
  r.set("dt", s_.dt);
  r.set("mean_step_us", mean);
  r.set("max_step_us", totals_.largest_us);
  r.set("split_mean_us", split());
  r.set("real_time_factor", mean / (s_.dt * 1e6));
  ResultValue exits = ResultValue::list();
  for (const LimitViolation& v : violations_) {
    ResultValue e;
    e.set("joint", v.joint);
    e.set("step", v.step);
    e.set("value", v.value);
    exits.push(e);
  }
  r.set("limit_violations", exits);
  r.set("steps_outside_limits", steps_outside_);
  if (!failure_.empty()) r.set("failure", failure_);
  r.set("step_reuse", reuse_->report());
  if (skip_numerics_asked_)
    r.set("numerics",
          "computed: fidelity.skip_numerics is ignored, a trajectory integrates its numbers and "
          "its pivots can change the schedule");
  r.set("final_q", joint_values(wide(final_.q)));
  r.set("final_qd", joint_values(wide(final_.qd)));
  if (!s_.output_csv.empty()) r.set("output_csv", s_.output_csv);  // written by tools/ (tables())
  return r;
}

// workload.output_csv, written row by row during the run (write_row).
template <class S>
std::vector<OutputTable> Trajectory<S>::tables() const {
  if (!csv_) return {};
  return {OutputTable{"output_csv", {}, {}, csv_}};
}

}  // namespace

std::unique_ptr<Workload> make_trajectory(const WorkloadContext& c) {
  TrajectorySettings s = settings_from(c.params);
  if (s.pipeline.precision == t800::Precision::real64)
    return std::make_unique<Trajectory<double>>(c, std::move(s));
  return std::make_unique<Trajectory<float>>(c, std::move(s));
}

namespace {
using T = ParamType;
// clang-format off
const Registration registered_trajectory{
    WorkloadInfo{"trajectory",
     "forward dynamics end to end: the dynamics farm, the elimination pipeline and an integrator on the farm's "
     "master, step by step (workloads/trajectory/trajectory.hpp)",
     {
         {"robot", T::robot_file, std::string{"../robots/stanford.toml"}, "robot model file, relative to the scene",
          {}, {}, {}},
         {"model", T::text, std::string{"full"},
          "dynamics model: \"full\" (every non-zero term) or \"paper\" (64 subtasks, joint-6 Coriolis terms "
          "dropped)",
          {}, {}, {"paper", "full"}},
         {"precision", T::precision, std::string{"real32"}, "occam REAL32 or REAL64 arithmetic", {}, {}, {}},
         {"m", T::integer, std::int64_t{3}, "level-2 processors E1..Em of the pipeline", 1, 64, {}},
         {"pivoting", T::text, std::string{"simple"},
          "\"simple\" (the paper: interchange only when the pivot is unusable) or \"partial\"", {}, {},
          {"simple", "partial"}},
         {"pivot_threshold", T::real, 0.0,
          "a pivot p is unusable when |p| <= pivot_threshold * max|a_ij|; 0 = only an exact zero", 0.0, 1.0, {}},
         {"integrator", T::text, std::string{"rk4"},
          "\"rk4\" (4 evaluations per step) or \"semi-implicit-euler\" (1 evaluation per step)", {}, {},
          {"rk4", "semi-implicit-euler"}},
         {"steps", T::integer, std::int64_t{100}, "integrator steps", 1, 1e7, {}},
         {"dt", T::real, 1e-3, "step, s", 1e-9, 10.0, {}},
         {"torque", T::text, std::string{"zero"},
          "\"zero\" (passive), \"csv\" (workload.torque_csv) or \"pd\" (kp, kd to target)", {}, {},
          {"zero", "csv", "pd"}},
         {"torque_csv", T::input_file, std::string{},
          "torque table, relative to the scene: header t,tau1,...,tau6, then rows with t increasing", {}, {}, {}},
         {"interpolation", T::text, std::string{"linear"},
          "torque table between rows: \"linear\" or \"hold\" (zero-order hold); held beyond its ends", {}, {},
          {"linear", "hold"}},
         // The defaults: critically damped at 10 rad/s for the Stanford arm at the scene's start, kp_i =
         // 100 D_ii and kd_i = 20 D_ii (D from `t800sim dynamics --q 0.1,0.2,0.5,0.3,0.4,0.5`). One gain
         // for every joint does not suit an arm whose inertias span 0.0003 to 156 kg m^2: kd = 20 on the
         // wrist's 0.0003 is a rate of 67,000 /s, and 1 ms RK4 steps diverge.
         {"kp", T::real_list, std::vector<double>{1099.0, 15561.0, 647.0, 22.45, 144.9, 0.03},
          "PD proportional gains, one or six values (default: 100 D_ii of the Stanford arm at the scene's start)", {}, {}, {}},
         {"kd", T::real_list, std::vector<double>{219.8, 3112.3, 129.4, 4.491, 28.99, 0.006},
          "PD derivative gains, one or six values (default: 20 D_ii of the Stanford arm at the scene's start)", {}, {}, {}},
         {"target", T::real_list, std::vector<double>{0.0, 0.0, 0.5, 0.0, 0.0, 0.0}, "PD target q", {}, {}, {}},
         {"q", T::real_list, std::vector<double>{0.1, 0.2, 0.5, 0.3, 0.4, 0.5}, "initial joint positions", {}, {},
          {}},
         {"qd", T::real_list, std::vector<double>{0.0, 0.0, 0.0, 0.0, 0.0, 0.0}, "initial joint rates", {}, {}, {}},
         {"stop_at_limits", T::flag, false,
          "stop at the first step that leaves the joint limits (reported either way, never clamped)", {}, {}, {}},
         {"output_csv", T::output_file, std::string{},
          "trajectory CSV (t, q, qd, tau, step_us and its split), relative to the scene; empty = none", {}, {}, {}},
     }},
    make_trajectory};
// clang-format on
}  // namespace

}  // namespace workloads
