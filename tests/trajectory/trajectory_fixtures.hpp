// Running the trajectory workload in-process (one simulation per test process), and the
// numerics-only rollout it must equal: integration::step over elimination::dynamics_system and
// elimination::solve, τ read at the same stage times.
#pragma once

#include <memory>
#include <stdexcept>
#include <string>

#include "network/topology_file.hpp"
#include "tests/test_paths.hpp"
#include "tools/robot_file.hpp"
#include "workloads/dynamics/subtask_set.hpp"
#include "workloads/elimination/system.hpp"
#include "workloads/integration/integrators.hpp"
#include "workloads/integration/torque.hpp"
#include "workloads/params.hpp"
#include "workloads/registry.hpp"
#include "workloads/run/run.hpp"

namespace trajectory_test {

inline std::shared_ptr<const dynamics::RobotModel> stanford() {
  return std::make_shared<const dynamics::RobotModel>(
      tools::load_robot(test_paths::source_dir() + "/configs/robots/stanford.toml"));
}

// The catalogue's defaults for the trajectory.
inline workloads::Params defaults() {
  workloads::Params p;
  for (const auto& spec : workloads::find_workload("trajectory")->params)
    p.set(spec.name, spec.default_value);
  return p;
}

inline workloads::RunInputs inputs(const workloads::Params& params) {
  workloads::RunInputs in;
  in.name = "trajectory-test";
  in.topology =
      network::load_topology(test_paths::source_dir() + "/configs/topologies/trajectory-9-m3.toml");
  in.options.precision = *t800::parse_precision(params.text("precision"));
  in.kind = "trajectory";
  in.params = params;
  in.robot = stanford();
  return in;
}

inline workloads::RunReport run(const workloads::Params& params) {
  return workloads::run(inputs(params));
}

inline dynamics::JointVector joints(const workloads::ResultValue& list) {
  dynamics::JointVector v;
  for (int i = 0; i < dynamics::kJoints; ++i) v(i) = list.items()[std::size_t(i)].number();
  return v;
}

inline dynamics::JointVector joints(const std::vector<double>& list) {
  dynamics::JointVector v;
  for (int i = 0; i < dynamics::kJoints; ++i) v(i) = list[list.size() == 1 ? 0 : std::size_t(i)];
  return v;
}

// τ(t, q, q̇) -> double, as the workload computes it.
using Torque = std::function<dynamics::JointVector(double, const dynamics::JointVector&,
                                                   const dynamics::JointVector&)>;

template <class S>
integration::State<S> rollout(const workloads::Params& p, const Torque& torque) {
  const auto model = stanford();
  const auto subtasks =
      dynamics::derive_subtasks(*model, *dynamics::parse_model_variant(p.text("model")));
  elimination::PivotRule rule;
  rule.pivoting = *elimination::parse_pivoting(p.text("pivoting"));
  const auto method = *integration::parse_method(p.text("integrator"));
  const double dt = p.real("dt");
  integration::State<S> x{joints(p.real_list("q")).cast<S>(), joints(p.real_list("qd")).cast<S>()};
  for (int n = 0; n < int(p.integer("steps")); ++n) {
    int stage = 0;
    auto f = [&](const dynamics::JointVectorT<S>& q, const dynamics::JointVectorT<S>& qd) {
      const double t = n * dt + integration::stage_offsets(method)[stage++] * dt;
      const dynamics::JointVector qw = q.template cast<double>(), qdw = qd.template cast<double>();
      const auto system =
          elimination::dynamics_system<S>(*model, subtasks, qw, qdw, torque(t, qw, qdw));
      const auto s = elimination::solve(system.a, system.b, rule);
      if (!elimination::solved(s.status)) throw std::runtime_error("reference solve failed");
      dynamics::JointVectorT<S> qdd;
      for (int i = 0; i < dynamics::kJoints; ++i) qdd(i) = s.x[std::size_t(i)];
      return qdd;
    };
    x = integration::step(method, x, S(dt), f);
  }
  return x;
}

}  // namespace trajectory_test
