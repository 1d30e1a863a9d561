#include "tools/trace_files.hpp"

#include <unistd.h>

#include <filesystem>
#include <memory>

#include <fmt/format.h>

#include <iostream>

#include "tools/child_run.hpp"
#include "tools/cli_numbers.hpp"
#include "tools/trace_format.hpp"
#include "workloads/run/output_file.hpp"

namespace tools {

namespace {

namespace fs = std::filesystem;

void write_vcd_through_child(const std::string& csv_text, const std::string& csv_given,
                             const std::string& vcd) {
  std::string csv = csv_given;
  std::unique_ptr<workloads::ScratchFile> scratch;  // removed on every exit, also by a signal
  if (csv.empty()) {
    scratch = std::make_unique<workloads::ScratchFile>(
        (fs::temp_directory_path() / ("t800sim-trace-" + std::to_string(getpid()) + ".csv"))
            .string());
    csv = scratch->path();
    workloads::write_output_file(csv, csv_text, "--trace-vcd (temporary CSV)");
  }
  const ChildOutput child = run_self({"vcd", csv, "-o", vcd});
  if (child.exit_code != 0) {
    // The child's errors name its own flag; here the file is --trace-vcd's.
    std::string err = child.err.empty() ? "the VCD writer failed" : child.err;
    for (auto at = err.find("-o " + vcd); at != std::string::npos; at = err.find("-o " + vcd, at))
      err.replace(at, 2, "--trace-vcd");
    throw std::invalid_argument("--trace-vcd " + vcd + ": " + err);
  }
}

}  // namespace

void add_trace_options(CLI::App& cmd, TraceFiles& files) {
  cmd.add_option("--trace-vcd", files.vcd,
                 "write a VCD trace (GTKWave): per processor a state signal (0 idle, 1 compute, 2 "
                 "communicate), "
                 "per busy link direction a busy signal");
  cmd.add_option(
      "--trace-json", files.json,
      "write a Chrome trace-event JSON trace (ui.perfetto.dev): a track per processor and link "
      "direction, slices named by subtask or message");
  cmd.add_option("--trace-csv", files.csv,
                 "write a CSV trace: kind,name,state,start_us,end_us,label, one row per interval");
  cmd.add_option("--trace-limit", files.limit,
                 "the intervals (rows) a trace may hold; a run whose trace would pass it is "
                 "stopped as soon as that is known. 0 = no limit")
      ->check(count_limit())
      ->capture_default_str();
}

void keep_trace(const TraceFiles& files, network::MachineOptions& options) {
  options.keep_intervals = files.any();
  if (!files.any()) return;
  options.max_trace_intervals = files.limit;
  options.trace_forecast = [limit = files.limit](const network::TraceForecast& f) {
    std::cerr << fmt::format(
                     "trace: about {} intervals expected (extrapolated from {} of {} steps)",
                     f.intervals, f.done, f.total)
              << (limit > 0 ? fmt::format("; --trace-limit {}", limit) : std::string{}) << "\n";
  };
}

std::string trace_limit_text(const TraceFiles& files, const workloads::RunReport& report) {
  const network::TraceForecast& f = report.trace_forecast;
  const std::string forecast =
      f.intervals > files.limit
          ? fmt::format("the trace would hold about {}, extrapolated from {} of {} steps; ",
                        f.intervals, f.done, f.total)
          : std::string{};
  return fmt::format("--trace-limit {} intervals ({}raise it, 0 for none, or trace fewer steps)",
                     files.limit, forecast);
}

void check_trace_files(const TraceFiles& files) {
  workloads::check_output_path(files.vcd, "--trace-vcd");
  workloads::check_output_path(files.json, "--trace-json");
  workloads::check_output_path(files.csv, "--trace-csv");
}

void write_traces(const workloads::RunReport& report, const TraceFiles& files) {
  if (!files.any()) return;
  const std::vector<TraceRow> rows = trace_rows(report);
  const std::string csv = trace_csv(rows);
  if (!files.csv.empty()) workloads::write_output_file(files.csv, csv, "--trace-csv");
  if (!files.json.empty())
    workloads::write_output_file(files.json, trace_chrome_json(rows), "--trace-json");
  if (!files.vcd.empty()) write_vcd_through_child(csv, files.csv, files.vcd);
}

}  // namespace tools
