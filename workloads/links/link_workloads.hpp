// Workloads that exercise links: ping-pong latency and streaming bandwidth between two neighbours.
#pragma once

#include <memory>

#include "workloads/run/workload.hpp"

namespace workloads {

std::unique_ptr<Workload> make_pingpong(const Params& params, const network::Topology& topology);
std::unique_ptr<Workload> make_link_stream(const Params& params, const network::Topology& topology);

}  // namespace workloads
