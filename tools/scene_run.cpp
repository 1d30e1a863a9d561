#include "t800sim/run.hpp"
#include "tools/commands.hpp"
#include "tools/report_format.hpp"
#include "tools/run_inputs.hpp"
#include "tools/scene.hpp"
#include "tools/table_files.hpp"
#include "workloads/run/run.hpp"

namespace t800sim {

namespace {

SceneRun run_checked(const std::string& scene_file, const std::vector<std::string>& overrides) {
  workloads::RunInputs inputs = tools::inputs_from(tools::load_scene(scene_file, overrides));
  inputs.options.tear_down = false;  // one simulation per process: no teardown (network::Machine)
  const workloads::RunReport report = workloads::run(inputs);
  tools::write_tables(report, inputs.params);
  SceneRun r;
  r.report_json = tools::format_json(report);
  if (!report.blocked.empty()) {
    r.exit_code = tools::kExitFailure;
    r.error = "error: the program deadlocked (the report's `blocked` says who waited for whom)";
  } else if (!report.failure.empty()) {
    r.exit_code = tools::kExitBadResult;
    r.error = "error: the run failed: " + report.failure;
  }
  return r;
}

}  // namespace

SceneRun run_scene(const std::string& scene_file, const std::vector<std::string>& overrides) {
  try {
    return run_checked(scene_file, overrides);
  } catch (const std::exception&) {  // the command line's exits for the same faults
    const tools::CommandError error = tools::command_error(std::current_exception());
    return {error.code, {}, error.message};
  }
}

}  // namespace t800sim
