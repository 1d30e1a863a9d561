// Judging a point from its child, the JSON result of one job, and the CSV table with speed-up and
// efficiency.
#include <gtest/gtest.h>

#include <cmath>
#include <csignal>

#include "sweep_fixtures.hpp"
#include "tools/sweep_csv.hpp"
#include "tools/sweep_result.hpp"

using namespace tools;

namespace {

const char* kReport =
    R"({"scene": "s", "simulated_us": 200.0, "processors": [{"name": "P0", "utilisation": 0.25},)"
    R"( {"name": "P1", "utilisation": 0.75}], "links": [], "workload": {}})";

PointResult row(const std::string& workers, const std::string& other, double tp) {
  PointResult r;
  r.params = {{"network.workers", workers}, {"workload.bytes", other}};
  r.tp_us = tp;
  return r;
}

// Column `name` of data line `n` (1-based) of a CSV text.
std::string cell(const std::string& csv, int n, const std::string& name) {
  const auto all = sweep_test::lines(csv);
  const auto header = parse_csv_line(all.at(0));
  const auto fields = parse_csv_line(all.at(std::size_t(n)));
  for (std::size_t i = 0; i < header.size(); ++i)
    if (header[i] == name) return fields.at(i);
  return "<no column " + name + ">";
}

}  // namespace

TEST(JudgePoint, CleanRunGivesTpAndUtilisationSpread) {
  ChildOutcome o;
  o.exit_code = 0;
  o.out = kReport;
  nlohmann::json report;
  const PointResult p = judge_point({{"k", "1"}}, o, report);
  EXPECT_TRUE(p.ok());
  EXPECT_DOUBLE_EQ(p.tp_us, 200.0);
  EXPECT_DOUBLE_EQ(p.util_min, 0.25);
  EXPECT_DOUBLE_EQ(p.util_mean, 0.5);
  EXPECT_DOUBLE_EQ(p.util_max, 0.75);
  EXPECT_EQ(report["scene"], "s");
}

TEST(JudgePoint, AWorkloadsOwnTpWinsOverTheRunsEnd) {
  ChildOutcome o;
  o.exit_code = 0;
  o.out = R"({"simulated_us": 200.0, "processors": [], "workload": {"tp_us": 150.5}})";
  nlohmann::json report;
  EXPECT_DOUBLE_EQ(judge_point({}, o, report).tp_us, 150.5);
}

TEST(JudgePoint, DeadlockIsAnErrorNamingABlockedProcess) {
  ChildOutcome o;
  o.exit_code = 1;
  o.out = R"j({"simulated_us": 5.0, "processors": [], "deadlock": [{"process": "worker1",)j"
          R"j( "processor": "P1",)j"
          R"j( "status": "waiting on in(c)"}]})j";
  nlohmann::json report;
  const PointResult p = judge_point({}, o, report);
  EXPECT_FALSE(p.ok());
  EXPECT_NE(p.status.find("deadlock"), std::string::npos) << p.status;
  EXPECT_NE(p.status.find("worker1 on P1"), std::string::npos) << p.status;
}

TEST(JudgePoint, BadInputKeepsTheChildsMessageOnOneLine) {
  ChildOutcome o;
  o.exit_code = 2;
  o.err = "--set network.workers=0: error: a tree needs at least 1 worker, got 0\nsecond line\n";
  nlohmann::json report;
  const PointResult p = judge_point({}, o, report);
  EXPECT_EQ(p.status,
            "error: --set network.workers=0: a tree needs at least 1 worker, got 0 | second line");
  EXPECT_TRUE(std::isnan(p.tp_us));
  EXPECT_TRUE(report.is_null());
}

TEST(JudgePoint, CrashAndTimeoutAreErrors) {
  ChildOutcome crash;
  crash.signal = SIGSEGV;
  crash.out = kReport;  // whatever it printed before dying does not count
  nlohmann::json report;
  const PointResult c = judge_point({}, crash, report);
  EXPECT_FALSE(c.ok());
  EXPECT_NE(c.status.find("crashed (signal 11"), std::string::npos) << c.status;
  ChildOutcome slow;
  slow.timed_out = true;
  EXPECT_NE(judge_point({}, slow, report).status.find("timed out"), std::string::npos);
}

TEST(PointJson, RoundTripsThroughTheJobFile) {
  PointResult p = row("3", "64", 123.456789);
  p.util_min = 0.1;
  p.status = "error: \"quoted\", with a comma";
  const PointResult back = point_from_json(nlohmann::json::parse(point_to_json(p, nullptr).dump()));
  EXPECT_EQ(back.params, p.params);
  EXPECT_EQ(back.status, p.status);
  EXPECT_DOUBLE_EQ(back.tp_us, p.tp_us);
  EXPECT_DOUBLE_EQ(back.util_min, 0.1);
  EXPECT_TRUE(std::isnan(back.util_max));
}

