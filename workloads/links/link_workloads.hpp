// Workloads that exercise links: ping-pong latency and streaming bandwidth between two neighbours.
#pragma once

#include <memory>

#include "workloads/run/workload.hpp"

namespace workloads {

std::unique_ptr<Workload> make_pingpong(const WorkloadContext& context);
std::unique_ptr<Workload> make_link_stream(const WorkloadContext& context);

}  // namespace workloads
