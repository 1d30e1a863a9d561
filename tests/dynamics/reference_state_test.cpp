// A reference state of the Stanford arm (full model): D, c, h, q̈ to the printed digits.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

#include "dynamics_fixtures.hpp"

namespace dynamics {
namespace {

using testing::stanford;

// A value as printed, and half a unit of its last printed digit ("0" means exactly zero).
struct Printed {
  double value;
  double tolerance;
};

Printed printed(const std::string& text) {
  const std::size_t exponent_at = text.find_first_of("eE");
  const std::string mantissa = text.substr(0, exponent_at);
  const int exponent =
      exponent_at == std::string::npos ? 0 : std::stoi(text.substr(exponent_at + 1));
  const std::size_t point = mantissa.find('.');
  const int decimals =
      point == std::string::npos ? 0 : static_cast<int>(mantissa.size() - point - 1);
  const double value = std::stod(text);
  if (value == 0) return {0, 1e-12};
  return {value, 0.5 * std::pow(10.0, exponent - decimals) + 1e-12};
}

void expect_printed(double actual, const std::string& text, const std::string& what) {
  const Printed p = printed(text);
  EXPECT_NEAR(actual, p.value, p.tolerance) << what << " printed as " << text;
}

const State& reference_state() {
  static const State state{(JointVector() << 0.1, 0.2, 0.5, 0.3, 0.4, 0.5).finished(),
                           (JointVector() << 0.1, -0.2, 0.05, 0.3, -0.1, 0.2).finished()};
  return state;
}

TEST(ReferenceState, MatchesPrintedDigits) {
  const char* d[kJoints][kJoints] = {
      {"10.98977", "4.195600", "-0.1095946", "0.1920722", "-0.4090546", "2.639514e-4"},
      {"4.195600", "155.6138", "-0.07652664", "0.7172025", "0.5847270", "-1.116077e-4"},
      {"-0.1095946", "-0.07652664", "6.47", "0", "-0.4474884", "0"},
      {"0.1920722", "0.7172025", "0", "0.2245445", "0", "2.763183e-4"},
      {"-0.4090546", "0.5847270", "-0.4474884", "0", "1.449431", "0"},
      {"2.639514e-4", "-1.116077e-4", "0", "2.763183e-4", "0", "3.0e-4"}};
  const char* c[kJoints] = {"-1.268386",   "-0.03862650", "0.9625814",
                            "-0.06971197", "-0.02163600", "-1.429584e-6"};
  const char* h[kJoints] = {"0", "44.490898", "62.205512", "-0.866768", "-4.91195", "0"};
  const char* qdd[kJoints] = {"0.070682", "-0.318066", "-9.72784",
                              "5.13206",  "0.548757",  "-4.902692"};

  const RobotModel& model = stanford();
  Dynamics data;
  forward_dynamics(model, data, derive_subtasks(model, ModelVariant::full), reference_state().q,
                   reference_state().qd, JointVector::Zero());
  for (int i = 0; i < kJoints; ++i) {
    for (int j = 0; j < kJoints; ++j) {
      expect_printed(data.D(i, j), d[i][j], "D" + std::to_string(i + 1) + std::to_string(j + 1));
    }
    expect_printed(data.c(i), c[i], "c" + std::to_string(i + 1));
    expect_printed(data.h(i), h[i], "h" + std::to_string(i + 1));
    expect_printed(data.qdd(i), qdd[i], "qdd" + std::to_string(i + 1));
  }
}

// Reported, not asserted: what REAL32 arithmetic and the paper's simplification do to q̈.
TEST(ReferenceState, ReportsPrecisionAndSimplificationEffects) {
  const RobotModel& model = stanford();
  const State& s = reference_state();
  const JointVector tau = JointVector::Zero();
  const std::vector<Subtask> full = derive_subtasks(model, ModelVariant::full);
  const std::vector<Subtask> paper = derive_subtasks(model, ModelVariant::paper);

  Dynamics full64;
  DynamicsData<float> full32;
  Dynamics paper64;
  forward_dynamics(model, full64, full, s.q, s.qd, tau);
  forward_dynamics(model, full32, full, s.q, s.qd, tau);
  forward_dynamics(model, paper64, paper, s.q, s.qd, tau);

  const JointVector qdd32 = full32.qdd.cast<double>();
  const double float_error = testing::relative_error(qdd32, full64.qdd);
  const double paper_difference = testing::relative_error(paper64.qdd, full64.qdd);
  const double paper_c_difference = testing::relative_error(paper64.c, full64.c);
  RecordProperty("qdd_real32_vs_real64_relative", std::to_string(float_error));
  RecordProperty("qdd_paper_vs_full_relative", std::to_string(paper_difference));
  std::cout.precision(3);
  std::cout << "[ report   ] reference state, full model: |qdd(REAL32) - qdd(REAL64)| / |qdd| = "
            << float_error << " (max abs " << (qdd32 - full64.qdd).cwiseAbs().maxCoeff() << ")\n"
            << "[ report   ] REAL64: |qdd(paper) - qdd(full)| / |qdd| = " << paper_difference
            << " (max abs " << (paper64.qdd - full64.qdd).cwiseAbs().maxCoeff()
            << "); |c(paper) - c(full)| / |c| = " << paper_c_difference << "\n";
  std::cout << "[ report   ] qdd full  = " << full64.qdd.transpose() << "\n"
            << "[ report   ] qdd paper = " << paper64.qdd.transpose() << "\n"
            << "[ report   ] qdd REAL32 = " << qdd32.transpose() << "\n";
  EXPECT_TRUE(qdd32.allFinite());

  // The same over random states inside the limits (q̇ uniform in ±1, τ = 0).
  std::mt19937_64 rng(99);
  std::uniform_real_distribution<double> rate(-1.0, 1.0);
  double worst_float = 0, worst_paper = 0;
  JointVector worst_paper_by_joint = JointVector::Zero();
  for (int sample = 0; sample < 100; ++sample) {
    const JointVector q = random_configuration(model, rng);
    JointVector qd;
    for (int i = 0; i < kJoints; ++i) qd(i) = rate(rng);
    forward_dynamics(model, full64, full, q, qd, tau);
    forward_dynamics(model, full32, full, q, qd, tau);
    forward_dynamics(model, paper64, paper, q, qd, tau);
    worst_float =
        std::max(worst_float, testing::relative_error(full32.qdd.cast<double>(), full64.qdd));
    worst_paper = std::max(worst_paper, testing::relative_error(paper64.qdd, full64.qdd));
    worst_paper_by_joint = worst_paper_by_joint.cwiseMax((paper64.qdd - full64.qdd).cwiseAbs());
  }
  RecordProperty("qdd_real32_vs_real64_worst_of_100", std::to_string(worst_float));
  RecordProperty("qdd_paper_vs_full_worst_of_100", std::to_string(worst_paper));
  std::cout << "[ report   ] 100 random states: worst |qdd(REAL32) - qdd(REAL64)| / |qdd| = "
            << worst_float << "; worst |qdd(paper) - qdd(full)| / |qdd| = " << worst_paper
            << ", worst abs per joint = " << worst_paper_by_joint.transpose() << "\n";
}

}  // namespace
}  // namespace dynamics
