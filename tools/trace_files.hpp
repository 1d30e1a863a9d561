// The trace files a run can write (--trace-vcd, --trace-json, --trace-csv). Off by default: only
// when one is asked for does the run keep per-interval records
// (network::MachineOptions::keep_intervals).
#pragma once

#include <cstdint>
#include <string>

#include <CLI/CLI.hpp>

#include "network/limits.hpp"
#include "workloads/run/run.hpp"

namespace tools {

struct TraceFiles {
  std::string vcd, json, csv;
  std::int64_t limit = network::kMaxTraceIntervals;  // --trace-limit (0: none)
  bool any() const { return !vcd.empty() || !json.empty() || !csv.empty(); }
};

void add_trace_options(CLI::App& cmd, TraceFiles& files);

// With a trace asked for: the run keeps its intervals, within --trace-limit, and its forecast size
// is announced on stderr as soon as the workload's progress gives it.
void keep_trace(const TraceFiles& files, network::MachineOptions& options);

// Why a run was stopped by --trace-limit, for its error message.
std::string trace_limit_text(const TraceFiles& files, const workloads::RunReport& report);

// Throws std::invalid_argument naming the flag when a file cannot be written (checked before the
// run, so a typo in a path does not cost a simulation).
void check_trace_files(const TraceFiles& files);

// Writes the asked-for traces of a finished run, each whole or not at all (workloads::OutputFile);
// the VCD through a `t800sim vcd` child (trace_vcd.hpp says why). Throws std::runtime_error.
void write_traces(const workloads::RunReport& report, const TraceFiles& files);

}  // namespace tools
