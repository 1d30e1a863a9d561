// The static list scheduler and explicit allocations.
#include <gtest/gtest.h>

#include <numeric>
#include <set>

#include "t800sim/farm_schedule.hpp"

using t800sim::Allocation;
using t800sim::WorkerCosts;

namespace {

double makespan(const Allocation& a, const std::vector<double>& t,
                const std::vector<WorkerCosts>& w) {
  const auto f = t800sim::estimated_finish_ns(a, t, w);
  return *std::max_element(f.begin(), f.end());
}

void expect_each_task_once(const Allocation& a, std::size_t tasks) {
  std::multiset<int> seen;
  for (const auto& w : a) seen.insert(w.begin(), w.end());
  ASSERT_EQ(seen.size(), tasks);
  for (std::size_t t = 0; t < tasks; ++t) EXPECT_EQ(seen.count(int(t)), 1u) << t;
}

}  // namespace

TEST(StaticSchedule, EqualTasksOnEqualWorkersBalancePerfectly) {
  const std::vector<double> tasks(12, 100.0);
  const std::vector<WorkerCosts> workers(4);
  const Allocation a = t800sim::schedule_static(tasks, workers);
  expect_each_task_once(a, tasks.size());
  for (const auto& w : a) EXPECT_EQ(w.size(), 3u);
}

// Graham's bound for any list schedule on identical machines: makespan <= sum/m + (1 - 1/m) max;
// and no schedule beats max(sum/m, max). The local search only lowers the makespan, so the bound
// holds after it too.
TEST(StaticSchedule, WithinGrahamsListSchedulingBound) {
  std::vector<double> tasks;
  for (int i = 0; i < 64; ++i) tasks.push_back(double((i * 7919) % 997 + 50));
  for (int m : {3, 6, 9}) {
    const std::vector<WorkerCosts> workers(m);
    const Allocation a = t800sim::schedule_static(tasks, workers);
    expect_each_task_once(a, tasks.size());
    const double sum = std::accumulate(tasks.begin(), tasks.end(), 0.0);
    const double lower = std::max(sum / m, *std::max_element(tasks.begin(), tasks.end()));
    const double longest = *std::max_element(tasks.begin(), tasks.end());
    EXPECT_LE(makespan(a, tasks, workers), sum / m + (1.0 - 1.0 / m) * longest + 1e-9) << m;
    EXPECT_GE(makespan(a, tasks, workers), lower - 1e-9);
  }
}

// A worker that starts late (further from the master) gets less work.
TEST(StaticSchedule, DistantWorkersGetLessWork) {
  const std::vector<double> tasks(30, 100.0);
  std::vector<WorkerCosts> workers(2);
  workers[1].start_ns = 1000;  // ten tasks late
  const Allocation a = t800sim::schedule_static(tasks, workers);
  EXPECT_GT(a[0].size(), a[1].size());
  EXPECT_LE(makespan(a, tasks, workers), 2100.0);
}

TEST(ExplicitAllocation, ParsesWorkersAndTasks) {
  const Allocation a =
      t800sim::parse_allocation("P1: D11 h2 ; P2: C1_23", {"D11", "C1_23", "h2"}, {"P1", "P2"});
  EXPECT_EQ(a[0], (std::vector<int>{0, 2}));
  EXPECT_EQ(a[1], (std::vector<int>{1}));
}

TEST(ExplicitAllocation, ErrorsNameTheProblem) {
  const std::vector<std::string> tasks{"D11", "D12"}, workers{"P1", "P2"};
  auto message = [&](const std::string& text) {
    try {
      t800sim::parse_allocation(text, tasks, workers);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message("P1: D11").find("D12 is given to no worker"), std::string::npos);
  EXPECT_NE(message("P1: D11 D12; P2: D11").find("given to both P1 and P2"), std::string::npos);
  EXPECT_NE(message("P7: D11 D12").find("'P7' is not a worker"), std::string::npos);
  EXPECT_NE(message("P1: D11 X99").find("no task 'X99'"), std::string::npos);
  EXPECT_NE(message("D11 D12").find("WORKER: TASK"), std::string::npos);
}
