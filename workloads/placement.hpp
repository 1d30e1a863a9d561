// A scene's [placement] table as plain data: which processors a program's processes run on
// (occam's PLACED PAR), each entry with where the scene says so. Programs written with the SDK are
// placed from it (sdk/placement.hpp).
#pragma once

#include <string>
#include <vector>

#include "network/config_error.hpp"

namespace workloads {

struct PlacementEntry {
  std::string process;                  // a process, a group ("worker") or a member ("worker[2]")
  std::vector<std::string> processors;  // one for all, or one per member of a group
  network::SourcePos where;
};

using Placement = std::vector<PlacementEntry>;

}  // namespace workloads
