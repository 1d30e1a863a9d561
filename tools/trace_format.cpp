#include "tools/trace_format.hpp"

#include <cmath>
#include <fstream>
#include <iterator>
#include <map>
#include <stdexcept>

#include <fmt/format.h>

#include "network/input_file.hpp"
#include "tools/sweep_csv.hpp"
#include "workloads/run/result_value.hpp"

namespace tools {

namespace {

using workloads::TraceTrack;

const std::vector<std::string> kHeader = {"kind", "name", "state", "start_us", "end_us", "label"};

// Times closer than half the simulator's resolution (1 ps) are the same time: a reused trajectory
// step's intervals are shifted by double arithmetic, which can leave such a sliver.
constexpr double kSameTimeUs = 0.5e-6;

void processor_rows(const TraceTrack& track, double end_us, std::vector<TraceRow>& rows) {
  double at = 0;
  const std::size_t first = rows.size();
  for (const t800::Interval& i : track.intervals) {
    if (i.start_us > at + kSameTimeUs)
      rows.push_back({"processor", track.name, "idle", at, i.start_us, ""});
    const std::string state = t800::to_string(t800::ProcessorState(i.state));
    // The recorder splits a communication where the CPU hands over to a link engine; unlabelled
    // pieces of one state that touch are one interval to a reader. Labelled blocks stay apart
    // (three set-ups in a row).
    TraceRow* last = rows.size() > first ? &rows.back() : nullptr;
    if (last && i.label.empty() && last->label.empty() && last->state == state &&
        std::abs(last->end_us - i.start_us) < kSameTimeUs)
      last->end_us = i.end_us;
    else
      rows.push_back({"processor", track.name, state, i.start_us, i.end_us, i.label});
    at = i.end_us;
  }
  if (end_us > at + kSameTimeUs || track.intervals.empty())
    rows.push_back({"processor", track.name, "idle", at, end_us, ""});
}

std::string quoted(const std::string& s) {
  return workloads::json_string(s);
}

}  // namespace

std::vector<TraceRow> trace_rows(const workloads::RunReport& report) {
  std::vector<TraceRow> rows;
  for (const TraceTrack& track : report.tracks) {
    if (track.kind == TraceTrack::Kind::processor) {
      processor_rows(track, report.simulated_us, rows);
      continue;
    }
    for (const t800::Interval& i : track.intervals)
      rows.push_back({"link", track.name, "busy", i.start_us, i.end_us, i.label});
  }
  return rows;
}

std::string trace_csv(const std::vector<TraceRow>& rows) {
  std::string text = csv_line(kHeader);
  text.reserve(text.size() + rows.size() * 64);
  // Microseconds to 6 decimals: the simulator's picosecond resolution, exactly.
  for (const TraceRow& r : rows) {
    for (const std::string* f : {&r.kind, &r.name, &r.state}) {
      append_csv_field(text, *f);
      text += ',';
    }
    // Times are whole picoseconds: printing them as integers is exact and much faster than a float
    // format.
    const long long start_ps = std::llround(r.start_us * 1e6),
                    end_ps = std::llround(r.end_us * 1e6);
    fmt::format_to(std::back_inserter(text), "{}.{:06d},{}.{:06d},", start_ps / 1000000,
                   start_ps % 1000000, end_ps / 1000000, end_ps % 1000000);
    append_csv_field(text, r.label);
    text += '\n';
  }
  return text;
}

std::string trace_chrome_json(const std::vector<TraceRow>& rows) {
  // pid 1 holds the processors, pid 2 the link directions; each track is a thread, in report order.
  std::map<std::string, int> tid;
  std::string events;
  auto add = [&events](const std::string& e) { events += (events.empty() ? "\n" : ",\n") + e; };
  add(R"({"ph":"M","pid":1,"name":"process_name","args":{"name":"processors"}})");
  add(R"({"ph":"M","pid":2,"name":"process_name","args":{"name":"link directions"}})");
  for (const TraceRow& r : rows) {
    const int pid = r.kind == "processor" ? 1 : 2;
    const std::string key = r.kind + "/" + r.name;
    if (!tid.count(key)) {
      const int id = int(tid.size()) + 1;
      tid[key] = id;
      add(fmt::format(R"({{"ph":"M","pid":{},"tid":{},"name":"thread_name","args":{{"name":{}}}}})",
                      pid, id, quoted(r.name)));
      add(fmt::format(
          R"({{"ph":"M","pid":{},"tid":{},"name":"thread_sort_index","args":{{"sort_index":{}}}}})",
          pid, id, id));
    }
    if (r.state == "idle") continue;
    add(fmt::format(
        R"({{"ph":"X","pid":{},"tid":{},"name":{},"cat":"{}","ts":{:.6f},"dur":{:.6f}}})", pid,
        tid[key], quoted(r.label.empty() ? r.state : r.label), r.state, r.start_us,
        r.end_us - r.start_us));
  }
  return "{\"displayTimeUnit\":\"ns\",\"traceEvents\":[" + events + "\n]}\n";
}

std::vector<TraceRow> read_trace_csv(const std::string& path) {
  network::require_regular_input(path, path, "a CSV trace written by run --trace-csv");
  std::ifstream in(path);
  if (!in) throw std::invalid_argument(path + ": cannot read it");
  std::string line;
  if (!std::getline(in, line) || parse_csv_line(line) != kHeader)
    throw std::invalid_argument(
        path + ":1: not a trace (expected the header kind,name,state,start_us,end_us,label)");
  std::vector<TraceRow> rows;
  for (int number = 2; std::getline(in, line); ++number) {
    if (line.empty()) continue;
    const auto f = parse_csv_line(line);
    try {
      if (f.size() != kHeader.size())
        throw std::invalid_argument(fmt::format("{} fields, expected 6", f.size()));
      if (f[0] != "processor" && f[0] != "link")
        throw std::invalid_argument("kind must be processor or link");
      const TraceRow r{f[0], f[1], f[2], csv_to_number(f[3]), csv_to_number(f[4]), f[5]};
      if (!(r.start_us >= 0 && r.end_us >= r.start_us))
        throw std::invalid_argument("needs 0 <= start_us <= end_us");
      rows.push_back(r);
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument(fmt::format("{}:{}: {}", path, number, e.what()));
    }
  }
  return rows;
}

}  // namespace tools
