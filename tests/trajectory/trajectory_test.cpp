// The trajectory workload: its numbers are the numerics-only rollout's, bit for bit; the PD
// controller drives the arm toward its target; torque tables fail with file:line; leaving a joint
// limit is reported, never clamped. One simulation per test (ctest runs each in its own process);
// no assertion on times.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "tests/test_paths.hpp"
#include "trajectory_fixtures.hpp"
#include "workloads/integration/trajectory.hpp"
#include "workloads/run/workload.hpp"

namespace {

using dynamics::JointVector;
using namespace trajectory_test;

JointVector zero_torque(double, const JointVector&, const JointVector&) {
  return JointVector::Zero();
}

template <class S>
void expect_same_state(const workloads::ResultValue& w, const integration::State<S>& x) {
  const JointVector q = joints(*w.get("final_q")), qd = joints(*w.get("final_qd"));
  for (int i = 0; i < dynamics::kJoints; ++i) {
    EXPECT_EQ(q(i), double(x.q(i))) << "q" << i + 1;  // exact
    EXPECT_EQ(qd(i), double(x.qd(i))) << "qd" << i + 1;
  }
}

void expect_clean(const workloads::RunReport& report, int steps) {
  ASSERT_TRUE(report.blocked.empty()) << report.blocked.front().process;
  ASSERT_EQ(report.workload.get("failure"), nullptr) << report.workload.get("failure")->to_text();
  ASSERT_EQ(report.workload.get("steps")->number(), steps);
}

TEST(Trajectory, Rk4Real32EqualsTheNumericsOnlyRolloutBitForBit) {
  auto p = defaults();
  p.set("steps", std::int64_t{3});
  const auto report = run(p);
  expect_clean(report, 3);
  expect_same_state(report.workload, rollout<float>(p, zero_torque));

  // And the passive rollout of workloads/integration (the energy study's) ends at the same q.
  integration::PassiveSettings passive;
  passive.real64 = false;
  passive.steps = 3;
  passive.q0 = joints(p.real_list("q"));
  const auto model = stanford();
  const auto end = integration::run_passive(
      *model, dynamics::derive_subtasks(*model, dynamics::ModelVariant::full), passive);
  EXPECT_EQ(joints(*report.workload.get("final_q")), end.q_end);
  EXPECT_EQ(report.workload.get("evaluations_per_step")->number(), 4);
}

TEST(Trajectory, SemiImplicitEulerReal64WithPdEqualsTheRolloutBitForBit) {
  auto p = defaults();
  p.set("precision", std::string("real64"));
  p.set("integrator", std::string("semi-implicit-euler"));
  p.set("pivoting", std::string("partial"));
  p.set("torque", std::string("pd"));
  p.set("steps", std::int64_t{4});
  const auto report = run(p);
  expect_clean(report, 4);
  integration::PdGains g{joints(p.real_list("kp")), joints(p.real_list("kd")),
                         joints(p.real_list("target"))};
  expect_same_state(report.workload,
                    rollout<double>(p, [&](double, const JointVector& q, const JointVector& qd) {
                      return integration::pd_torque<double>(g, q, qd);
                    }));
  EXPECT_EQ(report.workload.get("evaluations_per_step")->number(), 1);
}

std::string write_temp(const std::string& name, const std::string& text) {
  const std::string path = test_paths::binary_dir() + "/" + name;
  std::ofstream(path) << text;
  return path;
}

// The table is read at each RK4 stage's time (0, h/2, h/2, h), linearly interpolated.
TEST(Trajectory, TorqueTableRk4EqualsTheRolloutBitForBit) {
  const std::string csv =
      write_temp("trajectory_test_torque.csv",
                 "t,tau1,tau2,tau3,tau4,tau5,tau6\n0,0,0,0,0,0,0\n0.003,3,-6,9,0.3,0.2,0.1\n");
  auto p = defaults();
  p.set("torque", std::string("csv"));
  p.set("torque_csv", csv);
  p.set("steps", std::int64_t{2});
  const auto report = run(p);
  expect_clean(report, 2);
  std::ifstream file(csv);
  const auto table =
      integration::TorqueTable::parse(file, csv, integration::TorqueInterpolation::linear);
  expect_same_state(report.workload,
                    rollout<float>(p, [&](double t, const JointVector&, const JointVector&) {
                      return table.at(t);
                    }));
}

// Joints 1 and 6 turn about axes gravity does not load, so a PD controller without gravity
// compensation must bring them close to their targets; stiff gains hold the others (joint 3 against
// gravity) near where they start, inside their limits.
// Per-joint gains: the wrist's inertia is small, and explicit damping needs kd dt / I < 2.
TEST(Trajectory, PdDrivesTheArmTowardItsTarget) {
  auto p = defaults();
  p.set("precision", std::string("real64"));
  p.set("integrator", std::string("semi-implicit-euler"));
  p.set("torque", std::string("pd"));
  p.set("kp", std::vector<double>{300, 100, 2000, 5, 5, 2});
  p.set("kd", std::vector<double>{40, 20, 200, 0.5, 0.5, 0.2});
  p.set("target", std::vector<double>{0.3, 0.2, 0.5, 0.3, 0.4, 0.7});
  p.set("steps", std::int64_t{200});
  p.set("dt", 2e-3);
  const auto report = run(p);
  expect_clean(report, 200);
  const JointVector target = joints(p.real_list("target"));
  const JointVector start = joints(p.real_list("q"));
  const JointVector end = joints(*report.workload.get("final_q"));
  for (int i : {0, 5})
    EXPECT_LT(std::abs(end(i) - target(i)), 0.5 * std::abs(start(i) - target(i)))
        << "joint " << i + 1;
  EXPECT_EQ(report.workload.get("limit_violations")->items().size(), 0u);
}

// The default gains (100 D_ii and 20 D_ii at the scene's start: critically damped at 10 rad/s) hold
// the shipped arm with 1 ms RK4 steps; one gain for every joint (kd = 20 on the wrist's 0.0003 kg
// m^2) diverged in two steps. After 1 s the error e^(-10 t)(1 + 10 t) of a lone critically damped
// joint is 5e-4 of where it started; the prismatic joint 3 carries the load's weight, which a P
// term holds only below its target.
TEST(Trajectory, TheDefaultPdGainsSettleTheArmAtItsTarget) {
  auto p = defaults();
  p.set("torque", std::string("pd"));
  p.set("q", std::vector<double>{0.1, 0.2, 0.5, 0.3, 0.4, 0.5});
  p.set("steps", std::int64_t{1000});
  const auto report = run(p);
  expect_clean(report, 1000);
  const JointVector target = joints(p.real_list("target"));
  const JointVector end = joints(*report.workload.get("final_q"));
  for (int i : {0, 1, 3, 4, 5}) EXPECT_NEAR(end(i), target(i), 1e-2) << "joint " << i + 1;
  EXPECT_LT(end(2), target(2));
  EXPECT_GT(end(2), target(2) - 0.2);
}

TEST(TorqueTable, ABadLineIsNamedByFileAndLine) {
  std::istringstream in(
      "# comment\nt,tau1,tau2,tau3,tau4,tau5,tau6\n0,1,2,3,4,5,6\n0.1,1,2,x,4,5,6\n");
  try {
    integration::TorqueTable::parse(in, "torque.csv", integration::TorqueInterpolation::linear);
    FAIL() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("torque.csv:4: column 4"), std::string::npos) << e.what();
  }
}

