// Registering a program as a workload kind: its name (the scene's workload.kind), a summary, its
// parameters with types, ranges and help (validated from the scene before anything runs; `t800sim
// run --help-workload KIND` lists them), and how to make it. One registration per kind, next to
// the program's code:
//
//   T800SIM_WORKLOAD(commstime) {
//     return {"commstime", "prefix, delta, successor and consume in a ring",
//             {t800sim::integer_param("loops", 1000, "times round the ring", 1, 1e7)},
//             [](const t800sim::Params& p, const t800sim::Network&) {
//               return std::make_unique<Commstime>(p.integer("loops"));
//             }};
//   }
//
// A plugin (a shared library a scene names in `workload.plugin`) registers its kinds the same way
// and adds T800SIM_PLUGIN() once, which records the SDK version it was built against.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "t800sim/program.hpp"
#include "t800sim/version.hpp"
#include "workloads/params.hpp"
#include "workloads/setting_error.hpp"

namespace t800sim {

using Params = workloads::Params;
using Param = workloads::ParamSpec;
// A setting the network or the other settings rule out: throw it from a program's factory with
// the scene keys it is about (most specific first; kNetworkKey for the topology), and the error
// names the file and line, or the flag, that set them.
using workloads::kNetworkKey;
using workloads::SettingError;

struct WorkloadSpec {
  std::string kind;
  std::string summary;
  std::vector<Param> params;
  std::function<std::unique_ptr<Program>(const Params&, const Network&)> make;
};

// Adds a kind; throws std::invalid_argument for a kind already registered or a malformed spec.
void register_workload(WorkloadSpec spec);

// Parameter declarations (min and max inclusive).
Param integer_param(std::string name, std::int64_t fallback, std::string help, double min,
                    double max);
Param real_param(std::string name, double fallback, std::string help, double min, double max);
Param flag_param(std::string name, bool fallback, std::string help);
Param text_param(std::string name, std::string fallback, std::string help,
                 std::vector<std::string> choices = {});
Param real_list_param(std::string name, std::vector<double> fallback, std::string help);
// A processor of the network, by name; empty (the default) lets the program choose.
Param processor_param(std::string name, std::string help);
// The program's arithmetic, "real32" or "real64": the simulated processors compute at it and every
// report states it (and whether it was chosen or the default).
Param precision_param(std::string name, std::string fallback, std::string help);
// Files, relative to the scene that names them; the program gets the resolved path, or "" for none.
// An input file must exist when the scene is read; an output file must be writable before the
// simulation starts.
Param input_file_param(std::string name, std::string help);
Param output_file_param(std::string name, std::string help);

}  // namespace t800sim

#define T800SIM_DETAIL_CAT2(a, b) a##b
#define T800SIM_DETAIL_CAT(a, b) T800SIM_DETAIL_CAT2(a, b)

// Defines a function returning the WorkloadSpec and registers it when the program (or plugin) is
// loaded.
#define T800SIM_WORKLOAD(id)                                                             \
  static ::t800sim::WorkloadSpec T800SIM_DETAIL_CAT(t800sim_workload_, id)();            \
  static const bool T800SIM_DETAIL_CAT(t800sim_registered_, id) =                        \
      (::t800sim::register_workload(T800SIM_DETAIL_CAT(t800sim_workload_, id)()), true); \
  static ::t800sim::WorkloadSpec T800SIM_DETAIL_CAT(t800sim_workload_, id)()

// Once per plugin: the SDK version the plugin was compiled against, checked when it is loaded.
#define T800SIM_PLUGIN()                                                                       \
  extern "C" __attribute__((visibility("default"))) const char* t800sim_plugin_sdk_version() { \
    return T800SIM_VERSION;                                                                    \
  }
