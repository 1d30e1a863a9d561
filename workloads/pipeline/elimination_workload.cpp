// The "elimination" workload kind: a scene's parameters -> the system and the pipeline's settings;
// and the Table 6 helpers.
#include <cmath>
#include <stdexcept>

#include "workloads/setting_error.hpp"

#include "workloads/dynamics/subtask_set.hpp"
#include "workloads/pipeline/pipeline.hpp"

namespace workloads {

namespace {

elimination::LinearSystem<double> given_system(const Params& p) {
  const std::vector<double>& a = p.real_list("a");
  const std::vector<double>& b = p.real_list("b");
  const std::size_t n = b.size();
  if (n == 0 || a.size() != n * n)
    throw SettingError({"workload.a"},
                       "elimination: workload.a must hold n*n values (row by row) for the n "
                       "values of workload.b; got " +
                           std::to_string(a.size()) + " and " + std::to_string(n));
  elimination::LinearSystem<double> s;
  for (std::size_t i = 0; i < n; ++i) {
    s.a.emplace_back(a.begin() + std::ptrdiff_t(i * n), a.begin() + std::ptrdiff_t((i + 1) * n));
    s.b.push_back(b[i]);
  }
  return s;
}

dynamics::JointVector joint_vector(const Params& p, const std::string& name) {
  const std::vector<double>& v = p.real_list(name);
  if (v.size() != dynamics::kJoints)
    throw SettingError({"workload." + name}, "elimination: workload." + name + " needs " +
                                                 std::to_string(dynamics::kJoints) +
                                                 " values, got " + std::to_string(v.size()));
  dynamics::JointVector j;
  for (int i = 0; i < dynamics::kJoints; ++i) j(i) = v[std::size_t(i)];
  return j;
}

// The arm's system at the state, computed in double; the pipeline rounds it to its precision.
elimination::LinearSystem<double> arm_system(const WorkloadContext& c) {
  const dynamics::RobotModel& model = require_robot(c);
  const auto variant = dynamics::parse_model_variant(c.params.text("model"));
  const auto subtasks = dynamics::derive_subtasks(model, *variant);
  return elimination::dynamics_system<double>(model, subtasks, joint_vector(c.params, "q"),
                                              joint_vector(c.params, "qd"),
                                              joint_vector(c.params, "tau"));
}

elimination::LinearSystem<double> input_system(const WorkloadContext& c) {
  const std::string& source = c.params.text("source");
  if (source == "random")
    return elimination::random_system(int(c.params.integer("n")),
                                      std::uint64_t(c.params.integer("seed")));
  if (source == "given") return given_system(c.params);
  return arm_system(c);
}

// growth_limit 0 means "automatic": 1/sqrt(unit roundoff) of the precision, beyond which the
// pivot growth can cost half the digits. No growth check: limit 0 (PivotRule's "off").
double growth_limit(const Params& p, t800::Precision precision) {
  if (!p.flag("growth_check")) return 0;
  const double given = p.real("growth_limit");
  if (given > 0) return given;
  return precision == t800::Precision::real64 ? 1.0 / std::sqrt(0x1p-53) : 1.0 / std::sqrt(0x1p-24);
}

}  // namespace

PipelineSettings elimination_settings(const Params& p) {
  PipelineSettings s;
  s.m = int(p.integer("m"));
  s.precision = *t800::parse_precision(p.text("precision"));
  s.rule.pivoting = *elimination::parse_pivoting(p.text("pivoting"));
  s.rule.threshold = p.real("pivot_threshold");
  s.rule.growth_limit = growth_limit(p, s.precision);
  s.overlap = p.flag("overlap");
  s.buffered = p.flag("buffered");
  return s;
}

std::unique_ptr<Workload> make_elimination(const WorkloadContext& context) {
  return make_elimination_with(context, elimination_settings(context.params));
}

std::unique_ptr<Workload> make_elimination_with(const WorkloadContext& context,
                                                const PipelineSettings& settings) {
  return std::make_unique<EliminationPipeline>(settings, input_system(context), context.topology);
}

std::string elimination_topology(int m) {
  return "configs/topologies/elimination-m" + std::to_string(m) + ".toml";
}

std::vector<std::string> table6_overrides(int m) {
  return {"network.topology=../topologies/elimination-m" + std::to_string(m) + ".toml",
          "workload.m=" + std::to_string(m)};
}

}  // namespace workloads