TEST(PointJson, OtherJsonIsRefused) {
  EXPECT_THROW(point_from_json(nlohmann::json::parse(R"({"simulated_us": 1})")),
               std::invalid_argument);
  EXPECT_THROW(point_from_json(nlohmann::json::parse(R"({"params": [[1, 2]], "status": "ok"})")),
               std::invalid_argument);
}

// Speed-up against the fewest workers with the same other parameters; efficiency = S * w0 / w.
TEST(ResultsCsv, SpeedupAndEfficiencyPerGroupOfOtherParameters) {
  ResultsTable t{{"network.workers", "workload.bytes"},
                 {row("2", "64", 100), row("4", "64", 50), row("8", "64", 40), row("2", "128", 300),
                  row("4", "128", 100)}};
  const std::string csv = results_csv(t);
  EXPECT_EQ(cell(csv, 1, "speedup"), "1.000000");
  EXPECT_EQ(cell(csv, 2, "speedup"), "2.000000");
  EXPECT_EQ(cell(csv, 2, "efficiency"), "1.000000");
  EXPECT_EQ(cell(csv, 3, "speedup"), "2.500000");
  EXPECT_EQ(cell(csv, 3, "efficiency"), "0.625000");
  EXPECT_EQ(cell(csv, 5, "speedup"), "3.000000");
  EXPECT_EQ(cell(csv, 5, "efficiency"), "1.500000");
}

TEST(ResultsCsv, FailedRowsHaveNoSpeedupAndAreNoBaseline) {
  PointResult failed = row("1", "64", 1000);
  failed.status = "error: bad";
  ResultsTable t{{"network.workers", "workload.bytes"},
                 {failed, row("2", "64", 100), row("4", "64", 50)}};
  const std::string csv = results_csv(t);
  EXPECT_EQ(cell(csv, 1, "speedup"), "");
  EXPECT_EQ(cell(csv, 2, "speedup"), "1.000000");
  EXPECT_EQ(cell(csv, 3, "speedup"), "2.000000");
}

TEST(ResultsCsv, WithoutWorkersSpeedupIsEmpty) {
  PointResult r;
  r.params = {{"workload.bytes", "64"}};
  r.tp_us = 5;
  const std::string csv = results_csv({{"workload.bytes"}, {r}});
  EXPECT_EQ(cell(csv, 1, "tp_us"), "5.000000");
  EXPECT_EQ(cell(csv, 1, "speedup"), "");
  EXPECT_EQ(cell(csv, 1, "efficiency"), "");
}

TEST(ResultsCsv, ReadsBackWhatItWrites) {
  const std::string dir = sweep_test::fresh_dir();
  PointResult bad = row("1", "64", std::nan(""));
  bad.status = "error: x, \"y\"";
  PointResult good = row("2", "64", 100.25);
  good.workload = "pingpong";
  good.network = "tree";
  good.processor = "T800-20+T800-25";
  good.processors = 3;
  ResultsTable t{{"network.workers", "workload.bytes"}, {bad, good}};
  sweep_test::write_file(dir + "/r.csv", results_csv(t));
  const ResultsTable back = read_results_csv(dir + "/r.csv");
  EXPECT_EQ(back.keys, t.keys);
  ASSERT_EQ(back.rows.size(), 2u);
  EXPECT_EQ(back.rows[0].status, bad.status);
  EXPECT_DOUBLE_EQ(back.rows[1].tp_us, 100.25);
  EXPECT_EQ(back.rows[1].workload, "pingpong");
  EXPECT_EQ(back.rows[1].network, "tree");
  EXPECT_EQ(back.rows[1].processor, "T800-20+T800-25");
  EXPECT_DOUBLE_EQ(back.rows[1].processors, 3);
}

// Tables written before the setting columns existed are still read (a sweep resumes into them).
TEST(ResultsCsv, ReadsTablesWithoutTheSettingColumns) {
  const std::string dir = sweep_test::fresh_dir();
  sweep_test::write_file(dir + "/old.csv",
                         "network.workers,tp_us,speedup,efficiency,util_min,util_mean,util_max,"
                         "wall_s,status\n3,8556.25,,,0.1,0.5,0.9,0.02,ok\n");
  const ResultsTable back = read_results_csv(dir + "/old.csv");
  EXPECT_EQ(back.keys, std::vector<std::string>{"network.workers"});
  ASSERT_EQ(back.rows.size(), 1u);
  EXPECT_DOUBLE_EQ(back.rows[0].tp_us, 8556.25);
  EXPECT_EQ(back.rows[0].network, "");
}

TEST(ResultsCsv, ForeignFilesAreRefusedWithTheirName) {
  const std::string dir = sweep_test::fresh_dir();
  sweep_test::write_file(dir + "/other.csv", "a,b,c\n1,2,3\n");
  try {
    read_results_csv(dir + "/other.csv");
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("other.csv:1"), std::string::npos) << e.what();
  }
}
