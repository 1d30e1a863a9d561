// The two processors a link program measures: `from` (default: the processor wired to the host) and
// `to` (default: its first neighbour). They must be neighbours: these programs measure one link.
#pragma once

#include <stdexcept>
#include <string>
#include <utility>

#include "t800sim/workload.hpp"

namespace programs {

inline std::pair<std::string, std::string> neighbour_pair(const t800sim::Params& params,
                                                          const t800sim::Network& network) {
  const std::string& from_name = params.text("from");
  const int from = from_name.empty() ? network.host_processor() : network.find(from_name);
  const auto neighbours = network.neighbours(from);
  if (neighbours.empty())
    throw t800sim::SettingError(
        {"workload.from", t800sim::kNetworkKey},
        "processor " + network.processor_name(from) +
            " has no neighbour: a link workload needs two linked processors");
  const std::string& to_name = params.text("to");
  const int to = to_name.empty() ? neighbours.front() : network.find(to_name);
  if (std::find(neighbours.begin(), neighbours.end(), to) == neighbours.end())
    throw t800sim::SettingError(
        {"workload.to", "workload.from", t800sim::kNetworkKey},
        "workload.from and workload.to must be neighbours: " + network.processor_name(from) +
            " and " + network.processor_name(to) + " are not linked");
  return {network.processor_name(from), network.processor_name(to)};
}

}  // namespace programs
