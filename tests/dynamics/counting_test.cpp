// The counting scalar: same values as the plain scalar, bit for bit, and operation counts that do
// not depend on the state.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <random>

#include "dynamics_fixtures.hpp"

namespace dynamics {
namespace {

using testing::stanford;

TEST(CountedScalar, CountsEachOperationKind) {
  OpTally tally;
  const Counted<double> a(1.5), b(2.0);
  Counted<double> x = a + b - a * b / b;
  x = sqrt(x) + sin(a) + cos(b);
  const bool less = a < b;
  EXPECT_TRUE(less);
  const Counted<double> negated = -x;  // folded into the add or subtract that consumes it
  EXPECT_EQ(negated.value(), -x.value());
  const OpCounts& n = tally.counts();
  EXPECT_EQ(n.fadd, 4);
  EXPECT_EQ(n.fmul, 1);
  EXPECT_EQ(n.fdiv, 1);
  EXPECT_EQ(n.fsqrt, 1);
  EXPECT_EQ(n.fsincos, 2);
  EXPECT_EQ(n.fcompare, 1);
}

TEST(CountedScalar, TalliesNestAndStop) {
  OpTally outer;
  Counted<float> x(1.0f);
  x = x + x;
  {
    OpTally inner;
    x = x * x;
    EXPECT_EQ(inner.counts().fmul, 1);
    EXPECT_EQ(inner.counts().fadd, 0);
  }
  EXPECT_EQ(outer.counts().fadd, 1);
  EXPECT_EQ(outer.counts().fmul, 0);
}

TEST(CountedScalar, GivesExactlyThePlainValueForEveryTerm) {
  const RobotModel& model = stanford();
  std::mt19937_64 rng(11);
  for (int sample = 0; sample < 5; ++sample) {
    const JointVector q = random_configuration(model, rng);
    for (const Subtask& term : all_terms()) {
      EXPECT_EQ(evaluate<Counted<double>>(model, term, q).value(), evaluate<double>(model, term, q))
          << term.name;
      EXPECT_EQ(evaluate<Counted<float>>(model, term, q).value(), evaluate<float>(model, term, q))
          << term.name;
    }
  }
}

TEST(OpCounts, AreTheSameAtEveryState) {
  const RobotModel& model = stanford();
  std::mt19937_64 rng(5);
  for (const Subtask& task : derive_subtasks(model, ModelVariant::full)) {
    const OpCounts at_mid = count_ops(model, task);
    for (int sample = 0; sample < 4; ++sample) {
      EXPECT_EQ(count_ops(model, task, random_configuration(model, rng)), at_mid) << task.name;
    }
  }
}

TEST(OpCounts, EverySubtaskStoresOneResultAndDoesWork) {
  const RobotModel& model = stanford();
  for (const Subtask& task : derive_subtasks(model, ModelVariant::full)) {
    const OpCounts n = count_ops(model, task);
    EXPECT_EQ(n.fstore, 1) << task.name;
    EXPECT_EQ(n.fsincos, 0) << task.name;  // the master sends sines and cosines
    EXPECT_GT(n.fload, 0) << task.name;
  }
}

TEST(OpCounts, MasterPreprocessingIsTenSinCosCalls) {
  const OpCounts n = count_input_ops(stanford());
  EXPECT_EQ(n.fsincos, 10);  // sin and cos of the five revolute joints (all offsets 0: no adds)
  EXPECT_EQ(n.fadd, 0);
  EXPECT_EQ(n.fload, kJoints);
  EXPECT_EQ(n.fstore, worker_input_reals(stanford()));
  EXPECT_EQ(worker_input_reals(stanford()), 11);
}

// Reported, not asserted: the operation mix of every subtask of the paper's model, and the totals.
TEST(OpCounts, ReportPerSubtask) {
  const RobotModel& model = stanford();
  for (ModelVariant variant : {ModelVariant::paper, ModelVariant::full}) {
    const std::vector<Subtask> subtasks = derive_subtasks(model, variant);
    OpCounts total;
    for (const Subtask& task : subtasks) {
      const OpCounts n = count_ops(model, task);
      total += n;
      if (variant == ModelVariant::paper) {
        std::cout << fmt::format("[ ops      ] {:<6} {}\n", task.name, to_string(n));
      }
    }
    std::cout << fmt::format("[ ops      ] {} model, {} subtasks: {}\n", to_string(variant),
                             subtasks.size(), to_string(total));
    std::cout << fmt::format("[ ops      ] master: preprocessing {}; c assembly {}\n",
                             to_string(count_input_ops(model)),
                             to_string(count_assembly_ops(subtasks)));
  }
}

}  // namespace
}  // namespace dynamics
