#include "tools/sweep_result.hpp"

#include <algorithm>
#include <cstring>
#include <fstream>
#include <map>
#include <stdexcept>

#include <fmt/format.h>

#include "network/input_file.hpp"
#include "tools/sweep_csv.hpp"

namespace tools {

namespace {

using nlohmann::json;

const char* const kWorkersKey = "network.workers";
// Each row: the varied keys, what the point ran on, then its measures. Tables written before the
// setting columns existed (the varied keys, then the measures) are still read.
const std::vector<std::string> kSettingColumns = {"workload", "precision", "network", "processor",
                                                  "processors"};
const std::vector<std::string> kMeasureColumns = {"tp_us",     "speedup",  "efficiency", "util_min",
                                                  "util_mean", "util_max", "wall_s",     "status"};

// A child's error output as one line: config errors span lines (a message, then the valid choices).
std::string one_line(const std::string& text) {
  std::string line;
  std::size_t start = 0;
  while (start < text.size()) {
    auto end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    std::string part = text.substr(start, end - start);
    // The status already says "error: ": "--set k=v: error: why" reads "--set k=v: why".
    if (part.rfind("error: ", 0) == 0) part = part.substr(7);
    if (const auto at = part.find(": error: "); at != std::string::npos) part.erase(at, 7);
    if (!part.empty()) line += (line.empty() ? "" : " | ") + part;
    start = end + 1;
  }
  if (line.size() > 400) line = line.substr(0, 400) + "...";
  return line.empty() ? "no message" : line;
}

// Fields of a child's report, read without trusting its shape (a damaged report must not crash us).
double number_at(const json& j, const char* key) {
  const auto it = j.find(key);
  return it != j.end() && it->is_number() ? it->get<double>() : std::nan("");
}

std::string text_at(const json& j, const char* key) {
  const auto it = j.find(key);
  return it != j.end() && it->is_string() ? it->get<std::string>() : std::string("?");
}

std::string deadlock_text(const json& deadlock) {
  std::string text = fmt::format("deadlock: {} process(es) blocked", deadlock.size());
  if (!deadlock.empty()) {
    const json& b = deadlock.front();
    text += ", e.g. " + text_at(b, "process") + " on " + text_at(b, "processor") + " (" +
            text_at(b, "status") + ")";
  }
  return text;
}

void fill_setting(PointResult& p, const json& report) {
  const auto setting = report.find("setting");
  if (setting == report.end() || !setting->is_object()) return;
  p.workload = text_at(*setting, "kind");
  if (const auto precision = setting->find("precision");
      precision != setting->end() && precision->is_object())
    p.precision = text_at(*precision, "value");
  const auto network = setting->find("network");
  if (network == setting->end() || !network->is_object()) return;
  const auto family = network->find("family");
  p.network = family != network->end() && family->is_string() ? family->get<std::string>() : "";
  if (const auto types = network->find("processor_types");
      types != network->end() && types->is_array())
    for (const json& t : *types)
      if (t.is_string()) p.processor += (p.processor.empty() ? "" : "+") + t.get<std::string>();
  if (const auto procs = report.find("processors"); procs != report.end() && procs->is_array())
    p.processors = double(procs->size());
}

void fill_measures(PointResult& p, const json& report) {
  fill_setting(p, report);
  // A workload that measures its own Tp (the dynamics farm's window) knows it better than the end.
  const auto workload = report.find("workload");
  const double workload_tp = workload != report.end() && workload->is_object()
                                 ? number_at(*workload, "tp_us")
                                 : std::nan("");
  p.tp_us = std::isnan(workload_tp) ? number_at(report, "simulated_us") : workload_tp;
  const auto procs = report.find("processors");
  if (procs == report.end() || !procs->is_array() || procs->empty()) return;
  double lo = 1e300, hi = -1e300, sum = 0;
  for (const json& proc : *procs) {
    const double u = number_at(proc, "utilisation");
    lo = std::min(lo, u);
    hi = std::max(hi, u);
    sum += u;
  }
  p.util_min = lo;
  p.util_max = hi;
  p.util_mean = sum / double(procs->size());
}

// The report a child printed; false when it printed none (or it cannot be read).
bool read_report(const std::string& out, json& report) {
  const auto brace = out.find('{');
  if (brace == std::string::npos) return false;
  report = json::parse(out.substr(brace), nullptr, /*allow_exceptions=*/false);
  return report.is_object() && report.contains("simulated_us");
}

std::string failure(const ChildOutcome& o) {
  if (o.timed_out) return "timed out";
  if (o.signal)
    return fmt::format("crashed (signal {}, {}){}", o.signal, strsignal(o.signal),
                       o.err.empty() ? "" : ": " + one_line(o.err));
  return o.err.empty() ? fmt::format("exit code {} without a message", o.exit_code)
                       : one_line(o.err);
}

// A row's number of workers; NaN without one, or for a value that is no number (its point failed).
double workers_of(const PointResult& r) {
  for (const auto& [key, value] : r.params) {
    if (key != kWorkersKey) continue;
    try {
      return csv_to_number(value);
    } catch (const std::invalid_argument&) {
      return std::nan("");
    }
  }
  return std::nan("");
}

// Speed-up and efficiency of every row (NaN where not defined).
std::vector<std::pair<double, double>> speedups(const ResultsTable& t) {
  std::vector<std::pair<double, double>> out(t.rows.size(), {std::nan(""), std::nan("")});
  const auto w = std::find(t.keys.begin(), t.keys.end(), kWorkersKey);
  if (w == t.keys.end()) return out;
  // The other parameters name a group; its baseline is the ok row with the fewest workers.
  auto group = [&](const PointResult& r) {
    SweepPoint others;
    for (const auto& kv : r.params)
      if (kv.first != kWorkersKey) others.push_back(kv);
    return point_id(others);
  };
  auto workers = workers_of;
  std::map<std::string, const PointResult*> base;
  for (const PointResult& r : t.rows) {
    if (!r.ok() || std::isnan(workers(r))) continue;
    const PointResult*& b = base[group(r)];
    if (!b || workers(r) < workers(*b)) b = &r;
  }
  for (std::size_t i = 0; i < t.rows.size(); ++i) {
    const PointResult& r = t.rows[i];
    auto b = base.find(group(r));
    if (!r.ok() || b == base.end() || !(r.tp_us > 0) || !(workers(r) > 0)) continue;
    const double s = b->second->tp_us / r.tp_us;
    out[i] = {s, s * workers(*b->second) / workers(r)};
  }
  return out;
}

std::vector<std::string> row_fields(const PointResult& r, double speedup, double efficiency) {
  std::vector<std::string> f;
  for (const auto& kv : r.params) f.push_back(kv.second);
  for (const std::string& s : {r.workload, r.precision, r.network, r.processor}) f.push_back(s);
  f.push_back(csv_number(r.processors, 0));
  for (std::string s : {csv_number(r.tp_us, 6), csv_number(speedup, 6), csv_number(efficiency, 6),
                        csv_number(r.util_min, 6), csv_number(r.util_mean, 6),
                        csv_number(r.util_max, 6), csv_number(r.wall_s, 3), r.status})
    f.push_back(s);
  return f;
}

PointResult row_from_fields(const std::vector<std::string>& keys, bool with_setting,
                            const std::vector<std::string>& f) {
  PointResult r;
  for (std::size_t i = 0; i < keys.size(); ++i) r.params.emplace_back(keys[i], f[i]);
  std::size_t c = keys.size();
  if (with_setting) {
    r.workload = f[c];
    r.precision = f[c + 1];
    r.network = f[c + 2];
    r.processor = f[c + 3];
    r.processors = csv_to_number(f[c + 4]);
    c += kSettingColumns.size();
  }
  r.tp_us = csv_to_number(f[c]);
  r.util_min = csv_to_number(f[c + 3]);
  r.util_mean = csv_to_number(f[c + 4]);
  r.util_max = csv_to_number(f[c + 5]);
  r.wall_s = csv_to_number(f[c + 6]);
  r.status = f[c + 7];
  return r;
}

}  // namespace

PointResult judge_point(const SweepPoint& params, const ChildOutcome& o, json& report) {
  PointResult p;
  p.params = params;
  p.wall_s = o.wall_s;
  report = nullptr;
  const bool has_report = !o.timed_out && !o.signal && read_report(o.out, report);
  if (!has_report) report = nullptr;
  if (has_report) fill_measures(p, report);
  if (has_report && o.exit_code == 0) return p;
  const bool deadlock = has_report && report.contains("deadlock") && report["deadlock"].is_array();
  p.status = "error: " + (deadlock ? deadlock_text(report["deadlock"]) : failure(o));
  return p;
}

json point_to_json(const PointResult& p, const json& report) {
  // NaN has no JSON form: unknown measures are null.
  auto number = [](double x) { return std::isnan(x) ? json(nullptr) : json(x); };
  // nlohmann::json sorts keys; "params" keeps the sweep's order as a list of pairs.
  json ordered = json::array();
  for (const auto& [key, value] : p.params) ordered.push_back({key, value});
  return {{"params", ordered},
          {"status", p.status},
          {"tp_us", number(p.tp_us)},
          {"util_min", number(p.util_min)},
          {"util_mean", number(p.util_mean)},
          {"util_max", number(p.util_max)},
          {"wall_s", number(p.wall_s)},
          {"report", report}};  // the setting columns are read back from the report
}

PointResult point_from_json(const json& j) {
  if (!j.is_object() || !j.contains("params") || !j["params"].is_array() || !j.contains("status") ||
      !j["status"].is_string())
    throw std::invalid_argument("not a sweep point result (no \"params\" list and \"status\")");
  PointResult p;
  for (const json& kv : j["params"]) {
    if (!kv.is_array() || kv.size() != 2 || !kv[0].is_string() || !kv[1].is_string())
      throw std::invalid_argument("\"params\" must hold [\"key\", \"value\"] pairs");
    p.params.emplace_back(kv[0].get<std::string>(), kv[1].get<std::string>());
  }
  p.status = j["status"].get<std::string>();
  p.tp_us = number_at(j, "tp_us");
  p.util_min = number_at(j, "util_min");
  p.util_mean = number_at(j, "util_mean");
  p.util_max = number_at(j, "util_max");
  p.wall_s = number_at(j, "wall_s");
  if (const auto report = j.find("report"); report != j.end() && report->is_object())
    fill_setting(p, *report);
  return p;
}

std::string results_header(const std::vector<std::string>& keys) {
  std::vector<std::string> names = keys;
  names.insert(names.end(), kSettingColumns.begin(), kSettingColumns.end());
  names.insert(names.end(), kMeasureColumns.begin(), kMeasureColumns.end());
  return csv_line(names);
}

std::string results_row(const PointResult& row) {
  return csv_line(row_fields(row, std::nan(""), std::nan("")));
}

std::string results_csv(const ResultsTable& table) {
  std::string text = results_header(table.keys);
  const auto derived = speedups(table);
  for (std::size_t i = 0; i < table.rows.size(); ++i)
    text += csv_line(row_fields(table.rows[i], derived[i].first, derived[i].second));
  return text;
}

ResultsTable read_results_csv(const std::string& path) {
  network::require_regular_input(path, path, "a results table written by sweep -o or merge -o");
  std::ifstream in(path);
  if (!in) throw std::invalid_argument(path + ": cannot read it");
  std::string line;
  if (!std::getline(in, line))
    throw std::invalid_argument(path + ":1: empty file, expected a header");
  const std::vector<std::string> header = parse_csv_line(line);
  const auto first = std::find(header.begin(), header.end(), "tp_us");
  if (first == header.end() || std::vector<std::string>(first, header.end()) != kMeasureColumns)
    throw std::invalid_argument(path +
                                ":1: not a sweep results table (expected the parameters, then " +
                                results_header({}).substr(0, results_header({}).size() - 1) + ")");
  const auto settings = std::size_t(first - header.begin()) >= kSettingColumns.size()
                            ? first - std::ptrdiff_t(kSettingColumns.size())
                            : header.begin();
  const bool with_setting = std::vector<std::string>(settings, first) == kSettingColumns;
  ResultsTable table;
  table.keys.assign(header.begin(), with_setting ? settings : first);
  for (int number = 2; std::getline(in, line); ++number) {
    if (line.empty()) continue;
    const std::vector<std::string> fields = parse_csv_line(line);
    if (fields.size() != header.size())
      throw std::invalid_argument(
          fmt::format("{}:{}: {} fields, expected {}", path, number, fields.size(), header.size()));
    try {
      table.rows.push_back(row_from_fields(table.keys, with_setting, fields));
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument(fmt::format("{}:{}: {}", path, number, e.what()));
    }
  }
  return table;
}

std::string point_id(const SweepPoint& point) {
  SweepPoint sorted = point;
  std::sort(sorted.begin(), sorted.end());
  std::string id;
  for (const auto& [key, value] : sorted) id += key + "=" + value + "\n";
  return id;
}

}  // namespace tools
