// Energy of a passive trajectory (τ = 0, no friction): the potential is the one gravity derives
// from, RK4 converges at fourth order, and its drift stays within a bound derived from that order.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

#include "tests/test_paths.hpp"
#include "tools/robot_file.hpp"
#include "workloads/dynamics/assembly.hpp"
#include "workloads/dynamics/state.hpp"
#include "workloads/dynamics/subtask_set.hpp"
#include "workloads/integration/energy.hpp"
#include "workloads/integration/trajectory.hpp"

namespace {

using integration::Method;

const dynamics::RobotModel& stanford() {
  static const dynamics::RobotModel model =
      tools::load_robot(test_paths::source_dir() + "/configs/robots/stanford.toml");
  return model;
}

const std::vector<dynamics::Subtask>& full_model() {
  static const auto subtasks = dynamics::derive_subtasks(stanford(), dynamics::ModelVariant::full);
  return subtasks;
}

integration::PassiveResult passive(Method method, bool real64, double dt, double seconds) {
  integration::PassiveSettings s;
  s.method = method;
  s.real64 = real64;
  s.dt = dt;
  s.steps = int(std::lround(seconds / dt));
  s.q0 << 0.1, 0.2, 0.5, 0.3, 0.4, 0.5;
  s.qd0 << 0.1, -0.2, 0.05, 0.3, -0.1, 0.2;
  return integration::run_passive(stanford(), full_model(), s);
}

// h_i = ∂V/∂q_i: the potential energy is consistent with the dynamics' gravity term (central
// differences, error O(ε²) ~ 1e-12 relative, plus rounding of V / ε ~ 1e-10).
TEST(Energy, PotentialGradientIsTheGravityTerm) {
  std::mt19937_64 rng(11);
  for (int n = 0; n < 20; ++n) {
    const dynamics::JointVector q = dynamics::random_configuration(stanford(), rng);
    const dynamics::Dynamics d =
        dynamics::evaluate_all(stanford(), full_model(), q, dynamics::JointVector::Zero());
    for (int i = 0; i < dynamics::kJoints; ++i) {
      const double eps = 1e-6;
      dynamics::JointVector up = q, down = q;
      up(i) += eps;
      down(i) -= eps;
      const double gradient = double((integration::potential_energy(stanford(), up) -
                                      integration::potential_energy(stanford(), down)) /
                                     (2 * eps));
      EXPECT_NEAR(gradient, d.h(i), 1e-7 * (1 + d.h.cwiseAbs().maxCoeff())) << "joint " << i + 1;
    }
  }
}

// Halving the step divides RK4's energy error by 2^4 = 16, semi-implicit Euler's by 2.
TEST(Energy, Rk4IsFourthOrderAndEulerFirstOrder) {
  const double rk4 = passive(Method::rk4, true, 0.02, 0.4).max_abs_drift /
                     passive(Method::rk4, true, 0.01, 0.4).max_abs_drift;
  EXPECT_GT(rk4, 12.0);
  EXPECT_LT(rk4, 21.0);
  const double euler = passive(Method::semi_implicit_euler, true, 0.002, 0.4).max_abs_drift /
                       passive(Method::semi_implicit_euler, true, 0.001, 0.4).max_abs_drift;
  EXPECT_GT(euler, 1.6);
  EXPECT_LT(euler, 2.5);
}

// The bound: in the asymptotic range (the test above) the drift is K h⁴, so the drift at 1 ms is
// at most that at 10 ms times (1/10)⁴ (with a factor 2 for the approach to the asymptote); rounding
// adds at most a few units of roundoff of the energy scale per step (N u E_scale, a worst case in
// which every step's rounding has the same sign).
TEST(Energy, Rk4Real64DriftWithinTheDerivedBound) {
  const double seconds = 1.0;
  const auto coarse = passive(Method::rk4, true, 0.01, seconds);
  const auto fine = passive(Method::rk4, true, 0.001, seconds);
  ASSERT_TRUE(fine.failure.empty()) << fine.failure;
  const double scale = std::max(std::fabs(fine.e0), fine.max_kinetic);
  const double truncation = 2 * coarse.max_abs_drift * 1e-4;
  const double rounding = fine.steps_done * 0x1p-53 * scale;
  EXPECT_LE(fine.max_abs_drift, truncation + rounding)
      << "truncation " << truncation << " rounding " << rounding;
  EXPECT_GT(fine.max_kinetic, 100.0);  // the arm really moves: the check is not vacuous
}

// REAL32: rounding dominates (K h⁴ ~ 4e-13 J); its errors add like a random walk, sqrt(N) u E_scale
// with u = 2^-24, and a factor 4 for the several roundings of each step.
TEST(Energy, Rk4Real32DriftIsRoundingNotTruncation) {
  const auto r = passive(Method::rk4, false, 0.001, 1.0);
  ASSERT_TRUE(r.failure.empty()) << r.failure;
  const double scale = std::max(std::fabs(r.e0), r.max_kinetic);
  EXPECT_LE(r.max_abs_drift, 4 * std::sqrt(double(r.steps_done)) * 0x1p-24 * scale);
}

}  // namespace
