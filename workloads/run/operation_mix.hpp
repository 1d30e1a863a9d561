// Counted floating-point work (dynamics::OpCounts, from the counting scalar) -> the T800 operation mix the cost
// model prices. Every workload that charges counted kernels goes through this one mapping.
#pragma once

#include "t800/operation_mix.hpp"
#include "workloads/dynamics/op_counts.hpp"

namespace workloads {

// One kernel run as one occam PROC call (a call/return pair).
t800::OperationMix to_operation_mix(const dynamics::OpCounts& counts);

}  // namespace workloads
