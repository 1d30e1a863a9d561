// The pipeline's program structures (docs/table6.md): strict steps, overlapped steps
// (workload.overlap), and either with buffered level-2 processors (PipelineSettings::buffered:
// input, eliminator and output in PAR). Every structure changes when, never what: q̈ is
// bit-identical to the sequential solver. The Table6Structure tests run the Table 6 scene with
// each structure and print its figures (one simulation per process, so one test per figure):
//   cd build-t6 && ctest -R Table6Structure -V | grep TABLE6
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <limits>
#include <string>

#include "network/machine.hpp"
#include "network/topology_file.hpp"
#include "tests/elimination/elimination_fixtures.hpp"
#include "tests/elimination/pipeline_fixtures.hpp"
#include "tests/test_paths.hpp"
#include "tools/run_inputs.hpp"
#include "tools/scene.hpp"
#include "workloads/pipeline/pipeline.hpp"

namespace {

using namespace elimination_test;
using elimination::Pivoting;
using elimination::Status;

struct Structure {
  const char* name;
  bool overlap;
  bool buffered;
};

void PrintTo(const Structure& s, std::ostream* os) {
  *os << s.name;
}

constexpr Structure kStrict{"strict", false, false};
constexpr Structure kOverlap{"overlap", true, false};
constexpr Structure kBuffered{"buffered", false, true};
constexpr Structure kOverlapBuffered{"overlap_buffered", true, true};

// Every structure gives the sequential solver's q'', and the windows docs/table6.md reports lie
// inside Tp.
template <class T>
void expect_same_as_sequential(int m, const Structure& structure,
                               const elimination::LinearSystem<double>& system,
                               const elimination::PivotRule& r) {
  PipelineRun run;
  expect_same_as_sequential<T>(m, system, r, structure.overlap, structure.buffered, &run);
  if (!run.blocked.empty()) return;
  EXPECT_GE(run.outcome.level2_first_us, run.outcome.start_us);
  EXPECT_LE(run.outcome.level2_last_us, run.outcome.eliminated_us);
  EXPECT_LE(run.outcome.eliminated_us, run.outcome.end_us);
}

PipelineRun run_structure(int m, const Structure& structure,
                          const elimination::LinearSystem<double>& system,
                          const elimination::PivotRule& r, t800::Precision precision) {
  return run_pipeline(m, system, r, precision, structure.overlap, structure.buffered);
}

// Buffered level 2, strict and overlapped steps.
class Buffered : public ::testing::TestWithParam<std::tuple<int, bool>> {
 protected:
  int m() const { return std::get<0>(GetParam()); }
  Structure structure() const { return std::get<1>(GetParam()) ? kOverlapBuffered : kBuffered; }
};

TEST_P(Buffered, ArmReal64SimpleEqualsSequential) {
  expect_same_as_sequential<double>(m(), structure(), reference_system(), rule(Pivoting::simple));
}

TEST_P(Buffered, ArmReal32SimpleEqualsSequential) {
  expect_same_as_sequential<float>(m(), structure(), reference_system(), rule(Pivoting::simple));
}

TEST_P(Buffered, ArmReal32PartialEqualsSequential) {
  expect_same_as_sequential<float>(m(), structure(), reference_system(), rule(Pivoting::partial));
}

TEST_P(Buffered, RandomPartialWithInterchangesEqualsSequential) {
  const auto system = elimination::random_system(6, 7);
  ASSERT_GT(elimination::solve(system.a, system.b, rule(Pivoting::partial)).interchanges, 0);
  expect_same_as_sequential<double>(m(), structure(), system, rule(Pivoting::partial, 0, 1e8));
}

TEST_P(Buffered, ZeroPivotInterchangeEqualsSequential) {
  auto system = elimination::random_system(6, 3);
  system.a[0][0] = 0;
  expect_same_as_sequential<double>(m(), structure(), system, rule(Pivoting::simple));
}

TEST_P(Buffered, SingularSystemIsReportedAndNothingDeadlocks) {
  auto system = elimination::random_system(6, 5);
  for (auto& row : system.a) row[5] = 0;
  const PipelineRun run =
      run_structure(m(), structure(), system, rule(Pivoting::simple), t800::Precision::real64);
  EXPECT_TRUE(run.blocked.empty());
  EXPECT_EQ(run.outcome.status, Status::no_pivot);
  EXPECT_EQ(run.outcome.failed_step, 5);
  EXPECT_TRUE(run.outcome.qdd.empty());
}

TEST_P(Buffered, NonFiniteIsReportedByLevelThree) {
  auto system = elimination::random_system(6, 5);
  system.a[3][2] = std::numeric_limits<double>::quiet_NaN();
  const PipelineRun run =
      run_structure(m(), structure(), system, rule(Pivoting::simple), t800::Precision::real64);
  EXPECT_TRUE(run.blocked.empty());
  EXPECT_EQ(run.outcome.status, Status::non_finite);
  EXPECT_EQ(run.outcome.failed_step, 0);
  EXPECT_TRUE(run.outcome.qdd.empty());
  EXPECT_NE(run.outcome.failure.find("level 3"), std::string::npos) << run.outcome.failure;
}

INSTANTIATE_TEST_SUITE_P(Topologies, Buffered,
                         ::testing::Combine(::testing::Values(1, 2, 3, 4, 5), ::testing::Bool()),
                         [](const auto& info) {
                           return std::string(std::get<1>(info.param) ? "overlap_" : "strict_") +
                                  "m" + std::to_string(std::get<0>(info.param));
                         });

// ---- the Table 6 scene with each structure: one line of figures per test ----

class Table6Structure : public ::testing::TestWithParam<std::tuple<Structure, int>> {};

TEST_P(Table6Structure, Figures) {
  const auto& [structure, m] = GetParam();
  const tools::Scene scene =
      tools::load_scene(test_paths::source_dir() + "/" + workloads::kEliminationScene,
                        workloads::table6_overrides(m));
  const workloads::RunInputs in = tools::inputs_from(scene);
  const workloads::WorkloadContext context{in.params, in.topology, in.robot.get()};
  workloads::PipelineSettings settings = workloads::elimination_settings(in.params);
  settings.overlap = structure.overlap;
  settings.buffered = structure.buffered;
  network::Machine machine(in.topology, in.options);
  const auto workload = workloads::make_elimination_with(context, settings);
  workload->build(machine);
  ASSERT_TRUE(machine.run().empty());
  const workloads::ResultValue r = workload->results(machine);
  ASSERT_EQ(r.get("matches_sequential")->to_json(), "true");
  ASSERT_EQ(r.get("status")->to_json(), "\"ok\"");
  std::cout << "TABLE6 structure=" << structure.name << " m=" << m
            << " tp_us=" << r.get("tp_us")->number()
            << " elimination_us=" << r.get("elimination_us")->number()
            << " level2_window_us=" << r.get("level2_window_us")->number() << std::endl;
}

INSTANTIATE_TEST_SUITE_P(Scene, Table6Structure,
                         ::testing::Combine(::testing::Values(kStrict, kOverlap, kBuffered,
                                                              kOverlapBuffered),
                                            ::testing::Values(1, 2, 3, 4, 5)),
                         [](const auto& info) {
                           return std::string(std::get<0>(info.param).name) + "_m" +
                                  std::to_string(std::get<1>(info.param));
                         });

}  // namespace
