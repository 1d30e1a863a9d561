// The paper's processor farm as a program that serves evaluations: a master process calls
// evaluate() for each state (once for Table 4, four times per RK4 step in a trajectory); the
// workers loop over rounds until finish(). Used by the dynamics-farm and trajectory workloads.
//
// One round: the master computes sin/cos of the joint angles once and sends them to every worker;
// workers evaluate their subtasks -- each costed by the operations of the code that computes it --
// and return the values; the master forms c and assembles D, C, h. Workers that are not the
// master's neighbours are reached through software routers on the processors between
// (network/channel.hpp).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "network/machine.hpp"
#include "workloads/dynamics/assembly.hpp"
#include "workloads/dynamics/subtask_set.hpp"
#include "workloads/dynamics/worker_input.hpp"
#include "workloads/farm/farm_tasks.hpp"
#include "workloads/farm/schedule.hpp"

namespace workloads {

struct FarmSettings {
  dynamics::ModelVariant variant = dynamics::ModelVariant::paper;
  std::string schedule = "static";  // static | on-demand | explicit
  std::string allocation;           // for explicit
  int buffer = 2;                   // on-demand: subtasks in flight per worker
  // Timing only (fidelity.skip_numerics): no subtask is evaluated and nothing is assembled; every
  // message keeps its size and every piece of work its cost, which come from the operations counted
  // once when the farm is built (farm_work), never from evaluating. The values stay zero.
  bool skip_numerics = false;
  // Recovery from a halted or unreachable worker (static and explicit schedules): the master's
  // output to each worker and its wait for the results give up at a deadline (OutputOrFail /
  // InputOrFail, network/reliable.hpp) and the subtasks of a worker that failed are handed to the
  // others. Each worker then holds every subtask's code, as on demand.
  bool recovery = false;
  // How long the master waits for a worker beyond its predicted time (0: that predicted time again,
  // plus 50 us).
  double timeout_us = 0;
};

// What the master sends a worker each round: the state (nullopt: finish) and the subtasks to
// evaluate, in the order the results come back. The list is part of the compiled program (the
// allocation), so it costs no bytes, except in a recovery's order, which sends it.
template <class S>
struct WorkerOrder {
  std::optional<dynamics::WorkerInput<S>> input;
  std::vector<int> tasks;
};

// The timing of one round, as the master saw it.
struct FarmRound {
  double start_us = 0, end_us = 0;            // evaluate() called -> D, C, c, h assembled
  double farm_start_us = 0, farm_end_us = 0;  // first input sent -> last result received
  std::vector<double> busy_in_farm_us;        // per worker, its busy time inside the farm window
};

template <class S>
class FarmProgram {
 public:
  FarmProgram(const dynamics::RobotModel& model, FarmSettings settings, int master,
              std::vector<int> workers);

  // Before the run: works out the costs and the allocation, declares the channels, places the
  // workers, declares the master's code as that of its process `master_process`.
  void build(network::Machine& m, const std::string& master_process = "master");
  // Called from the master's process: one evaluation at (q, qd) into `data`.
  FarmRound evaluate(network::Process& master, const dynamics::JointVector& q,
                     const dynamics::JointVector& qd, dynamics::DynamicsData<S>& data);
  // Called from the master's process after the last evaluation: every worker ends.
  void finish(network::Process& master);

  // Before build(): see FarmSettings::skip_numerics.
  void set_skip_numerics(bool skip) { settings_.skip_numerics = skip; }
  bool skips_numerics() const { return settings_.skip_numerics; }

  const FarmWork& work() const { return work_; }
  const std::vector<int>& workers() const { return workers_; }
  // The subtasks each worker ran in the last round (indices into work().tasks).
  const std::vector<std::vector<int>>& done_by() const { return done_by_; }
  // Workers the master gave up on (recovery), in the order it did.
  const std::vector<int>& lost_workers() const { return lost_; }
  // The master's last round's recovery: when it noticed a failed worker, when the reassigned
  // subtasks' results were all in (both -1 without one).
  double recovery_started_us() const { return recovery_started_us_; }
  double recovery_done_us() const { return recovery_done_us_; }
  std::vector<dynamics::Subtask> subtasks() const;

 private:
  static constexpr std::int64_t kReal = sizeof(S);
  Allocation allocate(const network::Machine& m) const;
  bool has_work(std::size_t w) const;
  std::vector<double> workers_busy_now(network::Machine& m) const;
  void collect(network::Process& p, std::size_t w, dynamics::DynamicsData<S>& data);
  // Recovery: the order out and the results back, each with a deadline; false when either failed.
  bool exchange(network::Process& p, std::size_t w, const WorkerOrder<S>& order, std::int64_t bytes,
                dynamics::DynamicsData<S>& data);
  void reassign(network::Process& p, const std::optional<dynamics::WorkerInput<S>>& input,
                std::int64_t input_bytes, dynamics::DynamicsData<S>& data);
  double predicted_us(const network::Machine& m, std::size_t w,
                      const std::vector<int>& tasks) const;
  bool alive(std::size_t w) const;
  void hand_out(network::Process& p, std::size_t w, dynamics::DynamicsData<S>& data);
  void worker(network::Process& p, std::size_t w);
  void static_round(network::Process& p, std::size_t w, const std::vector<int>& tasks,
                    const dynamics::WorkerInput<S>& input);
  void on_demand_round(network::Process& p, std::size_t w, const dynamics::WorkerInput<S>& input);
  S run_task(network::Process& p, int t, const dynamics::WorkerInput<S>& input);
  const std::vector<int>& dispatch_order();

  const dynamics::RobotModel& model_;
  FarmSettings settings_;
  int master_;
  std::vector<int> workers_;
  FarmWork work_;
  Allocation allocation_;
  std::vector<network::Channel*> to_, from_, queue_;
  std::vector<std::vector<int>> done_by_;
  std::vector<int> order_;
  int next_ = 0;
  std::vector<int> lost_;            // node indices
  std::vector<std::size_t> failed_;  // this round's
  double recovery_started_us_ = -1, recovery_done_us_ = -1;
};

extern template class FarmProgram<float>;
extern template class FarmProgram<double>;

}  // namespace workloads
