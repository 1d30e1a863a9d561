// Livermore loop 7 on one processor: a single-processor benchmark against INMOS's published
// figures (loop7.hpp).
#pragma once

#include <memory>

#include "workloads/run/workload.hpp"

namespace workloads {

std::unique_ptr<Workload> make_livermore7(const WorkloadContext& context);

}  // namespace workloads
