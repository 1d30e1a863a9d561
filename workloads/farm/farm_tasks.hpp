// The dynamics subtasks as a farm sees them: what each is (its recorded code and its operation
// mix) and what it costs on a T800, plus the master's own work.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "t800/compute_model.hpp"
#include "t800/compute_work.hpp"
#include "workloads/dynamics/op_counts.hpp"
#include "workloads/dynamics/robot_model.hpp"
#include "workloads/dynamics/subtask.hpp"
#include "workloads/dynamics/subtask_set.hpp"
#include "workloads/run/operation_mix.hpp"

namespace workloads {

struct FarmTask {
  dynamics::Subtask subtask;
  dynamics::OpCounts ops;
  t800::ComputeWork work;
  // Its cost on a worker with everything in on-chip RAM: what a static schedule plans with (the
  // programmer's estimate; the run then places memory and times it as placed).
  std::int64_t cycles = 0;
};

struct FarmWork {
  std::vector<FarmTask> tasks;         // in the order of the subtask list
  t800::ComputeWork master_input;      // sin/cos of the joint angles, once per evaluation
  t800::ComputeWork master_assembly;   // forming c from the C terms
};

FarmWork farm_work(const dynamics::RobotModel& model, dynamics::ModelVariant variant,
                   const t800::ComputeModel& worker, bool real64);

}  // namespace workloads