TEST(TorqueTable, TheWorkloadRefusesABadTableWithFileAndLine) {
  const std::string csv = write_temp(
      "trajectory_test_bad.csv", "t,tau1,tau2,tau3,tau4,tau5,tau6\n0,0,0,0,0,0,0\n0.1,0,0,0,0,0\n");
  auto p = defaults();
  p.set("torque", std::string("csv"));
  p.set("torque_csv", csv);
  const auto in = inputs(p);
  try {
    workloads::make_workload("trajectory", {in.params, in.topology, in.robot.get()});
    FAIL() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find(csv + ":3: 6 columns"), std::string::npos) << e.what();
  }
}

TEST(TorqueTable, InterpolatesOrHoldsAndHoldsBeyondItsEnds) {
  const std::string text = "t,tau1,tau2,tau3,tau4,tau5,tau6\n0,0,0,0,0,0,0\n1,2,2,2,2,2,2\n";
  std::istringstream a(text), b(text);
  const auto linear =
      integration::TorqueTable::parse(a, "a", integration::TorqueInterpolation::linear);
  const auto hold = integration::TorqueTable::parse(b, "b", integration::TorqueInterpolation::hold);
  EXPECT_EQ(linear.at(0.25)(0), 0.5);
  EXPECT_EQ(hold.at(0.25)(0), 0.0);
  EXPECT_EQ(linear.at(-1)(0), 0.0);
  EXPECT_EQ(linear.at(5)(0), 2.0);
}

// Joint 5 (limits ±90°) starts just inside its upper limit and moving out.
workloads::Params near_limit() {
  auto p = defaults();
  p.set("precision", std::string("real64"));
  p.set("integrator", std::string("semi-implicit-euler"));
  p.set("q", std::vector<double>{0.1, 0.2, 0.5, 0.3, 1.5705, 0.5});
  p.set("qd", std::vector<double>{0, 0, 0, 0, 1.0, 0});
  p.set("steps", std::int64_t{3});
  return p;
}

