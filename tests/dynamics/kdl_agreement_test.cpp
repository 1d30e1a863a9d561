// The full model against Orocos KDL at random states inside the joint limits (REAL64).
#include <gtest/gtest.h>

#include <random>

#include "dynamics_fixtures.hpp"

namespace dynamics {
namespace {

using testing::KdlArm;
using testing::relative_error;
using testing::stanford;

constexpr double kTolerance = 1e-10;

JointVector random_vector(std::mt19937_64& rng, double amplitude) {
  std::uniform_real_distribution<double> uniform(-amplitude, amplitude);
  JointVector v;
  for (int i = 0; i < kJoints; ++i) v(i) = uniform(rng);
  return v;
}

TEST(KdlAgreement, FullModelMatchesAtRandomStates) {
  const RobotModel& model = stanford();
  const std::vector<Subtask> subtasks = derive_subtasks(model, ModelVariant::full);
  KdlArm kdl(model);
  std::mt19937_64 rng(2024);
  double worst_d = 0, worst_c = 0, worst_h = 0, worst_qdd = 0;
  for (int sample = 0; sample < 200; ++sample) {
    const JointVector q = random_configuration(model, rng);
    const JointVector qd = random_vector(rng, 2.0);
    const JointVector tau = random_vector(rng, 50.0);
    Dynamics data;
    forward_dynamics(model, data, subtasks, q, qd, tau);
    worst_d = std::max(worst_d, relative_error(data.D, kdl.mass(q)));
    worst_c = std::max(worst_c, relative_error(data.c, kdl.coriolis(q, qd)));
    worst_h = std::max(worst_h, relative_error(data.h, kdl.gravity(q)));
    worst_qdd = std::max(worst_qdd, relative_error(data.qdd, kdl.qdd(q, qd, tau)));
  }
  EXPECT_LE(worst_d, kTolerance);
  EXPECT_LE(worst_c, kTolerance);
  EXPECT_LE(worst_h, kTolerance);
  EXPECT_LE(worst_qdd, kTolerance);
  std::cout << "[ kdl      ] 200 states, worst relative error: D " << worst_d << ", c " << worst_c
            << ", h " << worst_h << ", qdd " << worst_qdd << "\n";
}

// The shipped PUMA 560 file (published data, inertias kept although they break the triangle
// inequality) through the same code, against KDL.
TEST(KdlAgreement, PumaFullModelMatchesAtRandomStates) {
  const RobotModel model =
      tools::load_robot(std::string(T800SIM_SOURCE_DIR) + "/configs/robots/puma560.toml");
  const std::vector<Subtask> subtasks = derive_subtasks(model, ModelVariant::full);
  KdlArm kdl(model);
  std::mt19937_64 rng(560);
  for (int sample = 0; sample < 50; ++sample) {
    const JointVector q = random_configuration(model, rng);
    const JointVector qd = random_vector(rng, 2.0);
    const JointVector tau = random_vector(rng, 50.0);
    Dynamics data;
    forward_dynamics(model, data, subtasks, q, qd, tau);
    EXPECT_LE(relative_error(data.D, kdl.mass(q)), kTolerance);
    EXPECT_LE(relative_error(data.c, kdl.coriolis(q, qd)), kTolerance);
    EXPECT_LE(relative_error(data.h, kdl.gravity(q)), kTolerance);
  }
}

// Each Coriolis term on its own: KDL's c(q, q̇) = Σ C_ijk q̇_j q̇_k polarised over unit rates gives
// C_ijj = c_i(e_j) and C_ijk = (c_i(e_j + e_k) − c_i(e_j) − c_i(e_k)) / 2, for every term (also
// those the structural-zero analysis found zero). KDL's value is symmetric in j, k by construction.
TEST(KdlAgreement, EveryCoriolisTermMatchesPolarisedKdl) {
  const RobotModel& model = stanford();
  KdlArm kdl(model);
  std::mt19937_64 rng(7);
  const JointMatrix unit = JointMatrix::Identity();
  for (int sample = 0; sample < 10; ++sample) {
    const JointVector q = random_configuration(model, rng);
    std::array<JointVector, kJoints> single;
    for (int j = 0; j < kJoints; ++j) single[j] = kdl.coriolis(q, unit.col(j));
    double scale = 0;
    for (const auto& c : single) scale = std::max(scale, c.cwiseAbs().maxCoeff());
    for (const Subtask& term : all_terms()) {
      if (term.kind != TermKind::coriolis) continue;
      const double ours = evaluate(model, term, q);
      for (const auto& [j, k] : {std::pair(term.j, term.k), std::pair(term.k, term.j)}) {
        const double reference = j == k
                                     ? single[j](term.i)
                                     : 0.5 * (kdl.coriolis(q, unit.col(j) + unit.col(k))(term.i) -
                                              single[j](term.i) - single[k](term.i));
        EXPECT_NEAR(ours, reference, kTolerance * scale)
            << term.name << " as C" << term.i + 1 << "_" << j + 1 << k + 1;
      }
    }
  }
}

// C_ijk is the Christoffel symbol ½(∂D_ij/∂q_k + ∂D_ik/∂q_j − ∂D_jk/∂q_i) of our own D (central
// differences), which is symmetric in j and k: a check of the analytic C independent of KDL.
TEST(KdlAgreement, CoriolisTermsAreChristoffelSymbolsOfD) {
  const RobotModel& model = stanford();
  const std::vector<Subtask> d_terms = [] {
    std::vector<Subtask> all = all_terms();
    std::vector<Subtask> d;
    for (const Subtask& t : all) {
      if (t.kind == TermKind::inertia) d.push_back(t);
    }
    return d;
  }();
  const JointVector q = (JointVector() << 0.3, -0.7, 0.8, 1.1, -0.4, 0.9).finished();
  const double step = 1e-6;
  std::array<JointMatrix, kJoints> dD;  // dD[k] = ∂D/∂q_k
  for (int k = 0; k < kJoints; ++k) {
    JointVector plus = q, minus = q;
    plus(k) += step;
    minus(k) -= step;
    dD[k] = (evaluate_all(model, d_terms, plus, JointVector::Zero()).D -
             evaluate_all(model, d_terms, minus, JointVector::Zero()).D) /
            (2 * step);
  }
  for (const Subtask& term : all_terms()) {
    if (term.kind != TermKind::coriolis) continue;
    const int i = term.i, j = term.j, k = term.k;
    const double christoffel = 0.5 * (dD[k](i, j) + dD[j](i, k) - dD[i](j, k));
    EXPECT_NEAR(evaluate(model, term, q), christoffel, 1e-6) << term.name;
  }
}

}  // namespace
}  // namespace dynamics
