// One run of the elimination pipeline on its elimination-m<m> topology, and the check every
// structure must pass: q'' bit-identical to the sequential solver (same precision, same pivoting).
// Shared by the pipeline and structure tests; one simulation per test process.
#pragma once

#include <gtest/gtest.h>

#include <string>
#include <type_traits>
#include <vector>

#include "network/machine.hpp"
#include "network/topology_file.hpp"
#include "tests/test_paths.hpp"
#include "workloads/elimination/gauss.hpp"
#include "workloads/pipeline/pipeline.hpp"

namespace elimination_test {

struct PipelineRun {
  workloads::PipelineOutcome outcome;
  std::vector<network::BlockedProcess> blocked;
  bool matches_sequential = false;
};

inline PipelineRun run_pipeline(int m, const elimination::LinearSystem<double>& system,
                                const elimination::PivotRule& r, t800::Precision precision,
                                bool overlap = false, bool buffered = false) {
  const network::Topology topology =
      network::load_topology(test_paths::source_dir() + "/" + workloads::elimination_topology(m));
  network::MachineOptions options;
  options.precision = precision;
  network::Machine machine(topology, options);
  workloads::PipelineSettings settings;
  settings.m = m;
  settings.precision = precision;
  settings.rule = r;
  settings.overlap = overlap;
  settings.buffered = buffered;
  workloads::EliminationPipeline pipeline(settings, system, topology);
  pipeline.build(machine);
  PipelineRun run;
  run.blocked = machine.run();
  run.outcome = pipeline.outcome();
  if (run.blocked.empty())
    run.matches_sequential =
        pipeline.results(machine).get("matches_sequential")->to_json() == "true";
  return run;
}

template <class T>
void expect_same_as_sequential(int m, const elimination::LinearSystem<double>& system,
                               const elimination::PivotRule& r, bool overlap = false,
                               bool buffered = false, PipelineRun* result = nullptr) {
  const auto precision =
      std::is_same_v<T, double> ? t800::Precision::real64 : t800::Precision::real32;
  const PipelineRun run = run_pipeline(m, system, r, precision, overlap, buffered);
  if (result) *result = run;
  ASSERT_TRUE(run.blocked.empty())
      << run.blocked.front().process << ": " << run.blocked.front().status;
  const auto data = elimination::convert<T>(system);
  const auto expected = elimination::solve(data.a, data.b, r);
  ASSERT_EQ(run.outcome.status, expected.status);
  ASSERT_EQ(run.outcome.qdd.size(), expected.x.size());
  for (std::size_t i = 0; i < expected.x.size(); ++i)
    EXPECT_EQ(run.outcome.qdd[i], static_cast<double>(expected.x[i])) << "unknown " << i;  // exact
  EXPECT_EQ(run.outcome.pivot_rows, expected.pivot_rows);
  EXPECT_EQ(run.outcome.interchanges, expected.interchanges);
  EXPECT_TRUE(run.matches_sequential);
  EXPECT_GT(run.outcome.tp_us(), 0.0);
}

}  // namespace elimination_test
