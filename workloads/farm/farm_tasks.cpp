#include "workloads/farm/farm_tasks.hpp"

#include "workloads/dynamics/assembly.hpp"
#include "workloads/dynamics/evaluate.hpp"
#include "workloads/dynamics/worker_input.hpp"

namespace workloads {

FarmWork farm_work(const dynamics::RobotModel& model, dynamics::ModelVariant variant,
                   const t800::ComputeModel& worker, bool real64) {
  FarmWork work;
  const std::vector<dynamics::Subtask> subtasks = dynamics::derive_subtasks(model, variant);
  for (const dynamics::Subtask& s : subtasks) {
    FarmTask t;
    t.subtask = s;
    t.ops = dynamics::count_ops(model, s);
    t.work = {to_operation_mix(t.ops), dynamics::record_subtask(model, s, real64)};
    t.cycles = worker.cycles(t.work);
    work.tasks.push_back(std::move(t));
  }
  work.master_input = {to_operation_mix(dynamics::count_input_ops(model)),
                       dynamics::record_input(model, real64)};
  work.master_assembly = {to_operation_mix(dynamics::count_assembly_ops(subtasks)),
                          dynamics::record_assembly(subtasks, real64)};
  return work;
}

}  // namespace workloads