TEST(Trajectory, LeavingAJointLimitIsReportedNotClamped) {
  const auto report = run(near_limit());
  expect_clean(report, 3);
  const auto& exits = report.workload.get("limit_violations")->items();
  ASSERT_EQ(exits.size(), 1u);
  EXPECT_EQ(exits[0].get("joint")->number(), 5);
  EXPECT_EQ(exits[0].get("step")->number(), 1);
  EXPECT_GT(exits[0].get("value")->number(), 1.5707963267948966);
  EXPECT_GT(joints(*report.workload.get("final_q"))(4),
            exits[0].get("value")->number());  // not clamped
  EXPECT_EQ(report.workload.get("steps_outside_limits")->number(), 3);
}

TEST(Trajectory, StopAtLimitsEndsTheRunAtTheFirstExit) {
  auto p = near_limit();
  p.set("stop_at_limits", true);
  const auto report = run(p);
  expect_clean(report, 1);
  EXPECT_EQ(report.workload.get("limit_violations")->items().size(), 1u);
}

}  // namespace

namespace {

// The farm runs on exactly the paper's tree: every link of tree-9 is in the trajectory topology,
// between the same processors on the same link numbers, and the host on P0.link0.
TEST(TrajectoryTopology, KeepsTheFarmTreeExactlyAsTree9) {
  const auto tree =
      network::load_topology(test_paths::source_dir() + "/configs/topologies/tree-9.toml");
  const auto both =
      network::load_topology(test_paths::source_dir() + "/configs/topologies/trajectory-9-m3.toml");
  for (int p = 0; p < int(tree.processors.size()); ++p) {
    const int q = both.find(tree.processors[std::size_t(p)].name);
    ASSERT_GE(q, 0);
    for (int link = 0; link < 4; ++link) {
      if (tree.connection_at(p, link) < 0) continue;
      const network::LinkEnd far = tree.peer(p, link);
      ASSERT_GE(both.connection_at(q, link), 0) << tree.processors[std::size_t(p)].name << link;
      const network::LinkEnd other = both.peer(q, link);
      EXPECT_EQ(both.processors[std::size_t(other.processor)].name,
                tree.processors[std::size_t(far.processor)].name);
      EXPECT_EQ(other.link, far.link);
    }
  }
  EXPECT_EQ(both.processors[std::size_t(both.host_processor())].name, "P0");
  EXPECT_EQ(both.host->link, tree.host->link);
}

}  // namespace

namespace {

// Gains far too stiff for the wrist's inertia at this step: the explicit method blows up, the
// pipeline's level 3 meets a non-finite value, and the run ends with the failure -- every level,
// worker and router ends, nothing is left blocked.
TEST(Trajectory, ADivergingRunEndsWithTheSolverFailureAndNothingBlocks) {
  auto p = defaults();
  p.set("precision", std::string("real64"));
  p.set("integrator", std::string("semi-implicit-euler"));
  p.set("torque", std::string("pd"));
  p.set("kp", std::vector<double>{400.0});
  p.set("kd", std::vector<double>{40.0});
  p.set("steps", std::int64_t{100});
  p.set("dt", 2e-3);
  const auto report = run(p);
  ASSERT_TRUE(report.blocked.empty()) << report.blocked.front().process;
  ASSERT_NE(report.workload.get("failure"), nullptr);
  EXPECT_NE(report.workload.get("failure")->to_text().find("non-finite"), std::string::npos);
  EXPECT_LT(report.workload.get("steps")->number(), 100);
  EXPECT_FALSE(report.workload.get("limit_violations")->items().empty());
}

// A pivot threshold above the wrist's tiny last pivot (D66 ~ 3e-4 against max|D| ~ 155): level 1
// finds no usable pivot at the last step of the first solve. Level-2 processors with no rows in
// that step already wait for the next system; they too must be stopped (a regression: they were
// left blocked).
TEST(Trajectory, NoUsablePivotAtTheLastStepEndsTheRunAndNothingBlocks) {
  auto p = defaults();
  p.set("pivot_threshold", 1e-5);
  p.set("steps", std::int64_t{3});
  const auto report = run(p);
  ASSERT_TRUE(report.blocked.empty()) << report.blocked.front().process;
  ASSERT_NE(report.workload.get("failure"), nullptr);
  EXPECT_NE(report.workload.get("failure")->to_text().find("no usable pivot at step 5"),
            std::string::npos);
  EXPECT_EQ(report.workload.get("steps")->number(), 0);
}

}  // namespace
