#include "tools/stress.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "tools/paper_data.hpp"
#include "tools/robot_file.hpp"
#include "tools/stress_matrices.hpp"
#include "workloads/dynamics/state.hpp"
#include "workloads/dynamics/subtask_set.hpp"
#include "workloads/elimination/system.hpp"
#include "workloads/integration/trajectory.hpp"

namespace tools {

namespace {

using elimination::LinearSystem;
using elimination::Pivoting;
using elimination::PivotRule;
using elimination::Status;
using workloads::ResultValue;
using VectorL = std::vector<long double>;

// ---- one solve, measured ----

// Unit roundoff of each precision, and the loss that counts as an algorithmic failure: a backward
// error above sqrt(u) means elimination threw away half the digits the data had.
double unit_roundoff(bool real64) {
  return real64 ? 0x1p-53 : 0x1p-24;
}
double inaccurate_above(bool real64) {
  return std::sqrt(unit_roundoff(real64));
}

struct Strategy {
  std::string name;  // "simple", "simple+threshold", "partial"
  PivotRule rule;
  bool real64 = true;
};

struct Trial {
  Status status = Status::ok;
  double forward = 0, backward = 0, growth = 1, smallest_pivot = 0;
  int interchanges = 0;
};

long double norm_inf(const VectorL& v) {
  long double m = 0;
  for (long double x : v) m = std::max(m, std::fabs(x));
  return m;
}

// Normwise backward error (Rigal-Gaches, infinity norm) of x for the data the solver saw.
template <class S>
long double backward_error(const LinearSystem<S>& s, const VectorL& x) {
  long double residual = 0, a_norm = 0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    long double r = elimination::value_of(s.b[i]), row = 0;
    for (std::size_t j = 0; j < s.size(); ++j) {
      r -= elimination::value_of(s.a[i][j]) * x[j];
      row += std::fabs(elimination::value_of(s.a[i][j]));
    }
    residual = std::max(residual, std::fabs(r));
    a_norm = std::max(a_norm, row);
  }
  long double b_norm = 0;
  for (const S& v : s.b) b_norm = std::max(b_norm, std::fabs(elimination::value_of(v)));
  return residual / (a_norm * norm_inf(x) + b_norm);
}

template <class S>
Trial solve_trial(const LinearSystem<double>& data, const PivotRule& rule,
                  const VectorL& reference) {
  const LinearSystem<S> seen = elimination::convert<S>(data);
  const elimination::Solution<S> s = elimination::solve(seen.a, seen.b, rule);
  Trial t;
  t.status = s.status;
  t.growth = double(s.growth);
  t.smallest_pivot = double(s.smallest_pivot);
  t.interchanges = s.interchanges;
  if (!elimination::solved(s.status)) return t;
  VectorL x, difference;
  for (std::size_t i = 0; i < s.x.size(); ++i) {
    x.push_back(elimination::value_of(s.x[i]));
    difference.push_back(x.back() - reference[i]);
  }
  t.forward = double(norm_inf(difference) / norm_inf(reference));
  t.backward = double(backward_error(seen, x));
  return t;
}

Trial run_trial(const Strategy& strategy, const LinearSystem<double>& data,
                const VectorL& reference) {
  return strategy.real64 ? solve_trial<double>(data, strategy.rule, reference)
                         : solve_trial<float>(data, strategy.rule, reference);
}

// The long double solution (partial pivoting) of the REAL64 data: the reference every error is
// measured against.
VectorL reference_solution(const LinearSystem<double>& data) {
  PivotRule partial;
  partial.pivoting = Pivoting::partial;
  const auto s = elimination::solve(elimination::convert<long double>(data).a,
                                    elimination::convert<long double>(data).b, partial);
  if (!elimination::solved(s.status)) return {};
  return VectorL(s.x.begin(), s.x.end());
}

// ---- statistics ----

double median(std::vector<double> v) {
  if (v.empty()) return std::nan("");
  std::nth_element(v.begin(), v.begin() + std::ptrdiff_t(v.size() / 2), v.end());
  return v[v.size() / 2];
}

double max_of(const std::vector<double>& v) {
  return v.empty() ? std::nan("") : *std::max_element(v.begin(), v.end());
}

ResultValue spread(const std::vector<double>& v) {
  ResultValue r;
  r.set("median", median(v));
  r.set("max", max_of(v));
  return r;
}

// Everything one strategy did over a set of systems.
struct Tally {
  Strategy strategy;
  std::vector<double> forward, backward;
  double growth_max = 1;
  double smallest_pivot = std::numeric_limits<double>::infinity();
  long interchanges = 0, ok = 0, unstable = 0, no_pivot = 0, non_finite = 0;
  long inaccurate = 0;         // solved, backward error above sqrt(u)
  long silent_inaccurate = 0;  // ... and reported as ok
  long growth_flagged = 0;     // growth above 1/sqrt(u): what the growth check reports
  long missed_by_growth = 0;   // inaccurate, yet growth below the limit

