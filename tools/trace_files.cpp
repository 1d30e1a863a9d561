#include "tools/trace_files.hpp"

#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "tools/child_run.hpp"
#include "tools/trace_format.hpp"

namespace tools {

namespace {

namespace fs = std::filesystem;

void write_text(const std::string& path, const std::string& text, const char* flag) {
  std::ofstream out(path, std::ios::trunc);
  out << text;
  out.close();
  if (!out) throw std::invalid_argument(std::string(flag) + " " + path + ": cannot write it");
}

void check_writable(const std::string& path, const char* flag) {
  if (path.empty()) return;
  const bool existed = fs::exists(path);
  std::ofstream probe(path, std::ios::app);
  if (!probe) throw std::invalid_argument(std::string(flag) + " " + path + ": cannot write it");
  probe.close();
  if (!existed) fs::remove(path);
}

void write_vcd_through_child(const std::string& csv_text, const std::string& csv_given,
                             const std::string& vcd) {
  std::string csv = csv_given;
  if (csv.empty()) {
    csv = (fs::temp_directory_path() / ("t800sim-trace-" + std::to_string(getpid()) + ".csv"))
              .string();
    write_text(csv, csv_text, "--trace-vcd (temporary CSV)");
  }
  const ChildOutput child = run_self({"vcd", csv, "-o", vcd});
  if (csv_given.empty()) fs::remove(csv);
  if (child.exit_code != 0)
    throw std::invalid_argument("--trace-vcd " + vcd + ": " +
                                (child.err.empty() ? "the VCD writer failed" : child.err));
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
}

void check_trace_files(const TraceFiles& files) {
  check_writable(files.vcd, "--trace-vcd");
  check_writable(files.json, "--trace-json");
  check_writable(files.csv, "--trace-csv");
}

void write_traces(const workloads::RunReport& report, const TraceFiles& files) {
  if (!files.any()) return;
  const std::vector<TraceRow> rows = trace_rows(report);
  const std::string csv = trace_csv(rows);
  if (!files.csv.empty()) write_text(files.csv, csv, "--trace-csv");
  if (!files.json.empty()) write_text(files.json, trace_chrome_json(rows), "--trace-json");
  if (!files.vcd.empty()) write_vcd_through_child(csv, files.csv, files.vcd);
}

}  // namespace tools
