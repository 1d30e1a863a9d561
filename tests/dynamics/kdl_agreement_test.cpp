// The full model against Orocos KDL at random states inside the joint limits (REAL64).
#include <gtest/gtest.h>

#include <random>

#include "dynamics_fixtures.hpp"
#include "tests/test_paths.hpp"

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

// The worst relative errors of the full model against KDL over random states inside the limits.
struct WorstErrors {
  double d = 0, c = 0, h = 0, qdd = 0;
};

WorstErrors against_kdl(const RobotModel& model, int samples, std::uint64_t seed) {
  const std::vector<Subtask> subtasks = derive_subtasks(model, ModelVariant::full);
  KdlArm kdl(model);
  std::mt19937_64 rng(seed);
  WorstErrors worst;
  for (int sample = 0; sample < samples; ++sample) {
    const JointVector q = random_configuration(model, rng);
    const JointVector qd = random_vector(rng, 2.0);
    const JointVector tau = random_vector(rng, 50.0);
    Dynamics data;
    forward_dynamics(model, data, subtasks, q, qd, tau);
    worst.d = std::max(worst.d, relative_error(data.D, kdl.mass(q)));
    worst.c = std::max(worst.c, relative_error(data.c, kdl.coriolis(q, qd)));
    worst.h = std::max(worst.h, relative_error(data.h, kdl.gravity(q)));
    worst.qdd = std::max(worst.qdd, relative_error(data.qdd, kdl.qdd(q, qd, tau)));
  }
  return worst;
}

void expect_within_tolerance(const WorstErrors& worst) {
  EXPECT_LE(worst.d, kTolerance);
  EXPECT_LE(worst.c, kTolerance);
  EXPECT_LE(worst.h, kTolerance);
  EXPECT_LE(worst.qdd, kTolerance);
}

TEST(KdlAgreement, FullModelMatchesAtRandomStates) {
  const WorstErrors worst = against_kdl(stanford(), 200, 2024);
  expect_within_tolerance(worst);
  std::cout << "[ kdl      ] 200 states, worst relative error: D " << worst.d << ", c " << worst.c
            << ", h " << worst.h << ", qdd " << worst.qdd << "\n";
}

// The shipped PUMA 560 file (published data, inertias kept although they break the triangle
// inequality) through the same code, against KDL.
TEST(KdlAgreement, PumaFullModelMatchesAtRandomStates) {
  expect_within_tolerance(against_kdl(
      tools::load_robot(test_paths::source_dir() + "/configs/robots/puma560.toml"), 50, 560));
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
