#include "workloads/farm/farm_tasks.hpp"

#include "workloads/dynamics/assembly.hpp"
#include "workloads/dynamics/evaluate.hpp"
#include "workloads/dynamics/worker_input.hpp"

namespace workloads {

FarmWork farm_work(const dynamics::RobotModel& model, dynamics::ModelVariant variant,
                   const t800::CostModel& cost) {
  FarmWork work;
  const std::vector<dynamics::Subtask> subtasks = dynamics::derive_subtasks(model, variant);
  for (const dynamics::Subtask& s : subtasks) {
    FarmTask t;
    t.subtask = s;
    t.ops = dynamics::count_ops(model, s);
    t.mix = to_operation_mix(t.ops);
    t.cycles = cost.cycles(t.mix);
    work.tasks.push_back(t);
  }
  work.master_input = to_operation_mix(dynamics::count_input_ops(model));
  work.master_assembly = to_operation_mix(dynamics::count_assembly_ops(subtasks));
  return work;
}

}  // namespace workloads
