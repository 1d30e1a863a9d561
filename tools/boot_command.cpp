// `t800sim boot FILE`: what `iserver -se -sb FILE` does with a board, on a simulated one. The file
// is booted through the host link (workloads/boot); the program's output is on stdout, its keyboard
// stdin, and its exit status the command's. A short account goes to stderr, the whole report (as
// `run --json` gives it) to --json REPORT.
#include <unistd.h>

#include <csignal>

#include <chrono>
#include <filesystem>
#include <iostream>
#include <optional>

#include <fmt/format.h>

#include "network/icollect_map.hpp"
#include "network/input_file.hpp"
#include "network/stop_request.hpp"
#include "network/topology_file.hpp"
#include "tools/commands.hpp"
#include "tools/report_format.hpp"
#include "tools/run_inputs.hpp"
#include "tools/scene.hpp"
#include "tools/trace_files.hpp"
#include "workloads/registry.hpp"
#include "workloads/run/output_file.hpp"
#include "workloads/run/run.hpp"

namespace tools {

namespace {

struct BootArgs {
  std::string file;
  std::string processor;  // empty: T800-20, or a map's family
  std::int64_t memory = std::int64_t(2) << 20;
  std::string network;
  std::string host_dir;
  bool allow_system = false;
  bool strict = false;
  std::string json;
  std::string profile;
  TraceFiles traces;
  double max_simulated_s = 0, max_host_s = 0;
  std::int64_t max_instructions = 0;
  bool no_run_ahead = false;
  std::string clock = "simulated";
  std::int64_t clock_start = -1;
  std::vector<std::string> program_args;
};

// One processor of the given type, its link 0 wired to the host: a board with one transputer.
network::Topology single_board(const std::string& type_name) {
  const auto type = t800::parse_processor_type(type_name);
  if (!type)
    throw std::invalid_argument("--processor " + type_name +
                                ": not a processor type; give one of " +
                                t800::processor_type_names());
  network::Topology t;
  t.name = "board";
  t.source = "t800sim boot --processor " + type_name;
  network::ProcessorSpec p;
  p.name = "P0";
  p.config.type = *type;
  t.processors.push_back(p);
  t.host = network::LinkEnd{0, 0};
  network::validate(t);
  return t;
}

std::optional<t800::ProcessorType> processor_flag(const std::string& name) {
  if (name.empty()) return std::nullopt;
  const auto type = t800::parse_processor_type(name);
  if (!type)
    throw std::invalid_argument("--processor " + name + ": not a processor type; give one of " +
                                t800::processor_type_names());
  return type;
}

// The network: one board, a topology file, or the map file icollect wrote for a configured
// program. --processor sets the board's processor, or every processor of a map (which names only
// the family); a topology file names its own, so the flag beside one is an error.
network::Topology boot_network(const BootArgs& args) {
  const std::optional<t800::ProcessorType> each = processor_flag(args.processor);
  if (args.network.empty()) return single_board(each ? args.processor : "T800-20");
  const bool toml = std::filesystem::path(args.network).extension() == ".toml";
  if (!toml) {
    std::string text;
    try {
      text = network::read_input_file(args.network, std::size_t(64) << 20);
    } catch (const network::InputFileError& e) {
      if (!e.missing) throw std::invalid_argument("--network " + args.network + ": " + e.what());
    }
    if (network::is_icollect_map(text))
      return network::parse_icollect_map(text, args.network, each);
  }
  if (each)
    throw std::invalid_argument("--processor " + args.processor + " beside --network " +
                                args.network +
                                ": a topology file names its processors' types; give one or the "
                                "other (--processor applies to the processors of an icollect map)");
  if (toml) return network::load_topology(args.network);
  try {
    return network::load_topology(args.network);
  } catch (const network::ConfigError& e) {
    // Neither a map nor TOML: most likely a configuration's source, which is not read.
    throw network::ConfigError(
        e.where(), e.message() +
                       " (--network takes a topology file or the .map file icollect wrote beside "
                       "the boot file; a configuration's .cfs or .pgm source is not read)");
  }
}

Scene boot_scene(const BootArgs& args) {
  Scene scene;
  scene.file = args.file;
  scene.name = "boot " + args.file;
  scene.topology = boot_network(args);
  scene.workload_kind = "boot";
  const workloads::WorkloadInfo* info = workloads::find_workload("boot");
  for (const workloads::ParamSpec& p : info->params) scene.workload.set(p.name, p.default_value);
  std::string joined;
  for (const std::string& a : args.program_args) {
    if (a.find_first_of(" \t") != std::string::npos)
      throw std::invalid_argument("program argument \"" + a +
                                  "\": arguments with blanks are not supported yet");
    joined += (joined.empty() ? "" : " ") + a;
  }
  scene.workload.set("file", args.file);
  scene.workload.set("host_dir", args.host_dir);
  scene.workload.set("allow_system", args.allow_system);
  scene.workload.set("args", joined);
  scene.workload.set("memory", args.memory);
  scene.workload.set("addressing", std::string(args.strict ? "strict" : "wrap"));
  scene.workload.set("max_instructions", args.max_instructions);
  scene.workload.set("run_ahead", !args.no_run_ahead);
  scene.workload.set("profile", args.profile);
  scene.workload.set("clock", args.clock);
  scene.workload.set("clock_start", args.clock_start);
  // The flags' values against the kind's declared ranges, as a scene's are (tools/scene.cpp).
  for (const auto& [name, flag] :
       {std::pair{"memory", "--memory"}, std::pair{"max_instructions", "--max-instructions"},
        std::pair{"clock_start", "--clock-start"}}) {
    const workloads::ParamSpec* spec = info->find(name);
    const double value = double(scene.workload.integer(name));
    if ((spec->min && value < *spec->min) || (spec->max && value > *spec->max))
      throw std::invalid_argument(fmt::format("{} {}: give {} to {}", flag,
                                              scene.workload.integer(name), *spec->min,
                                              std::int64_t(*spec->max)));
  }
  scene.origins["workload.file"] = {"FILE " + args.file, 0, 0};
  scene.origins["workload.host_dir"] = {"--host-dir", 0, 0};
  scene.origins["workload.memory"] = {"--memory", 0, 0};
  scene.origins["workload.max_instructions"] = {"--max-instructions", 0, 0};
  scene.origins["workload.clock_start"] = {"--clock-start", 0, 0};
  scene.origins["workload.profile"] = {"--profile", 0, 0};
  scene.origins["network"] = {args.network.empty() ? "--processor" : args.network, 0, 0};
  return scene;
}

const workloads::ResultValue* field(const workloads::ResultValue& v, const char* key) {
  return v.get(key);
}

// The account on stderr: how the program ended, its time and instructions, the host's speed.
void print_account(const workloads::RunReport& r) {
  const workloads::ResultValue& w = r.workload;
  const double instructions = field(w, "instructions") ? field(w, "instructions")->number() : 0;
  std::cerr << fmt::format(
      "t800sim boot: {}; simulated {:.6f} s, {:.0f} instructions; host {:.3f} s ({:.1f} M "
      "instructions per host second)\n",
      field(w, "ended") ? field(w, "ended")->to_text() : std::string("not run"),
      r.simulated_us * 1e-6, instructions, r.wall_s,
      r.wall_s > 0 ? instructions / r.wall_s * 1e-6 : 0.0);
  for (const workloads::ProcessorReport& p : r.processors)
    std::cerr << fmt::format("  {} {}: busy {:.1f} us, idle {:.1f} us ({:.1f} %)\n", p.name, p.type,
                             p.busy_us, p.idle_us, 100 * p.utilisation);
}

// A run stopped before its end: by what, when, and each processor's state (the report and --json
// are written already). A livelock is the program's failure (exit 1, as a deadlock); a stop
// request exits as the signal would have (128 + its number); a limit exits kExitLimit.
int report_stop(const BootArgs& args, const workloads::RunReport& report) {
  std::string by;
  int exit_code = kExitLimit;
  switch (report.limit) {
    case network::Limit::trace_size:
      by = trace_limit_text(args.traces, report);
      break;
    case network::Limit::sim_time:
      by = fmt::format("--max-simulated-s {}", args.max_simulated_s);
      break;
    case network::Limit::wall_time:
      by = fmt::format("--max-host-s {}", args.max_host_s);
      break;
    case network::Limit::livelock:
      by = "a livelock: simulated time stood still while the processors handed work back and forth";
      exit_code = kExitFailure;
      break;
    case network::Limit::interrupted:
      by = fmt::format("signal {} ({})", report.stop_signal,
                       report.stop_signal == SIGINT ? "SIGINT" : "SIGTERM");
      exit_code = 128 + report.stop_signal;
      break;
    case network::Limit::none:
      break;
  }
  std::cerr << fmt::format("error: stopped by {} at simulated time {:.6f} s\n", by,
                           report.simulated_us * 1e-6);
  if (const auto* ps = field(report.workload, "processors"))
    for (const auto& p : ps->items())
      std::cerr << fmt::format("  {}: {}\n", p.get("name")->to_text(), p.get("state")->to_text());
  return exit_code;
}

int boot_file(const BootArgs& args) {
  if (!(args.max_simulated_s >= 0))
    throw std::invalid_argument("--max-simulated-s: give a number of seconds, 0 for no limit");
  if (!(args.max_host_s >= 0))
    throw std::invalid_argument("--max-host-s: give a number of seconds, 0 for no limit");
  if (!args.json.empty()) workloads::check_output_path(args.json, "--json");
  if (!args.profile.empty()) workloads::check_output_path(args.profile, "--profile");
  check_trace_files(args.traces);
  const Scene scene = boot_scene(args);
  workloads::RunInputs inputs = inputs_from(scene);
  keep_trace(args.traces, inputs.options);
  inputs.options.max_sim_s = args.max_simulated_s;
  inputs.options.max_wall_s = args.max_host_s;
  network::catch_stop_signals();     // Ctrl-C and kill stop the run with its report written
  inputs.options.tear_down = false;  // the command exits after this run (network::Machine)
  const workloads::RunReport report = workloads::run(inputs);
  std::cout << std::flush;
  print_account(report);
  if (!args.json.empty()) workloads::write_output_file(args.json, format_json(report), "--json");
  write_traces(report, args.traces);
  if (!report.blocked.empty()) {
    std::cerr << "error: deadlock: nothing can run, no timer is set and no link is moving:\n";
    for (const auto& b : report.blocked)
      std::cerr << fmt::format("  {} on {}: {}\n", b.process, b.processor, b.status);
    return kExitFailure;
  }
  if (report.limit != network::Limit::none) return report_stop(args, report);
  if (field(report.workload, "instruction_limit")) {
    std::cerr << fmt::format("error: stopped by --max-instructions {} at simulated time {:.6f} s\n",
                             args.max_instructions, report.simulated_us * 1e-6);
    return kExitLimit;
  }
  if (const auto* broken = field(report.workload, "host_protocol_error")) {
    std::cerr << "error: " << broken->to_text() << "\n";
    return kExitHostProtocol;
  }
  if (!report.failure.empty()) {
    std::cerr << "error: " << report.failure << "\n";
    if (const auto* ps = field(report.workload, "processors"))
      for (const auto& p : ps->items())
        if (const auto* h = p.get("halt")) std::cerr << h->to_text(2);
    return kExitBadResult;
  }
  if (const auto* code = field(report.workload, "exit_code")) return int(code->number());
  std::cerr << "note: the program ended without SP.EXIT (every process finished)\n";
  return kExitOk;
}

}  // namespace

void add_boot_command(CLI::App& app) {
  auto args = std::make_shared<BootArgs>();
  auto* cmd = app.add_subcommand(
      "boot",
      "Boot a bootable file through the host link and run it instruction by instruction, as "
      "`iserver -se -sb FILE` does (docs/iss.md)");
  cmd->add_option("file", args->file, "the bootable file")->required();
  cmd->add_option("program_args", args->program_args, "the program's command line, after --")
      ->type_name("ARGS");
  cmd->add_option("--processor", args->processor,
                  "the processor type of the one-transputer board, or of every processor of an "
                  "icollect map (default T800-20, or the map's family at 20 MHz)")
      ->type_name("TYPE");
  cmd->add_option("--memory", args->memory,
                  "bytes of memory per processor from MostNeg, on-chip RAM included")
      ->type_name("BYTES");
  cmd->add_option("--network", args->network,
                  "a topology file (its host link boots the network), or the .map file icollect "
                  "wrote for a configured program, instead of one board")
      ->type_name("TOPOLOGY");
  cmd->add_option("--host-dir", args->host_dir,
                  "the directory the program's files live in (default: the current one)")
      ->type_name("DIR");
  cmd->add_flag("--allow-system", args->allow_system,
                "let the program run host commands (SP.SYSTEM; refused by default)");
  cmd->add_flag("--strict", args->strict,
                "an access outside the installed memory halts the processor (default: wrap)");
  cmd->add_option("--json", args->json, "write the whole report as JSON to this file")
      ->type_name("REPORT");
  cmd->add_option("--profile", args->profile,
                  "write a profile as JSON to this file: per processor, each operation's count "
                  "and cycles, the hottest code, time waiting per link and timer "
                  "(tools/plot profile draws it)")
      ->type_name("FILE");
  add_trace_options(*cmd, args->traces);
  cmd->add_option("--max-simulated-s", args->max_simulated_s,
                  "stop after this many seconds of simulated time (exit code 4; 0: no limit)")
      ->type_name("SECONDS");
  cmd->add_option("--max-host-s", args->max_host_s,
                  "stop after this many seconds of host (wall-clock) time (exit code 4; 0: no "
                  "limit)")
      ->type_name("SECONDS");
  cmd->add_option("--clock", args->clock,
                  "what the program's SP.TIME tells: simulated (the default: --clock-start plus "
                  "the simulated seconds) or host (the host's clock, as iserver gives it)")
      ->check(CLI::IsMember({"simulated", "host"}))
      ->type_name("simulated|host");
  cmd->add_option("--clock-start", args->clock_start,
                  "the simulated clock's start, seconds since 1970-01-01 UTC (default: the host's "
                  "clock when the run starts); a fixed start makes SP.TIME reproducible")
      ->type_name("SECONDS");
  cmd->add_option("--max-instructions", args->max_instructions,
                  "stop when a processor has executed this many instructions (0: no limit)")
      ->type_name("N");
  cmd->add_flag("--no-run-ahead", args->no_run_ahead,
                "never run a processor past the look-ahead: slower, the same run but for where "
                "link DMA stalls fall (docs/iss.md, \"Running ahead\")");
  cmd->callback([args] { run_command([&] { return boot_file(*args); }); });
}

}  // namespace tools
