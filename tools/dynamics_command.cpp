// `t800sim dynamics`: one evaluation of the robot's dynamics on the host (no network): D, c, h, q̈ and every
// subtask with its operation counts and T800 cycles -- what a worker of the farm would be charged.
#include <cmath>
#include <iostream>
#include <sstream>
#include <stdexcept>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "network/config_error.hpp"
#include "t800/cost_model.hpp"
#include "tools/commands.hpp"
#include "tools/paper_data.hpp"
#include "tools/robot_file.hpp"
#include "tools/scene.hpp"
#include "workloads/dynamics/assembly.hpp"
#include "workloads/dynamics/evaluate.hpp"
#include "workloads/dynamics/subtask_set.hpp"
#include "workloads/farm/farm_tasks.hpp"

namespace tools {

namespace {

using nlohmann::json;

struct DynamicsArgs {
  std::string q, qd, tau;
  std::string model = "full";
  std::string precision = "real64";
  std::string robot = "configs/robots/stanford.toml";
  std::string scene = "configs/scenes/dynamics-farm.toml";
  bool json_output = false;
};

// "a,b,c,d,e,f" -> six finite numbers, or an error naming the flag.
dynamics::JointVector joint_values(const std::string& text, const std::string& flag) {
  std::vector<double> values;
  std::stringstream in(text);
  for (std::string item; std::getline(in, item, ',');) {
    std::size_t used = 0;
    double v = 0;
    try {
      v = std::stod(item, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    while (used < item.size() && std::isspace(static_cast<unsigned char>(item[used]))) ++used;
    if (item.empty() || used != item.size())
      throw std::invalid_argument(flag + ": '" + item + "' is not a number (expected " +
                                  std::to_string(dynamics::kJoints) + " comma-separated numbers)");
    if (!std::isfinite(v)) throw std::invalid_argument(flag + ": values must be finite, got '" + item + "'");
    values.push_back(v);
  }
  if (values.size() != dynamics::kJoints)
    throw std::invalid_argument(flag + ": expected " + std::to_string(dynamics::kJoints) + " values, got " +
                                std::to_string(values.size()));
  return Eigen::Map<dynamics::JointVector>(values.data());
}

void check_limits(const dynamics::RobotModel& model, const dynamics::JointVector& q) {
  for (int i = 0; i < dynamics::kJoints; ++i) {
    const auto& l = model.joints[i].limits;
    if (q(i) < l.min || q(i) > l.max)
      throw std::invalid_argument(fmt::format("--q: joint {} = {} is outside its limits [{}, {}]", i + 1, q(i),
                                              l.min, l.max));
  }
}

// The calibration recorded in the farm scene, so that cycles match what the farm charges.
double code_efficiency(const std::string& scene) {
  try {
    return load_scene(find_repository_file(scene)).code_efficiency;
  } catch (const std::exception&) {
    return 1.0;
  }
}

template <class S>
json evaluate(const DynamicsArgs& a, const dynamics::RobotModel& model) {
  const auto variant = *dynamics::parse_model_variant(a.model);
  const dynamics::JointVector q = joint_values(a.q, "--q");
  check_limits(model, q);
  const dynamics::JointVector qd = a.qd.empty() ? dynamics::JointVector::Zero() : joint_values(a.qd, "--qd");
  const dynamics::JointVector tau = a.tau.empty() ? dynamics::JointVector::Zero() : joint_values(a.tau, "--tau");
  const auto subtasks = dynamics::derive_subtasks(model, variant);
  dynamics::DynamicsData<S> data;
  dynamics::forward_dynamics(model, data, subtasks, q, qd, tau);

  const double efficiency = code_efficiency(a.scene);
  const t800::CostModel cost({}, *t800::parse_precision(a.precision), efficiency);
  json out;
  out["model"] = a.model;
  out["precision"] = a.precision;
  out["code_efficiency"] = efficiency;
  out["D"] = json::array();
  for (int i = 0; i < dynamics::kJoints; ++i) {
    json row = json::array();
    for (int j = 0; j < dynamics::kJoints; ++j) row.push_back(double(data.D(i, j)));
    out["D"].push_back(row);
  }
  for (const auto& [key, v] : {std::pair{"c", &data.c}, {"h", &data.h}, {"qdd", &data.qdd}}) {
    out[key] = json::array();
    for (int i = 0; i < dynamics::kJoints; ++i) out[key].push_back(double((*v)(i)));
  }
  out["subtasks"] = json::array();
  for (std::size_t t = 0; t < subtasks.size(); ++t) {
    const dynamics::OpCounts ops = dynamics::count_ops(model, subtasks[t]);
    out["subtasks"].push_back({{"name", subtasks[t].name},
                               {"value", double(data.values[t])},
                               {"ops", dynamics::to_string(ops)},
                               {"cycles", cost.cycles(workloads::to_operation_mix(ops))}});
  }
  return out;
}

std::string text_of(const json& r) {
  std::string s = fmt::format("model {}, {}, cycles at T800-20 with code_efficiency {}\n\nD =\n",
                              r["model"].get<std::string>(), r["precision"].get<std::string>(),
                              r["code_efficiency"].get<double>());
  for (const json& row : r["D"]) {
    for (const json& v : row) s += fmt::format(" {:>14.7g}", v.get<double>());
    s += "\n";
  }
  for (const char* key : {"c", "h", "qdd"}) {
    s += fmt::format("\n{:<4}=", key);
    for (const json& v : r[key]) s += fmt::format(" {:>14.7g}", v.get<double>());
    s += "\n";
  }
  s += fmt::format("\n{} subtasks\n{:<8} {:>14} {:>9}  {}\n", r["subtasks"].size(), "name", "value", "cycles", "ops");
  for (const json& t : r["subtasks"])
    s += fmt::format("{:<8} {:>14.7g} {:>9}  {}\n", t["name"].get<std::string>(), t["value"].get<double>(),
                     t["cycles"].get<long>(), t["ops"].get<std::string>());
  return s;
}

}  // namespace

void add_dynamics_command(CLI::App& app) {
  auto a = std::make_shared<DynamicsArgs>();
  auto* cmd = app.add_subcommand("dynamics", "Evaluate the robot's D, c, h and q̈ at one state, with each subtask's "
                                             "operation counts and T800 cycles");
  cmd->add_option("--q", a->q, "joint positions q1,...,q6 (rad; q3 in m)")->required();
  cmd->add_option("--qd", a->qd, "joint rates (default zero)");
  cmd->add_option("--tau", a->tau, "joint torques/forces (default zero)");
  cmd->add_option("--model", a->model, "full (every non-zero term) or paper (64 subtasks)")
      ->check(CLI::IsMember({"full", "paper"}))
      ->capture_default_str();
  cmd->add_option("--precision", a->precision, "real32 or real64")
      ->check(CLI::IsMember({"real32", "real64"}))
      ->capture_default_str();
  cmd->add_option("--robot", a->robot, "robot model file")->capture_default_str();
  cmd->add_option("--scene", a->scene, "the farm scene whose calibration prices the cycles")->capture_default_str();
  cmd->add_flag("--json", a->json_output, "print JSON");
  cmd->callback([a] {
    run_command([&] {
      const dynamics::RobotModel model = load_robot(find_repository_file(a->robot));
      const json r = a->precision == "real32" ? evaluate<float>(*a, model) : evaluate<double>(*a, model);
      std::cout << (a->json_output ? r.dump(2) + "\n" : text_of(r));
      return kExitOk;
    });
  });
}

}  // namespace tools
