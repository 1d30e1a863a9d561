// A scene = topology + workload + options, read once from a TOML file (plus --set overrides) into
// plain structs. All validation happens here (docs/architecture.md, "From a scene file to a
// report").
#pragma once

#include <string>
#include <vector>

#include "network/faults.hpp"
#include "network/fidelity.hpp"
#include "network/topology.hpp"
#include "t800/processor_config.hpp"
#include "workloads/params.hpp"
#include "workloads/placement.hpp"

namespace tools {

struct Scene {
  std::string file;
  std::string name;
  std::string description;
  network::Topology topology;
  t800::LinkConfig link;  // network.link_speed_mbps, network.link_protocol: defaults for every link
  std::string workload_kind;
  workloads::Params workload;  // validated against the workload's declared parameters
  std::vector<std::string> workload_defaults;  // the parameters the scene left at their defaults
  workloads::Placement placement;              // [placement]: where the program's processes run
  // [calibration]: the occam code-efficiency factor (t800::CostModel) and how it was fitted. 1 =
  // uncalibrated.
  double code_efficiency = 1.0;
  std::string calibration_note;
  // [fidelity]: links, compute, compute_cost, skip_numerics, reuse_steps (network/fidelity.hpp).
  network::Fidelity fidelity;
  // [compiler] run_time_checks: occam's run-time checks compiled in (the compiler's default).
  bool run_time_checks = true;
  // Where settings were written, for errors found after reading (workloads::SettingError): each
  // workload parameter given ("workload.NAME"), the [workload] table ("workload") and what gave
  // the network ("network"); a file position, or the --set flag that gave it.
  std::map<std::string, network::SourcePos> origins;
  // [[fault]] tables (tools/scene_faults.hpp), then any --fault flags the command adds.
  std::vector<network::FaultSpec> faults;
};

// Where `keys` (most specific first) were written: the first one given, else the [workload] table
// for a workload key, else the scene file.
network::SourcePos origin_of(const Scene& scene, const std::vector<std::string>& keys);

// Loads a scene file. Each override is "key=value" with a dotted key ("workload.bytes=4000"); the
// value is read as a TOML value (4000, 2.5, "text", true, [1,2]) and, if that fails, as a bare
// string. Overrides are applied before validation, so a bad override is reported naming the flag.
// Throws network::ConfigError.
Scene load_scene(const std::string& path, const std::vector<std::string>& overrides = {});

// `t800sim check FILE`: validates a scene or a topology file (a scene has a [workload] table).
// Returns a one-line summary on success; throws network::ConfigError otherwise.
std::string check_file(const std::string& path);

}  // namespace tools
