// The farm skeleton (t800sim/farm.hpp) over a toy task type: task i sums k * x for k = 1 .. i + 1,
// whose closed form is x (i + 1)(i + 2) / 2 (exact in REAL64 for the x used: halves and integers).
// Every schedule, round after round, on a tree whose deeper workers are reached through routers;
// with recovery, a halted worker's tasks are done by the others and the results stay exact.
#include <gtest/gtest.h>

#include <set>
#include <tuple>

#include "network/faults.hpp"
#include "sdk_fixtures.hpp"
#include "t800sim/farm.hpp"

namespace {

using namespace t800sim;

constexpr int kTasks = 12;
using ToyFarm = Farm<REAL64, REAL64>;

double closed_form(int task, double x) {
  return x * double(task + 1) * double(task + 2) / 2.0;
}

// The PROC a worker runs for task i, recorded (its loop of i + 1 multiply-adds sets its cost).
Kernel sum_kernel(int task) {
  return record_kernel<Real64>("SUM" + std::to_string(task), [task] {
    Real64 s = 0.0, x = 1.0;
    declare_variable(s, "s");
    declare_variable(x, "x");
    for (std::size_t k : seq<Real64>(std::size_t(task) + 1)) s = s + Real64(double(k + 1)) * x;
  });
}

std::vector<FarmTask> toy_tasks() {
  std::vector<FarmTask> tasks;
  for (int i = 0; i < kTasks; ++i) tasks.push_back({"t" + std::to_string(i), sum_kernel(i)});
  return tasks;
}

double toy_work(int task, const double& x) {
  double s = 0;
  for (int k = 1; k <= task + 1; ++k) s += double(k) * x;
  return s;
}

struct Rounds {
  std::vector<std::vector<double>> results;  // per round, per task
  std::vector<std::vector<std::vector<int>>> done_by;
  std::vector<FarmRoundTiming> timing;
  std::vector<std::string> lost;
  std::vector<network::BlockedProcess> blocked;
};

const std::vector<double> kShared{0.5, -3.0, 1024.25};

const std::vector<std::string> kFiveWorkers{"P1", "P2", "P3", "P4", "P5"};

// A master on P0 calling three rounds, then finish, on a tree of 5 workers (P4 and P5 are not P0's
// neighbours: their channels are routed).
Rounds run_toy(const FarmOptions& options, const std::vector<network::FaultSpec>& faults = {},
               const std::vector<std::string>& workers = kFiveWorkers) {
  Rounds out;
  ToyFarm farm(toy_tasks(), toy_work, options);
  const network::Topology topology =
      network::generate(network::Family::tree, 5, {}, {"test", 0, 0});
  network::MachineOptions machine_options;
  machine_options.link.speed_mbps = 20;
  network::Machine machine(topology, machine_options);
  for (const network::FaultSpec& f : faults) machine.faults().add(f);
  network::arm_faults(machine);
  auto* program = new sdk_test::Lambda([&](Builder& b) {
    b.process("master", [&](Process& p) {
       for (double x : kShared) {
         out.results.push_back(farm.round(p, x));
         out.done_by.push_back(farm.done_by());
         out.timing.push_back(farm.last_round());
       }
       farm.finish(p);
       out.lost = farm.lost_workers();
     }).placed_on("P0");
    farm.build(b, "master", workers);
  });
  const workloads::Params params;
  const workloads::Placement placement;
  const workloads::WorkloadContext context{params, topology, nullptr, &placement};
  detail::ProgramWorkload workload("toy-farm", std::unique_ptr<Program>(program), context);
  workload.build(machine);
  out.blocked = machine.run();
  return out;
}

void expect_exact(const Rounds& r) {
  ASSERT_EQ(r.results.size(), kShared.size());
  for (std::size_t round = 0; round < kShared.size(); ++round) {
    ASSERT_EQ(r.results[round].size(), std::size_t(kTasks));
    for (int t = 0; t < kTasks; ++t)
      EXPECT_EQ(r.results[round][std::size_t(t)], closed_form(t, kShared[round]))
          << "round " << round << " task " << t;
  }
}

// Each round, every task ran exactly once.
void expect_each_task_once_a_round(const Rounds& r) {
  for (const auto& round : r.done_by) {
    std::multiset<int> done;
    for (const auto& tasks : round) done.insert(tasks.begin(), tasks.end());
    ASSERT_EQ(done.size(), std::size_t(kTasks));
    for (int t = 0; t < kTasks; ++t) EXPECT_EQ(done.count(t), 1u) << "task " << t;
  }
}

FarmOptions with(FarmSchedule s) {
  FarmOptions o;
  o.schedule = s;
  o.allocation = "P1: t0 t1 t2; P2: t3 t4; P3: t5 t6 t7; P4: t8 t9; P5: t10 t11";
  return o;
}

class ToyFarmSchedules : public ::testing::TestWithParam<FarmSchedule> {};

TEST_P(ToyFarmSchedules, EveryRoundGivesTheClosedFormSums) {
  const Rounds r = run_toy(with(GetParam()));
  ASSERT_TRUE(r.blocked.empty());
  expect_exact(r);
  expect_each_task_once_a_round(r);
  for (const FarmRoundTiming& t : r.timing) {
    EXPECT_GT(t.end_us, t.start_us);
    ASSERT_EQ(t.busy_us.size(), 5u);
  }
}

std::string schedule_name(const ::testing::TestParamInfo<FarmSchedule>& info) {
  switch (info.param) {
    case FarmSchedule::static_list:
      return "StaticList";
    case FarmSchedule::on_demand:
      return "OnDemand";
    case FarmSchedule::explicit_allocation:
      return "Explicit";
  }
  return "Unknown";
}

INSTANTIATE_TEST_SUITE_P(Each, ToyFarmSchedules,
                         ::testing::Values(FarmSchedule::static_list, FarmSchedule::on_demand,
                                           FarmSchedule::explicit_allocation),
                         schedule_name);

// The on-demand master either way (a PAR of dialogues or one ALT), results sent directly or through
// a buffer, tasks longest first or in order: the same exact sums, each task once.
class ToyFarmOnDemand : public ::testing::TestWithParam<std::tuple<bool, bool, bool>> {};

TEST_P(ToyFarmOnDemand, EveryRoundGivesTheClosedFormSums) {
  FarmOptions o = with(FarmSchedule::on_demand);
  std::tie(o.alt_master, o.buffered_replies, o.longest_first) = GetParam();
  const Rounds r = run_toy(o);
  ASSERT_TRUE(r.blocked.empty());
  expect_exact(r);
  expect_each_task_once_a_round(r);
}

INSTANTIATE_TEST_SUITE_P(AltBufferedLongestFirst, ToyFarmOnDemand,
                         ::testing::Combine(::testing::Bool(), ::testing::Bool(),
                                            ::testing::Bool()));

// Task i loops i + 1 times, so the tasks' costs grow with i: one worker runs them from t11 down
// longest first, from t0 up in order.
std::vector<int> one_workers_tasks(bool longest_first) {
  FarmOptions o = with(FarmSchedule::on_demand);
  o.alt_master = true;
  o.longest_first = longest_first;
  const Rounds r = run_toy(o, {}, {"P1"});
  EXPECT_TRUE(r.blocked.empty());
  return r.done_by.front().front();
}

TEST(ToyFarm, OnDemandTasksGoLongestFirst) {
  std::vector<int> down;
  for (int t = kTasks - 1; t >= 0; --t) down.push_back(t);
  EXPECT_EQ(one_workers_tasks(true), down);
}

TEST(ToyFarm, OnDemandTasksGoInTheirOrder) {
  std::vector<int> up;
  for (int t = 0; t < kTasks; ++t) up.push_back(t);
  EXPECT_EQ(one_workers_tasks(false), up);
}

TEST(ToyFarm, OnDemandSettingsWithAStaticScheduleAreAnError) {
  FarmOptions o = with(FarmSchedule::static_list);
  o.alt_master = true;
  EXPECT_THROW(ToyFarm(toy_tasks(), toy_work, o), std::invalid_argument);
}

TEST(ToyFarm, AnExplicitAllocationIsFollowed) {
  const Rounds r = run_toy(with(FarmSchedule::explicit_allocation));
  ASSERT_TRUE(r.blocked.empty());
  EXPECT_EQ(r.done_by.front()[1], (std::vector<int>{3, 4}));    // P2
  EXPECT_EQ(r.done_by.front()[4], (std::vector<int>{10, 11}));  // P5
}

// Twelve tasks of growing cost on five workers: list scheduling leaves nobody idle.
TEST(ToyFarm, TheStaticScheduleUsesEveryWorker) {
  const Rounds r = run_toy(with(FarmSchedule::static_list));
  ASSERT_TRUE(r.blocked.empty());
  for (const auto& tasks : r.done_by.front()) EXPECT_FALSE(tasks.empty());
}

TEST(ToyFarm, AnExplicitAllocationNamingAnUnknownTaskIsAnErrorNamingIt) {
  FarmOptions o = with(FarmSchedule::explicit_allocation);
  o.allocation = "P1: t0 t1 t2 t3 t4 t5 t99";
  try {
    run_toy(o);
    FAIL() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("no task 't99'"), std::string::npos) << e.what();
  }
}

// P2 halts before the first round, and P5 behind it (its channels are routed through P2) goes
// with it: the master's deadlines give both up, their tasks go to the others, and every round's
// sums are still exact.
TEST(ToyFarm, RecoveryReassignsAHaltedWorkersTasks) {
  FarmOptions o = with(FarmSchedule::static_list);
  o.recovery = true;
  network::FaultSpec halt;
  halt.kind = network::FaultSpec::Kind::halt;
  halt.processor = "P2";
  halt.at_us = 0;
  const Rounds r = run_toy(o, {halt});
  expect_exact(r);
  expect_each_task_once_a_round(r);
  EXPECT_EQ(r.lost, (std::vector<std::string>{"P2", "P5"}));
  // Only the lost subtree's workers are left waiting: P2's, halted, and P5's, cut off by it.
  for (const auto& b : r.blocked)
    EXPECT_TRUE(b.processor == "P2" || b.processor == "P5") << b.process;
}

}  // namespace