  void add(const Trial& t) {
    interchanges += t.interchanges;
    growth_max = std::max(growth_max, t.growth);
    if (t.smallest_pivot > 0) smallest_pivot = std::min(smallest_pivot, t.smallest_pivot);
    count_status(t.status);
    if (!elimination::solved(t.status)) return;
    forward.push_back(t.forward);
    backward.push_back(t.backward);
    const bool bad = t.backward > inaccurate_above(strategy.real64);
    const bool flagged = t.growth > 1 / inaccurate_above(strategy.real64);
    inaccurate += bad;
    silent_inaccurate += bad && t.status == Status::ok;
    growth_flagged += flagged;
    missed_by_growth += bad && !flagged;
  }

  void count_status(Status s) {
    switch (s) {
      case Status::ok:
        ++ok;
        break;
      case Status::unstable:
        ++unstable;
        break;
      case Status::no_pivot:
        ++no_pivot;
        break;
      case Status::non_finite:
        ++non_finite;
        break;
      case Status::lost:  // only a pipeline with faults loses rows
        break;
    }
  }

  ResultValue to_value() const {
    ResultValue r;
    r.set("strategy", strategy.name);
    r.set("precision", strategy.real64 ? "real64" : "real32");
    r.set("pivot_threshold", strategy.rule.threshold);
    r.set("forward_error", spread(forward));
    r.set("backward_error", spread(backward));
    r.set("growth_max", growth_max);
    r.set("smallest_relative_pivot", std::isinf(smallest_pivot) ? 0.0 : smallest_pivot);
    r.set("interchanges", std::int64_t(interchanges));
    r.set("ok", std::int64_t(ok));
    r.set("unstable", std::int64_t(unstable));
    r.set("no_pivot", std::int64_t(no_pivot));
    r.set("non_finite", std::int64_t(non_finite));
    r.set("inaccurate", std::int64_t(inaccurate));
    r.set("silent_inaccurate", std::int64_t(silent_inaccurate));
    r.set("growth_flagged", std::int64_t(growth_flagged));
    r.set("missed_by_growth_check", std::int64_t(missed_by_growth));
    return r;
  }
};

// Relative pivot thresholds for simple interchange: far above each precision's rounding noise
// and below the arm's smallest relative pivot (1.7e-6 of max D_ij: the last pivot, ~ Izz6).
double threshold_for(bool real64) {
  return real64 ? 1e-10 : 1e-7;
}

std::vector<Strategy> strategies(bool with_threshold) {
  std::vector<Strategy> out;
  for (bool real64 : {true, false}) {
    out.push_back({"simple", {}, real64});
    if (with_threshold)
      out.push_back({"simple+threshold", {Pivoting::simple, threshold_for(real64), 0}, real64});
    out.push_back({"partial", {Pivoting::partial, 0, 0}, real64});
  }
  return out;
}

std::vector<Tally> tallies(const std::vector<Strategy>& list) {
  std::vector<Tally> out;
  for (const Strategy& s : list) {
    out.emplace_back();
    out.back().strategy = s;
  }
  return out;
}

ResultValue tally_list(const std::vector<Tally>& tallies) {
  ResultValue list = ResultValue::list();
  for (const Tally& t : tallies) list.push(t.to_value());
  return list;
}

// ---- (a) the arm ----

// Uniform in the limits, except that each joint is put in the outer 2 % of its range (either end)
// with probability 1/5.
dynamics::JointVector sample_configuration(const dynamics::RobotModel& model,
                                           std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  dynamics::JointVector q;
  for (int i = 0; i < dynamics::kJoints; ++i) {
    const dynamics::JointLimits& l = model.joints[std::size_t(i)].limits;
    const double range = l.max - l.min;
    if (u(rng) < 0.2) {
      const double inset = 0.02 * range * u(rng);
      q(i) = u(rng) < 0.5 ? l.min + inset : l.max - inset;
    } else {
      q(i) = l.min + range * u(rng);
    }
  }
  return q;
}

ResultValue arm_experiment(const dynamics::RobotModel& model, int states, std::mt19937_64& rng) {
  const auto subtasks = dynamics::derive_subtasks(model, dynamics::ModelVariant::full);
  std::vector<Tally> t = tallies(strategies(false));
  std::vector<double> conditions;
  dynamics::JointVector worst = dynamics::JointVector::Zero();
  std::uniform_real_distribution<double> rate(-1.0, 1.0);
  for (int n = 0; n < states; ++n) {
    const dynamics::JointVector q = sample_configuration(model, rng);
    dynamics::JointVector qd;
    for (int i = 0; i < dynamics::kJoints; ++i) qd(i) = rate(rng);
    const auto data =
        elimination::dynamics_system<double>(model, subtasks, q, qd, dynamics::JointVector::Zero());
    Eigen::MatrixXd d(dynamics::kJoints, dynamics::kJoints);
    for (int i = 0; i < dynamics::kJoints; ++i)
      for (int j = 0; j < dynamics::kJoints; ++j) d(i, j) = data.a[std::size_t(i)][std::size_t(j)];
    conditions.push_back(stress::condition_number(d));
    if (conditions.back() >= max_of(conditions)) worst = q;
    const VectorL reference = reference_solution(data);
    for (Tally& tally : t) tally.add(run_trial(tally.strategy, data, reference));
  }
  ResultValue r;
  r.set("states", states);
  ResultValue cond;
  cond.set("min", *std::min_element(conditions.begin(), conditions.end()));
  cond.set("median", median(conditions));
  cond.set("max", max_of(conditions));
  r.set("condition", cond);
  ResultValue q = ResultValue::list();
  for (int i = 0; i < dynamics::kJoints; ++i) q.push(worst(i));
  r.set("worst_condition_q", q);
  r.set("strategies", tally_list(t));
  return r;
}

// ---- (b) random matrices ----

LinearSystem<double> system_for(const Eigen::MatrixXd& a, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  LinearSystem<double> s;
  std::vector<double> x;
  for (int j = 0; j < a.cols(); ++j) x.push_back(u(rng));
  for (int i = 0; i < a.rows(); ++i) {
    elimination::Row<double> row;
    long double b = 0;
    for (int j = 0; j < a.cols(); ++j) {
      row.push_back(a(i, j));
      b += static_cast<long double>(a(i, j)) * x[std::size_t(j)];
    }
    s.a.push_back(std::move(row));
    s.b.push_back(double(b));
  }
  return s;
}

// Runs every strategy on `count` matrices from `make`; returns the tallies and the median
// measured condition number.
template <class Make>
ResultValue matrix_experiment(int count, std::mt19937_64& rng, bool with_threshold, Make make) {
  std::vector<Tally> t = tallies(strategies(with_threshold));
  std::vector<double> conditions;
  for (int c = 0; c < count; ++c) {
    const Eigen::MatrixXd a = make();
    conditions.push_back(stress::condition_number(a));
    const LinearSystem<double> data = system_for(a, rng);
    const VectorL reference = reference_solution(data);
    if (reference.empty()) continue;
    for (Tally& tally : t) tally.add(run_trial(tally.strategy, data, reference));
  }
  ResultValue r;
  r.set("matrices", count);
  r.set("measured_condition", median(conditions));
  r.set("strategies", tally_list(t));
  return r;
}

ResultValue condition_sweep(int count, std::mt19937_64& rng) {
  ResultValue rows = ResultValue::list();
  for (bool spd : {true, false}) {
    for (int e = 0; e <= 12; e += 2) {
      const double condition = std::pow(10.0, e);
      ResultValue r = matrix_experiment(
          count, rng, false, [&] { return stress::with_condition(6, condition, spd, rng); });
      r.set("kind", spd ? "spd" : "nonsymmetric");
      r.set("condition", condition);
      rows.push(r);
    }
  }
  return rows;
}

// Well-conditioned nonsymmetric matrices (condition 10) whose k-th pivot without interchanges is
// delta * max|a_ij|.
ResultValue tiny_pivots(int count, std::mt19937_64& rng) {
  ResultValue rows = ResultValue::list();
  for (int k : {0, 3}) {
    for (double delta : {1e-2, 1e-5, 1e-8, 1e-11, 1e-14, 1e-17, 0.0}) {
      ResultValue r = matrix_experiment(count, rng, true, [&] {
        return stress::with_tiny_pivot(stress::with_condition(6, 10.0, false, rng), k, delta);
      });
      r.set("step", k);
      r.set("delta", delta);
      rows.push(r);
    }
  }
  return rows;
}

// ---- (c) energy ----

ResultValue energy_run(const dynamics::RobotModel& model,
                       const std::vector<dynamics::Subtask>& subtasks, const char* model_name,
                       integration::Method method, bool real64, bool quick) {
  integration::PassiveSettings s;
  s.method = method;
  s.real64 = real64;
  s.dt = 1e-3;
  s.steps = quick ? 1000 : 10000;
  s.energy_every = quick ? 10 : 1;
  s.q0 << 0.1, 0.2, 0.5, 0.3, 0.4, 0.5;  // the README's reference state
  s.qd0 << 0.1, -0.2, 0.05, 0.3, -0.1, 0.2;
  const integration::PassiveResult p = integration::run_passive(model, subtasks, s);
  ResultValue r;
  r.set("model", model_name);
  r.set("method", integration::to_string(method));
  r.set("precision", real64 ? "real64" : "real32");
  r.set("seconds", s.steps * s.dt);
  r.set("dt", s.dt);
  r.set("e0_J", p.e0);
  r.set("max_abs_drift_J", p.max_abs_drift);
  r.set("final_drift_J", p.final_drift);
  r.set("max_kinetic_J", p.max_kinetic);
  r.set("relative_drift", p.relative_drift());
  r.set("first_limit_exit_s", p.first_limit_exit_s);
  r.set("failure", p.failure);
  return r;
}

ResultValue energy_experiment(const dynamics::RobotModel& model, bool quick) {
  const auto full = dynamics::derive_subtasks(model, dynamics::ModelVariant::full);
  const auto paper = dynamics::derive_subtasks(model, dynamics::ModelVariant::paper);
  using integration::Method;
  ResultValue rows = ResultValue::list();
  for (Method method : {Method::rk4, Method::semi_implicit_euler})
    for (bool real64 : {true, false})
      rows.push(energy_run(model, full, "full", method, real64, quick));
  rows.push(energy_run(model, paper, "paper", Method::rk4, true, quick));
  return rows;
}

}  // namespace

ResultValue run_stress(const StressOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  const dynamics::RobotModel model = load_robot(find_repository_file(options.robot));
  const int states = options.states > 0 ? options.states : (options.quick ? 5000 : 100000);
  const int matrices = options.quick ? 40 : 400;
  std::mt19937_64 rng(options.seed);
  ResultValue r;
  r.set("quick", options.quick);
  r.set("seed", std::int64_t(options.seed));
  r.set("inaccurate_means",
        "backward error above sqrt(unit roundoff): 1.5e-8 (REAL64), 2.4e-4 (REAL32)");
  r.set("arm", arm_experiment(model, states, rng));
  r.set("condition_sweep", condition_sweep(matrices, rng));
  r.set("tiny_pivot", tiny_pivots(matrices, rng));
  r.set("energy", energy_experiment(model, options.quick));
  r.set("wall_s", std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  return r;
}

}  // namespace tools
