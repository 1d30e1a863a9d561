// A workload setting the network or the other settings rule out ("workload.m = 4 but the topology
// has 3 level-2 processors"). It names the scene keys it is about, most specific first, so that the
// caller, who knows where each key was written (a file line or a --set flag), can say where to fix
// it. workloads/ knows nothing of files.
#pragma once

#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace workloads {

// The key "network" stands for whatever gave the scene its topology (network.topology,
// network.family or an inline [topology]).
inline const std::string kNetworkKey = "network";

class SettingError : public std::invalid_argument {
 public:
  SettingError(std::vector<std::string> keys, const std::string& message)
      : std::invalid_argument(message), keys_(std::move(keys)) {}
  const std::vector<std::string>& keys() const { return keys_; }

 private:
  std::vector<std::string> keys_;
};

}  // namespace workloads
