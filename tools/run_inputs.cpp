#include "tools/run_inputs.hpp"

namespace tools {

workloads::RunInputs inputs_from(const Scene& scene, bool keep_intervals) {
  workloads::RunInputs in;
  in.name = scene.name;
  in.topology = scene.topology;
  in.options.link = scene.link;
  in.options.code_efficiency = scene.code_efficiency;
  in.options.keep_intervals = keep_intervals;
  // Workloads that compute declare their arithmetic precision; the scene loader has validated the choice.
  if (scene.workload.has("precision"))
    in.options.precision = *t800::parse_precision(scene.workload.text("precision"));
  in.kind = scene.workload_kind;
  in.params = scene.workload;
  return in;
}

}  // namespace tools
