// The paper's processor farm as a program that serves evaluations, built on the SDK's farm
// skeleton (t800sim/farm.hpp): a master process calls evaluate() for each state (once for Table 4,
// four times per RK4 step in a trajectory); the workers loop over rounds until finish(). Used by
// the dynamics-farm and trajectory workloads.
//
// One round: the master computes sin/cos of the joint angles once and sends them to every worker
// (the skeleton's shared input, one message of REALs); workers evaluate their subtasks -- each
// costed by the code that computes it -- and return the values; the master forms c and assembles
// D, C, h. Workers that are not the master's neighbours are reached through software routers on
// the processors between (network/transport/store_and_forward.hpp).
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "network/machine.hpp"
#include "t800sim/farm.hpp"
#include "workloads/dynamics/assembly.hpp"
#include "workloads/dynamics/replay.hpp"
#include "workloads/dynamics/subtask_set.hpp"
#include "workloads/farm/farm_tasks.hpp"

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
  // output to each worker and its wait for the results give up at a deadline and the subtasks of a
  // worker that failed are handed to the others (t800sim/farm.hpp). Each worker then holds every
  // subtask's code, as on demand.
  bool recovery = false;
  // How long the master waits for a worker beyond its predicted time (0: that predicted time again,
  // plus 50 us).
  double timeout_us = 0;
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
  FarmRound evaluate(t800sim::Process& master, const dynamics::JointVector& q,
                     const dynamics::JointVector& qd, dynamics::DynamicsData<S>& data);
  // What evaluate() gives, computed on the host without simulating the round (a trajectory's
  // sequential numerics): the same message, each subtask's value as the workers compute it, the
  // same assembly; bit-identical to a round's.
  void evaluate_on_host(const dynamics::JointVector& q, const dynamics::JointVector& qd,
                        dynamics::DynamicsData<S>& data);
  // Called from the master's process after the last evaluation: every worker ends.
  void finish(t800sim::Process& master);

  // Before build(): see FarmSettings::skip_numerics.
  void set_skip_numerics(bool skip) { settings_.skip_numerics = skip; }
  bool skips_numerics() const { return settings_.skip_numerics; }

  const FarmWork& work() const { return work_; }
  const std::vector<int>& workers() const { return workers_; }
  // The subtasks each worker ran in the last round (indices into work().tasks).
  const std::vector<std::vector<int>>& done_by() const { return farm_->done_by(); }
  const std::vector<dynamics::Subtask>& subtasks() const { return subtasks_; }

 private:
  // The shared input: the worker input's REALs in message order (dynamics::message_fields), one
  // message; each subtask's result: one REAL.
  using Skeleton = t800sim::Farm<t800sim::Block<S>, S>;
  t800sim::FarmOptions options() const;
  S run_subtask(int task, const std::vector<S>& shared) const;
  S kernel_value(int task, const std::vector<S>& shared) const;  // evaluate_subtask<S> itself
  std::vector<S> message_for(const dynamics::JointVector& q) const;
  void count_evaluation();

  const dynamics::RobotModel& model_;
  FarmSettings settings_;
  int master_;
  std::vector<int> workers_;
  FarmWork work_;
  std::vector<dynamics::Subtask> subtasks_;  // work_.tasks' subtasks, in order (assemble's input)
  // The subtasks' kernels traced for the host (dynamics/replay.hpp), from the second evaluation on:
  // what run_subtask evaluates then.
  std::optional<dynamics::SubtaskReplay<S>> replay_;
  int rounds_ = 0;                             // evaluations so far
  std::unique_ptr<t800sim::Builder> builder_;  // owns the channels the skeleton's handles name
  std::unique_ptr<Skeleton> farm_;
};

// The host's part of a farm workload, after the farm (and whatever else) is built: the host sends
// the state (q, q̇: 2 × 6 REALs of S) on channel "state" to the process "master" on processor
// `master`, which takes it and runs `body`. `label` names the message in traces. The returned
// Builder owns the channel: keep it for the run.
template <class S>
std::unique_ptr<t800sim::Builder> spawn_host_and_master(network::Machine& m, int master,
                                                        const std::string& label,
                                                        const t800sim::Process::Body& body);

extern template class FarmProgram<float>;
extern template class FarmProgram<double>;

}  // namespace workloads
