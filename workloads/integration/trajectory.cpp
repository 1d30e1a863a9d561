#include "workloads/integration/trajectory.hpp"

#include <cmath>
#include <stdexcept>

#include "workloads/elimination/system.hpp"
#include "workloads/integration/energy.hpp"

namespace integration {

namespace {

// q̈ = D⁻¹(−c − h) in S by the paper's elimination; a failed solve ends the run.
template <class S>
struct PassiveDynamics {
  const dynamics::RobotModel& model;
  const std::vector<dynamics::Subtask>& subtasks;
  const elimination::PivotRule& rule;

  dynamics::JointVectorT<S> operator()(const dynamics::JointVectorT<S>& q,
                                       const dynamics::JointVectorT<S>& qd) const {
    const auto system =
        elimination::dynamics_system<S>(model, subtasks, q.template cast<double>(),
                                        qd.template cast<double>(), dynamics::JointVector::Zero());
    const elimination::Solution<S> s = elimination::solve(system.a, system.b, rule);
    if (!elimination::solved(s.status))
      throw std::runtime_error(std::string("elimination failed: ") +
                               elimination::to_string(s.status) + " at step " +
                               std::to_string(s.step));
    dynamics::JointVectorT<S> qdd;
    for (int i = 0; i < dynamics::kJoints; ++i) qdd(i) = s.x[std::size_t(i)];
    return qdd;
  }
};

struct EnergyWatch {
  const dynamics::RobotModel& model;
  const std::vector<dynamics::Subtask>& subtasks;
  PassiveResult& result;

  void sample(const dynamics::JointVector& q, const dynamics::JointVector& qd, double t_s,
              bool first) {
    const long double kinetic = kinetic_energy(model, subtasks, q, qd);
    const double e = double(kinetic + potential_energy(model, q));
    if (first) result.e0 = e;
    result.final_drift = e - result.e0;
    result.max_abs_drift = std::max(result.max_abs_drift, std::fabs(result.final_drift));
    result.max_kinetic = std::max(result.max_kinetic, double(kinetic));
    if (dynamics::within_limits(model, q)) return;
    if (result.limit_exits++ == 0) result.first_limit_exit_s = t_s;
  }
};

template <class S>
PassiveResult run(const dynamics::RobotModel& model, const std::vector<dynamics::Subtask>& subtasks,
                  const PassiveSettings& settings) {
  PassiveResult result;
  EnergyWatch watch{model, subtasks, result};
  const PassiveDynamics<S> f{model, subtasks, settings.rule};
  State<S> x{settings.q0.cast<S>(), settings.qd0.cast<S>()};
  watch.sample(x.q.template cast<double>(), x.qd.template cast<double>(), 0.0, true);
  const S h = S(settings.dt);
  try {
    for (int n = 1; n <= settings.steps; ++n) {
      x = step(settings.method, x, h, f);
      result.steps_done = n;
      if (n % settings.energy_every == 0 || n == settings.steps)
        watch.sample(x.q.template cast<double>(), x.qd.template cast<double>(), n * settings.dt,
                     false);
    }
  } catch (const std::runtime_error& e) {
    result.failure = e.what();
  }
  result.q_end = x.q.template cast<double>();
  return result;
}

}  // namespace

PassiveResult run_passive(const dynamics::RobotModel& model,
                          const std::vector<dynamics::Subtask>& subtasks,
                          const PassiveSettings& settings) {
  if (settings.steps < 1 || settings.energy_every < 1 || !(settings.dt > 0))
    throw std::invalid_argument("passive trajectory: steps, energy_every and dt must be positive");
  return settings.real64 ? run<double>(model, subtasks, settings)
                         : run<float>(model, subtasks, settings);
}

}  // namespace integration
