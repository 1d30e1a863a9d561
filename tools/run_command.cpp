#include <unistd.h>

#include <cmath>
#include <iostream>

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <stdexcept>
#include <string>
#include <vector>

#include "network/config_error.hpp"
#include "network/stop_request.hpp"
#include "tools/cli_numbers.hpp"
#include "tools/commands.hpp"
#include "tools/report_format.hpp"
#include "tools/run_inputs.hpp"
#include "tools/run_progress.hpp"
#include "tools/scene.hpp"
#include "tools/scene_faults.hpp"
#include "tools/table_files.hpp"
#include "tools/trace_files.hpp"
#include "workloads/params.hpp"
#include "workloads/registry.hpp"
#include "workloads/run/run.hpp"

namespace tools {

namespace {

std::string default_text(const workloads::ParamValue& v) {
  struct Visitor {
    std::string operator()(bool b) const { return b ? "true" : "false"; }
    std::string operator()(std::int64_t i) const { return std::to_string(i); }
    std::string operator()(double d) const { return fmt::format("{}", d); }
    std::string operator()(const std::string& t) const { return "\"" + t + "\""; }
    std::string operator()(const std::vector<double>& l) const {
      return fmt::format("[{}]", fmt::join(l, ", "));
    }
  };
  return std::visit(Visitor{}, v);
}

// The workload kinds and their parameters, from the registry (workloads/registry.hpp), for `run
// --help`.
std::string workload_help() {
  std::string out =
      "\nWorkload kinds (workload.kind) and their parameters (workload.NAME = default); a scene's "
      "workload.plugin = \"FILE.so\" adds the kinds of a plugin (docs/tutorial.md):\n";
  for (const workloads::WorkloadInfo& w : workloads::workload_catalog()) {
    out += fmt::format("\n  {}: {}\n", w.kind, w.summary);
    for (const workloads::ParamSpec& p : w.params)
      out += fmt::format("    {} = {}  ({}) {}\n", p.name, default_text(p.default_value),
                         to_string(p.type), p.help);
  }
  return out;
}

struct RunArgs {
  std::string scene;
  std::vector<std::string> overrides;
  std::vector<std::string> faults;
  bool json = false;
  TraceFiles traces;
  double max_sim_s = 0, max_wall_s = 0;
};

std::string limit_text(const RunArgs& args, const workloads::RunReport& report) {
  switch (report.limit) {
    case network::Limit::sim_time:
      return fmt::format("--max-sim-time {} s", args.max_sim_s);
    case network::Limit::trace_size:
      return trace_limit_text(args.traces, report);
    case network::Limit::livelock:
      return "a livelock (simulated time stood still while processes handed work back and forth)";
    case network::Limit::interrupted:
      return fmt::format("signal {}", report.stop_signal);
    default:
      return fmt::format("--max-wall-time {} s", args.max_wall_s);
  }
}

int run_scene(const RunArgs& args) {
  Scene scene = load_scene(args.scene, args.overrides);
  for (const std::string& f : args.faults)
    scene.faults.push_back(parse_fault_flag(f, scene.topology));
  workloads::RunInputs inputs = inputs_from(scene);
  keep_trace(args.traces, inputs.options);
  check_trace_files(args.traces);
  inputs.options.max_sim_s = args.max_sim_s;
  inputs.options.max_wall_s = args.max_wall_s;
  inputs.options.tear_down = false;  // the command exits after this run: no teardown (Machine)
  network::catch_stop_signals();     // Ctrl-C and kill stop the run with its report written
  RunProgress progress(isatty(STDERR_FILENO));
  inputs.options.progress = [&progress](std::int64_t done, std::int64_t total) {
    progress.update(done, total);
  };
  workloads::RunReport report;
  at_scene_keys(scene, [&] { report = workloads::run(inputs); });
  progress.end();
  std::cout << (args.json ? format_json(report) : format_text(report)) << std::flush;
  write_traces(report, args.traces);  // also after a deadlock: the trace shows who waited for whom
  write_tables(report, inputs.params);
  if (!report.blocked.empty()) return kExitFailure;
  if (report.limit != network::Limit::none) {
    std::cerr << fmt::format(
        "error: stopped by {} at simulated time {:.3f} us, before the run ended: "
        "no workload results\n",
        limit_text(args, report), report.simulated_us);
    if (report.limit == network::Limit::interrupted) return 128 + report.stop_signal;
    return report.limit == network::Limit::livelock ? kExitFailure : kExitLimit;
  }
  if (!report.failure.empty()) {
    std::cerr << "error: the run failed: " << report.failure << "\n";
    return kExitBadResult;
  }
  return kExitOk;
}

}  // namespace

void add_run_command(CLI::App& app) {
  auto args = std::make_shared<RunArgs>();
  auto* cmd = app.add_subcommand("run", "Simulate one scene and print a report");
  cmd->footer(workload_help());
  cmd->add_option("scene", args->scene, "scene TOML file (configs/scenes/*.toml)")->required();
  cmd->add_option(
         "--set", args->overrides,
         "override a scene key, e.g. --set workload.bytes=4000 --set network.link_speed_mbps=10")
      ->type_name("KEY=VALUE");
  cmd->add_option(
         "--fault", args->faults,
         "inject a fault (repeatable), as a [[fault]] table: kind=corrupt|drop,link=A->B | "
         "kind=dead-link,link=A-B | kind=halt,processor=P; at_us=T; xor=1..255 (corrupt)")
      ->type_name("KEY=VALUE,...");
  cmd->add_flag("--json", args->json, "print one JSON object instead of the text report");
  add_trace_options(*cmd, args->traces);
  cmd->add_option(
         "--max-sim-time", args->max_sim_s,
         "stop the run after this many seconds of simulated time (exit code 4; 0: no limit)")
      ->check(seconds_limit());
  cmd->add_option("--max-wall-time", args->max_wall_s,
                  "stop the run after this many seconds of host time (exit code 4; 0: no limit)")
      ->check(seconds_limit());
  cmd->callback([args] { run_command([&] { return run_scene(*args); }); });
}

}  // namespace tools
