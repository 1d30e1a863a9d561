// A farm's static allocation of tasks to workers, decided before the run from the tasks' costs and
// the workers' communication distances -- as the paper's pre-computed allocation tables were
// (t800sim/farm.hpp schedules with it; a program may call it directly).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace t800sim {

// The estimated timing of one worker that does not depend on which tasks it gets: the delay before
// it can start (its input message reaching it through 0 or more routers) and the cost of returning
// each result (bytes over its hops), in nanoseconds.
struct WorkerCosts {
  double start_ns = 0;
  double per_result_ns = 0;
  double finish_ns = 0;  // fixed part of returning the results message
};

// tasks[w] = indices of the tasks worker w runs, in the order it runs them.
using Allocation = std::vector<std::vector<int>>;

// Longest-processing-time-first list scheduling onto the worker that would finish a task earliest,
// then a local search (moves and swaps off the most loaded worker) while the estimated makespan
// improves.
Allocation schedule_static(const std::vector<double>& task_ns,
                           const std::vector<WorkerCosts>& workers);

// The estimated completion time of each worker under an allocation.
std::vector<double> estimated_finish_ns(const Allocation& allocation,
                                        const std::vector<double>& task_ns,
                                        const std::vector<WorkerCosts>& workers);

// An explicit allocation, "P1: D11 D12 h2; P2: C1_23 C1_24": every task exactly once, on workers
// only. Throws std::invalid_argument naming the setting the text came from, the bad token and what
// is valid.
Allocation parse_allocation(const std::string& text, const std::vector<std::string>& task_names,
                            const std::vector<std::string>& worker_names,
                            const std::string& setting = "allocation");

}  // namespace t800sim
