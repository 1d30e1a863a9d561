// The dynamics subtasks as a farm sees them: what each costs on a T800 (cycles from its counted operations
// through t800::CostModel), plus the master's own work.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "t800/cost_model.hpp"
#include "t800/operation_mix.hpp"
#include "workloads/dynamics/op_counts.hpp"
#include "workloads/dynamics/robot_model.hpp"
#include "workloads/dynamics/subtask.hpp"
#include "workloads/dynamics/subtask_set.hpp"
#include "workloads/run/operation_mix.hpp"

namespace workloads {

struct FarmTask {
  dynamics::Subtask subtask;
  dynamics::OpCounts ops;
  t800::OperationMix mix;
  std::int64_t cycles = 0;
};

struct FarmWork {
  std::vector<FarmTask> tasks;       // in the order of the subtask list
  t800::OperationMix master_input;   // sin/cos of the joint angles, once per evaluation
  t800::OperationMix master_assembly;  // forming c from the C terms
};

FarmWork farm_work(const dynamics::RobotModel& model, dynamics::ModelVariant variant,
                   const t800::CostModel& cost);

}  // namespace workloads
