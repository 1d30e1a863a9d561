// The processor farm: its numbers are the sequential computation's, every subtask runs exactly once, and the
// utilisation it reports is its busy time over Tp.
#include <gtest/gtest.h>

#include <set>
#include <tuple>

#include "farm_fixtures.hpp"
#include "workloads/dynamics/assembly.hpp"
#include "workloads/dynamics/subtask_set.hpp"

namespace {

using Case = std::tuple<int, std::string, std::string>;  // workers, schedule, precision

class FarmCase : public ::testing::TestWithParam<Case> {};

template <class S>
dynamics::DynamicsData<S> sequential(const workloads::Params& p) {
  const auto model = farm_test::stanford();
  const auto subtasks = dynamics::derive_subtasks(*model, *dynamics::parse_model_variant(p.text("model")));
  dynamics::JointVector q, qd;
  for (int i = 0; i < dynamics::kJoints; ++i) {
    q(i) = p.real_list("q")[i];
    qd(i) = p.real_list("qd")[i];
  }
  dynamics::DynamicsData<S> data;
  dynamics::evaluate_all(*model, data, subtasks, q, qd);
  return data;
}

// The farm sends values as REAL32 or REAL64 and the master assembles them with the sequential code, so the
// results must be identical -- not merely close.
template <class S>
void expect_identical(const workloads::ResultValue& w, const dynamics::DynamicsData<S>& ref) {
  for (int i = 0; i < dynamics::kJoints; ++i) {
    for (int j = 0; j < dynamics::kJoints; ++j)
      EXPECT_EQ(w.get("D")->items()[i].items()[j].number(), double(ref.D(i, j))) << "D" << i + 1 << j + 1;
    EXPECT_EQ(w.get("c")->items()[i].number(), double(ref.c(i))) << "c" << i + 1;
    EXPECT_EQ(w.get("h")->items()[i].number(), double(ref.h(i))) << "h" << i + 1;
  }
}

TEST_P(FarmCase, ResultsEqualTheSequentialComputationExactly) {
  const auto& [workers, schedule, precision] = GetParam();
  const auto params = farm_test::farm_params(schedule, precision);
  const auto report = farm_test::run_farm(workers, params);
  ASSERT_TRUE(report.blocked.empty());
  if (precision == "real32")
    expect_identical(report.workload, sequential<float>(params));
  else
    expect_identical(report.workload, sequential<double>(params));
}

TEST_P(FarmCase, EverySubtaskRunsExactlyOnce) {
  const auto& [workers, schedule, precision] = GetParam();
  const auto params = farm_test::farm_params(schedule, precision);
  const auto report = farm_test::run_farm(workers, params);
  ASSERT_TRUE(report.blocked.empty());
  std::multiset<std::string> done;
  for (const auto& w : report.workload.get("per_worker")->items())
    for (const auto& name : w.get("subtasks")->items()) done.insert(name.to_text());
  const auto expected = dynamics::derive_subtasks(*farm_test::stanford(), dynamics::ModelVariant::paper);
  ASSERT_EQ(done.size(), expected.size());
  for (const auto& s : expected) EXPECT_EQ(done.count(s.name), 1u) << s.name;
}

TEST_P(FarmCase, UtilisationIsBusyTimeOverTp) {
  const auto& [workers, schedule, precision] = GetParam();
  // With the evaluation window, a worker's busy time in Tp is all its busy time: compare with the report's.
  const auto params = farm_test::farm_params(schedule, precision, "paper", "evaluation");
  const auto report = farm_test::run_farm(workers, params);
  ASSERT_TRUE(report.blocked.empty());
  const double tp = report.workload.get("tp_us")->number();
  const auto& rows = report.workload.get("per_worker")->items();
  ASSERT_EQ(rows.size(), std::size_t(workers));
  for (const auto& row : rows) {
    const std::string name = row.get("name")->to_text();
    const auto* proc = &report.processors.front();
    for (const auto& p : report.processors)
      if (p.name == name) proc = &p;
    EXPECT_NEAR(row.get("busy_in_tp_us")->number(), proc->busy_us, 1e-6) << name;
    EXPECT_NEAR(row.get("utilisation_pct")->number(), 100.0 * proc->busy_us / tp, 1e-9) << name;
    EXPECT_LE(row.get("utilisation_pct")->number(), 100.0 + 1e-9) << name;
  }
}

INSTANTIATE_TEST_SUITE_P(
    PaperNetworks, FarmCase,
    ::testing::Combine(::testing::Values(1, 3, 6, 9), ::testing::Values("static", "on-demand"),
                       ::testing::Values("real32", "real64")),
    [](const auto& info) {
      std::string s = std::to_string(std::get<0>(info.param)) + "_" + std::get<1>(info.param) + "_" +
                      std::get<2>(info.param);
      for (char& c : s)
        if (c == '-') c = '_';
      return s;
    });

TEST(Farm, FullModelRunsAllEightyTwoSubtasks) {
  const auto report = farm_test::run_farm(6, farm_test::farm_params("static", "real64", "full"));
  ASSERT_TRUE(report.blocked.empty());
  EXPECT_EQ(report.workload.get("subtasks")->number(), 82);
}

TEST(Farm, MoreWorkersThanSubtasksLeavesSomeIdle) {
  const auto report = farm_test::run_farm(70, farm_test::farm_params("static", "real32"));
  ASSERT_TRUE(report.blocked.empty());
  int idle = 0;
  for (const auto& w : report.workload.get("per_worker")->items()) idle += w.get("subtasks")->items().empty();
  EXPECT_GE(idle, 70 - 64);
}

// The farm window lies inside the evaluation window: the master's sin/cos and assembly are outside it.
TEST(Farm, FarmWindowExcludesTheMastersOwnWork) {
  const auto report = farm_test::run_farm(3, farm_test::farm_params("static", "real32"));
  ASSERT_TRUE(report.blocked.empty());
  EXPECT_LT(report.workload.get("farm_us")->number(), report.workload.get("evaluation_us")->number());
  EXPECT_EQ(report.workload.get("tp_us")->number(), report.workload.get("farm_us")->number());
}

}  // namespace
