// A validated scene -> the plain inputs of one simulation (workloads::RunInputs).
#pragma once

#include "tools/scene.hpp"
#include "workloads/run/run.hpp"

namespace tools {

// keep_intervals: record per-interval state (only when a trace is written).
workloads::RunInputs inputs_from(const Scene& scene, bool keep_intervals = false);

}  // namespace tools
