// Systems shared by the elimination tests: the arm at its reference state (the README's),
// random systems, and small hand-made cases.
#pragma once

#include <string>

#include <Eigen/LU>

#include "tests/test_paths.hpp"
#include "tools/robot_file.hpp"
#include "workloads/dynamics/subtask_set.hpp"
#include "workloads/elimination/system.hpp"

namespace elimination_test {

inline const dynamics::RobotModel& stanford() {
  static const dynamics::RobotModel model =
      tools::load_robot(test_paths::source_dir() + "/configs/robots/stanford.toml");
  return model;
}

// D q̈ = −(c + h) at q = (0.1, 0.2, 0.5, 0.3, 0.4, 0.5), q̇ = (0.1, −0.2, 0.05, 0.3, −0.1, 0.2).
inline elimination::LinearSystem<double> reference_system() {
  dynamics::JointVector q, qd;
  q << 0.1, 0.2, 0.5, 0.3, 0.4, 0.5;
  qd << 0.1, -0.2, 0.05, 0.3, -0.1, 0.2;
  const auto subtasks = dynamics::derive_subtasks(stanford(), dynamics::ModelVariant::full);
  return elimination::dynamics_system<double>(stanford(), subtasks, q, qd,
                                              dynamics::JointVector::Zero());
}

inline elimination::LinearSystem<double> given(std::vector<std::vector<double>> a,
                                               std::vector<double> b) {
  return {std::move(a), std::move(b)};
}

inline elimination::PivotRule rule(elimination::Pivoting pivoting, double threshold = 0,
                                   double growth_limit = 0) {
  elimination::PivotRule r;
  r.pivoting = pivoting;
  r.threshold = threshold;
  r.growth_limit = growth_limit;
  return r;
}

inline Eigen::MatrixXd to_eigen(const elimination::LinearSystem<double>& s) {
  Eigen::MatrixXd a(s.size(), s.size());
  for (std::size_t i = 0; i < s.size(); ++i)
    for (std::size_t j = 0; j < s.size(); ++j) a(Eigen::Index(i), Eigen::Index(j)) = s.a[i][j];
  return a;
}

inline Eigen::VectorXd rhs(const elimination::LinearSystem<double>& s) {
  return Eigen::Map<const Eigen::VectorXd>(s.b.data(), Eigen::Index(s.size()));
}

}  // namespace elimination_test
