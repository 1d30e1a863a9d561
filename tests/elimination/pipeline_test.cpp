// The four-level pipeline on the elimination-m<m> topologies: bit-identical to the sequential
// solver, failures that stop every level cleanly. One simulation per test (each test is its own
// process under ctest). No assertion on times.
#include <gtest/gtest.h>

#include <cmath>

#include "network/machine.hpp"
#include "network/topology_file.hpp"
#include "tests/elimination/elimination_fixtures.hpp"
#include "tests/elimination/pipeline_fixtures.hpp"
#include "tests/test_paths.hpp"
#include "workloads/pipeline/pipeline.hpp"

namespace {

using namespace elimination_test;
using elimination::Pivoting;
using elimination::Status;

class PipelineM : public ::testing::TestWithParam<int> {};

TEST_P(PipelineM, ArmReal64SimpleEqualsSequential) {
  expect_same_as_sequential<double>(GetParam(), reference_system(), rule(Pivoting::simple));
}

TEST_P(PipelineM, ArmReal32SimpleEqualsSequential) {
  expect_same_as_sequential<float>(GetParam(), reference_system(), rule(Pivoting::simple));
}

// A random system needs interchanges under partial pivoting; the growth check is on.
TEST_P(PipelineM, RandomPartialWithInterchangesEqualsSequential) {
  const auto system = elimination::random_system(6, 7);
  ASSERT_GT(elimination::solve(system.a, system.b, rule(Pivoting::partial)).interchanges, 0);
  expect_same_as_sequential<double>(GetParam(), system, rule(Pivoting::partial, 0, 1e8));
}

// A zero pivot: simple interchange on every level's data.
TEST_P(PipelineM, ZeroPivotInterchangeEqualsSequential) {
  auto system = elimination::random_system(6, 3);
  system.a[0][0] = 0;
  expect_same_as_sequential<double>(GetParam(), system, rule(Pivoting::simple));
}

// Overlap (rows streamed back, the next step started early) changes when, never what: q̈ is still
// bit-identical, for both precisions and both pivotings.
TEST_P(PipelineM, OverlapArmReal64SimpleEqualsSequential) {
  expect_same_as_sequential<double>(GetParam(), reference_system(), rule(Pivoting::simple), true);
}

TEST_P(PipelineM, OverlapArmReal32SimpleEqualsSequential) {
  expect_same_as_sequential<float>(GetParam(), reference_system(), rule(Pivoting::simple), true);
}

// Partial pivoting needs every row before it chooses: level 1 waits for the whole matrix.
TEST_P(PipelineM, OverlapArmReal64PartialEqualsSequential) {
  expect_same_as_sequential<double>(GetParam(), reference_system(), rule(Pivoting::partial), true);
}

TEST_P(PipelineM, OverlapArmReal32PartialEqualsSequential) {
  expect_same_as_sequential<float>(GetParam(), reference_system(), rule(Pivoting::partial), true);
}

TEST_P(PipelineM, OverlapRandomPartialWithInterchangesEqualsSequential) {
  const auto system = elimination::random_system(6, 7);
  expect_same_as_sequential<float>(GetParam(), system, rule(Pivoting::partial, 0, 1e8), true);
}

// A zero first row: level 1 waits for the whole reduced matrix before it interchanges.
TEST_P(PipelineM, OverlapZeroPivotInterchangeEqualsSequential) {
  auto system = elimination::random_system(6, 3);
  system.a[0][0] = 0;
  expect_same_as_sequential<double>(GetParam(), system, rule(Pivoting::simple), true);
}

// A singular system fails at level 1 in the last step; a NaN fails at level 3 in the first: both
// are reported and every process ends. (The last column is zero, so the last pivot is an exact
// zero: a singularity that rounding turns into a tiny pivot is what the growth check is for.)
TEST_P(PipelineM, SingularSystemIsReportedAndNothingDeadlocks) {
  auto system = elimination::random_system(6, 5);
  for (auto& row : system.a) row[5] = 0;
  const PipelineRun run =
      run_pipeline(GetParam(), system, rule(Pivoting::simple), t800::Precision::real64);
  EXPECT_TRUE(run.blocked.empty());
  EXPECT_EQ(run.outcome.status, Status::no_pivot);
  EXPECT_EQ(run.outcome.failed_step, 5);
  EXPECT_TRUE(run.outcome.qdd.empty());
  EXPECT_NE(run.outcome.failure.find("level 1"), std::string::npos) << run.outcome.failure;
}

TEST_P(PipelineM, NonFiniteIsReportedByLevelThree) {
  auto system = elimination::random_system(6, 5);
  system.a[3][2] = std::numeric_limits<double>::quiet_NaN();
  const PipelineRun run =
      run_pipeline(GetParam(), system, rule(Pivoting::simple), t800::Precision::real64);
  EXPECT_TRUE(run.blocked.empty());
  EXPECT_EQ(run.outcome.status, Status::non_finite);
  EXPECT_EQ(run.outcome.failed_step, 0);
  EXPECT_NE(run.outcome.failure.find("level 3"), std::string::npos) << run.outcome.failure;
}

// With overlap the rows already in flight are not called back: a NaN is reported by level 3 at
// the step it appears in, the pipeline drains and gives no q̈; a singular system still stops at
// level 1 (it waited for every row before it gave up).
TEST_P(PipelineM, OverlapSingularSystemIsReportedAndNothingDeadlocks) {
  auto system = elimination::random_system(6, 5);
  for (auto& row : system.a) row[5] = 0;
  const PipelineRun run =
      run_pipeline(GetParam(), system, rule(Pivoting::simple), t800::Precision::real64, true);
  EXPECT_TRUE(run.blocked.empty());
  EXPECT_EQ(run.outcome.status, Status::no_pivot);
  EXPECT_EQ(run.outcome.failed_step, 5);
  EXPECT_TRUE(run.outcome.qdd.empty());
}

TEST_P(PipelineM, OverlapNonFiniteIsReportedByLevelThree) {
  auto system = elimination::random_system(6, 5);
  system.a[3][2] = std::numeric_limits<double>::quiet_NaN();
  const PipelineRun run =
      run_pipeline(GetParam(), system, rule(Pivoting::simple), t800::Precision::real64, true);
  EXPECT_TRUE(run.blocked.empty());
  EXPECT_EQ(run.outcome.status, Status::non_finite);
  EXPECT_EQ(run.outcome.failed_step, 0);
  EXPECT_TRUE(run.outcome.qdd.empty());
  EXPECT_NE(run.outcome.failure.find("level 3"), std::string::npos) << run.outcome.failure;
}

TEST_P(PipelineM, TinyPivotIsFlaggedByTheGrowthCheck) {
  auto system = elimination::random_system(6, 9);
  system.a[0][0] = 1e-15;
  const PipelineRun run =
      run_pipeline(GetParam(), system, rule(Pivoting::simple, 0, 1e8), t800::Precision::real64);
  EXPECT_TRUE(run.blocked.empty());
  EXPECT_EQ(run.outcome.status, Status::unstable);
  EXPECT_EQ(run.outcome.failed_step, 0);
  EXPECT_FALSE(run.outcome.qdd.empty());
  EXPECT_TRUE(run.matches_sequential);
}

INSTANTIATE_TEST_SUITE_P(Topologies, PipelineM, ::testing::Values(1, 2, 3, 4, 5),
                         [](const auto& info) { return "m" + std::to_string(info.param); });

TEST(Pipeline, RejectsATopologyWithTooFewLevelTwoProcessors) {
  const network::Topology topology =
      network::load_topology(test_paths::source_dir() + "/" + workloads::elimination_topology(2));
  workloads::PipelineSettings settings;
  settings.m = 3;
  try {
    workloads::EliminationPipeline pipeline(settings, reference_system(), topology);
    FAIL() << "m = 3 on a 2-processor topology was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("elimination-m3.toml"), std::string::npos) << e.what();
  }
}

}  // namespace
