// Traces of one run, all views of the same recorded intervals (RunReport.tracks, kept only when a
// trace is asked for): a CSV table, Chrome trace-event JSON (ui.perfetto.dev, chrome://tracing),
// and VCD (GTKWave, trace_vcd.hpp). The CSV is also what `t800sim vcd` and `tools/plot gantt` read.
#pragma once

#include <string>
#include <vector>

#include "workloads/run/run.hpp"

namespace tools {

// One CSV row: kind "processor" or "link"; state idle, compute or communicate (processors) or busy
// (links).
struct TraceRow {
  std::string kind, name, state;
  double start_us = 0, end_us = 0;
  std::string label;
};

// Processors get a row per interval including idle ones, so every processor's line spans the whole
// run; link directions get their busy intervals only (unused directions have none).
std::vector<TraceRow> trace_rows(const workloads::RunReport& report);

std::string trace_csv(const std::vector<TraceRow>& rows);
// One track per processor and per busy link direction; slices named by their label (a compute
// block's subtask, a message) or else their state.
std::string trace_chrome_json(const std::vector<TraceRow>& rows);

// Reads a CSV trace; throws std::invalid_argument ("FILE:LINE: why").
std::vector<TraceRow> read_trace_csv(const std::string& path);

}  // namespace tools
