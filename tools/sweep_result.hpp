// The result of one sweep point, how it is judged from the child that ran it, and the two files
// results live in: the JSON file of one job (--emit-jobs) and the CSV table of a whole sweep (sweep
// -o, merge -o).
#pragma once

#include <cmath>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "tools/sweep_runner.hpp"
#include "tools/sweep_spec.hpp"

namespace tools {

struct PointResult {
  SweepPoint params;
  std::string status = "ok";  // "ok", or "error: " and why
  double tp_us =
      std::nan("");  // the workload's Tp when it reports one (workload.tp_us), else simulated_us
  double util_min = std::nan(""), util_mean = std::nan(""),
         util_max = std::nan("");  // over processors
  double wall_s = std::nan("");
  // What the point ran on, from its report (empty when there is none): the workload kind, its
  // precision, the family its network is wired as (network::family_of; "" for none), the processor
  // types ("T800-20", or "T800-20+T800-25") and how many processors.
  std::string workload, precision, network, processor;
  double processors = std::nan("");
  bool ok() const { return status == "ok"; }
};

// Judges a point from how its `t800sim run --json` child ended; `report` receives the parsed report
// (null when there is none).
PointResult judge_point(const SweepPoint& params, const ChildOutcome& outcome,
                        nlohmann::json& report);

// One job's result file: the point, its result and the full report.
nlohmann::json point_to_json(const PointResult& point, const nlohmann::json& report);
// Throws std::invalid_argument when the JSON is not a point result.
PointResult point_from_json(const nlohmann::json& json);

// A sweep's table: the varied keys (the first columns) and one row per point.
struct ResultsTable {
  std::vector<std::string> keys;
  std::vector<PointResult> rows;
};

// The whole CSV text. Speed-up and efficiency are derived here, from the ok rows, when a key is
// network.workers: relative to the row with the fewest workers among those with the same other
// values.
std::string results_csv(const ResultsTable& table);
// One row with its derived columns left empty, for appending while a sweep runs.
std::string results_row(const PointResult& row);
std::string results_header(const std::vector<std::string>& keys);
// Reads a table written by results_csv. Throws std::invalid_argument ("FILE:LINE: why").
ResultsTable read_results_csv(const std::string& path);

// A text identifying a point whatever the order of its keys, for matching rows between sweeps.
std::string point_id(const SweepPoint& point);

}  // namespace tools
