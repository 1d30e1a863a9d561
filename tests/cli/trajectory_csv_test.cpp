// workload.output_csv of a trajectory, written row by row as the steps go (so that a run of 10^7
// steps holds none of them in memory): the file has a row per step and the final state, the
// results are exactly what its rows give (the means over the steps, the largest step, the final
// state), and a run that does not end well leaves the previous file and no temporary behind. And
// --trace-limit, which bounds the other thing a long run grows: its trace.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <sstream>

#include "cli_fixtures.hpp"
#include "tests/test_paths.hpp"

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

using cli_test::fresh_dir;

using cli_test::report_of;

// The CSV as a header and rows of numbers.
struct Csv {
  std::vector<std::string> columns;
  std::vector<std::vector<double>> rows;

  double at(std::size_t row, const std::string& column) const {
    const auto c = std::find(columns.begin(), columns.end(), column);
    return rows.at(row).at(std::size_t(c - columns.begin()));
  }
};

Csv read_csv(const std::string& path) {
  std::ifstream in(path);
  Csv csv;
  std::string line, cell;
  std::getline(in, line);
  for (std::istringstream header(line); std::getline(header, cell, ',');)
    csv.columns.push_back(cell);
  while (std::getline(in, line)) {
    std::vector<double> row;
    for (std::istringstream cells(line); std::getline(cells, cell, ',');)
      row.push_back(std::stod(cell));
    csv.rows.push_back(row);
  }
  return csv;
}

TEST(TrajectoryCsv, HasARowPerStepAndTheResultsAreWhatItsRowsGive) {
  const std::string csv_path = fresh_dir() + "/q.csv";
  const int steps = 40;
  const auto o = cli_test::run(
      "run configs/scenes/trajectory.toml --json --set workload.steps=" + std::to_string(steps) +
      " --set 'workload.torque=\"pd\"' --set workload.output_csv=" + csv_path + " 2>&1");
  ASSERT_EQ(o.exit_code, 0) << o.out;
  const json w = report_of(o)["workload"];
  ASSERT_TRUE(w.is_object()) << o.out;
  const Csv csv = read_csv(csv_path);
  ASSERT_EQ(csv.rows.size(), std::size_t(steps + 1));  // and the final state
  ASSERT_EQ(csv.columns.size(), 1u + 18u + 5u);
  double total = 0, largest = 0, dynamics = 0, solve = 0;
  for (std::size_t r = 0; r < std::size_t(steps); ++r) {
    total += csv.at(r, "step_us");
    largest = std::max(largest, csv.at(r, "step_us"));
    dynamics += csv.at(r, "dynamics_us");
    solve += csv.at(r, "solve_us");
    EXPECT_GT(csv.at(r, "step_us"), 0.0) << "row " << r;
  }
  EXPECT_EQ(csv.at(std::size_t(steps), "step_us"), 0.0);  // the final state starts no step
  EXPECT_EQ(w["steps"].get<int>(), steps);
  EXPECT_EQ(w["mean_step_us"].get<double>(), total / steps);
  EXPECT_EQ(w["max_step_us"].get<double>(), largest);
  EXPECT_EQ(w["split_mean_us"]["dynamics_us"].get<double>(), dynamics / steps);
  EXPECT_EQ(w["split_mean_us"]["solve_us"].get<double>(), solve / steps);
  for (int i = 0; i < 6; ++i) {
    EXPECT_EQ(w["final_q"][std::size_t(i)].get<double>(),
              csv.at(std::size_t(steps), "q" + std::to_string(i + 1)));
    EXPECT_EQ(w["final_qd"][std::size_t(i)].get<double>(),
              csv.at(std::size_t(steps), "qd" + std::to_string(i + 1)));
  }
  EXPECT_DOUBLE_EQ(csv.at(1, "t") - csv.at(0, "t"), w["dt"].get<double>());
}

TEST(TrajectoryCsv, ARunStoppedBeforeItsEndLeavesThePreviousFileAndNoTemporary) {
  const std::string dir = fresh_dir();
  std::ofstream(dir + "/q.csv") << "old\n";
  const auto o = cli_test::run(
      "run configs/scenes/trajectory.toml --set workload.steps=1000 --max-sim-time 0.05 "
      "--set workload.output_csv=" +
      dir + "/q.csv 2>&1");
  EXPECT_EQ(o.exit_code, 4) << o.out;
  std::ifstream in(dir + "/q.csv");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_EQ(text, "old\n");
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
  EXPECT_EQ(names, std::vector<std::string>{"q.csv"});
}

}  // namespace

namespace {

// --trace-limit: the trajectory's trace is forecast from its first step and announced; a forecast
// past the limit stops the run there, with the forecast in the message; any run stops when its
// kept intervals pass the limit; a limit that is not a count is refused at the flag.
TEST(TraceLimit, AForecastPastTheLimitStopsTheRunAfterItsFirstStep) {
  const std::string dir = fresh_dir();
  const auto o = cli_test::run(
      "run configs/scenes/trajectory.toml --set workload.steps=1000 --trace-limit 100000 "
      "--trace-csv " +
      dir + "/t.csv 2>&1");
  EXPECT_EQ(o.exit_code, 4) << o.out;
  EXPECT_NE(o.out.find("trace: about "), std::string::npos) << o.out;
  EXPECT_NE(o.out.find("extrapolated from 1 of 1000 steps"), std::string::npos) << o.out;
  EXPECT_NE(o.out.find("error: stopped by --trace-limit 100000 intervals (the trace would hold"),
            std::string::npos)
      << o.out;
  std::ifstream csv(dir + "/t.csv");
  std::size_t rows = 0;
  for (std::string line; std::getline(csv, line);) ++rows;
  EXPECT_LT(rows, 100000u);  // stopped at its forecast, not at the limit
}

TEST(TraceLimit, AnyRunStopsWhenItsTracePassesTheLimitAndZeroMeansNone) {
  const std::string dir = fresh_dir();
  const auto o = cli_test::run("run configs/scenes/pingpong.toml --trace-limit 5 --trace-csv " +
                               dir + "/t.csv 2>&1");
  EXPECT_EQ(o.exit_code, 4) << o.out;
  EXPECT_NE(o.out.find("error: stopped by --trace-limit 5 intervals"), std::string::npos) << o.out;
  const auto unlimited = cli_test::run(
      "run configs/scenes/pingpong.toml --trace-limit 0 --trace-csv " + dir + "/t.csv 2>&1");
  EXPECT_EQ(unlimited.exit_code, 0) << unlimited.out;
}

TEST(TraceLimit, ALimitThatIsNotACountIsRefusedAtTheFlag) {
  for (const std::string bad : {"-1", "abc", "1e6", "9223372036854775808"}) {
    const auto o = cli_test::run(
        "run configs/scenes/pingpong.toml --trace-csv /dev/null --trace-limit " + bad + " 2>&1");
    EXPECT_EQ(o.exit_code, 2) << bad << ": " << o.out;
    EXPECT_NE(o.out.find("--trace-limit: '" + bad + "' is not a count"), std::string::npos)
        << o.out;
  }
}

}  // namespace
