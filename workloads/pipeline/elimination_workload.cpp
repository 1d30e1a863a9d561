// The "elimination" workload kind: a scene's parameters -> the system and the pipeline's settings;
// and the Table 6 helpers.
#include <cmath>
#include <stdexcept>

#include "workloads/setting_error.hpp"

#include "workloads/dynamics/subtask_set.hpp"
#include "workloads/pipeline/pipeline.hpp"
#include "workloads/registry.hpp"

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
  s.recovery = p.flag("recovery");
  s.timeout_us = p.real("recovery_timeout_us");
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

namespace {
using T = ParamType;
// clang-format off
const Registration registered_elimination{
    WorkloadInfo{"elimination",
     "the paper's Gaussian-elimination pipeline (Fig. 7): L1 pivots and normalises, m level-2 "
     "processors eliminate, L3 collects, L4 back-substitutes (workloads/pipeline/pipeline.hpp)",
     {
         {"m", T::integer, std::int64_t{0},
          "level-2 processors E1..Em used; 0 = all of the topology's (elimination-m<m>.toml has m)", 0, 64,
          {}},
         {"precision", T::precision, std::string{"real64"}, "occam REAL32 or REAL64 arithmetic", {}, {}, {}},
         {"pivoting", T::text, std::string{"simple"},
          "\"simple\" (the paper: interchange only when the pivot is unusable) or \"partial\" (largest in "
          "the column)",
          {}, {}, {"simple", "partial"}},
         {"pivot_threshold", T::real, 0.0,
          "a pivot p is unusable when |p| <= pivot_threshold * max|a_ij|; 0 = only an exact zero (the paper)",
          0.0, 1.0, {}},
         {"growth_check", T::flag, true,
          "level 3 also checks the pivot growth (catches tiny non-zero pivots; costs a pass over each reduced "
          "matrix and one over A on level 1); false = the paper's checks only (every row arrived, finite)",
          {}, {}, {}},
         {"growth_limit", T::real, 0.0,
          "growth above which level 3 flags the result unstable; 0 = 1/sqrt(unit roundoff) of the precision "
          "(4096 for REAL32, 9.5e7 for REAL64)",
          0.0, 1e300, {}},
         {"overlap", T::flag, false,
          "pipelined steps: level 3 streams each row back to level 1 as it arrives, and level 1 starts the next "
          "step once it has the rows its pivot choice needs (simple interchange: the first); false = strict steps",
          {}, {}, {}},
         {"buffered", T::flag, false,
          "each level-2 processor runs input, elimination and output as three parallel processes joined by "
          "one-row buffers (docs/table6.md); false = one process that takes, eliminates and passes a row",
          {}, {}, {}},
         {"recovery", T::flag, false,
          "level 3 detects a corrupted or missing row (a checksum with every row, a timeout) and has level 1 "
          "resend it through another level-2 processor (strict, unbuffered steps; README \"Faults\")",
          {}, {}, {}},
         {"recovery_timeout_us", T::real, 1000.0,
          "recovery: how long a level waits for the next message of a step before it gives up on it", 1.0, 1e9,
          {}},
         {"source", T::text, std::string{"arm"},
          "the system: \"arm\" (D q'' = tau - c - h of the robot at q, qd, tau), \"random\" (n x n from "
          "seed) or \"given\" (workload.a, workload.b)",
          {}, {}, {"arm", "random", "given"}},
         {"robot", T::robot_file, std::string{"../robots/stanford.toml"}, "robot model file, relative to the scene",
          {}, {}, {}},
         {"model", T::text, std::string{"full"},
          "dynamics model for source = \"arm\": \"full\" or \"paper\" (64 subtasks)", {}, {},
          {"paper", "full"}},
         {"q", T::real_list, std::vector<double>{0.1, 0.2, 0.5, 0.3, 0.4, 0.5},
          "joint positions (rad, q3 in m); default: the README's reference state", {}, {}, {}},
         {"qd", T::real_list, std::vector<double>{0.1, -0.2, 0.05, 0.3, -0.1, 0.2}, "joint rates", {}, {}, {}},
         {"tau", T::real_list, std::vector<double>{0, 0, 0, 0, 0, 0}, "joint torques (N m; N for joint 3)", {},
          {}, {}},
         {"n", T::integer, std::int64_t{6}, "unknowns, for source = \"random\"", 1, 64, {}},
         {"seed", T::integer, std::int64_t{1}, "random generator seed, for source = \"random\"", 0, 9.0e15,
          {}},
         {"a", T::real_list, std::vector<double>{}, "source = \"given\": the n x n matrix, row by row", {}, {},
          {}},
         {"b", T::real_list, std::vector<double>{}, "source = \"given\": the right-hand side", {}, {}, {}},
     }},
    make_elimination};
// clang-format on
}  // namespace

}  // namespace workloads
