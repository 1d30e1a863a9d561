// The three traces of one run (VCD, Chrome JSON, CSV) agree with each other and with the report's
// busy times.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include <nlohmann/json.hpp>

#include "../cli/cli_fixtures.hpp"
#include "tests/test_paths.hpp"
#include "tools/trace_format.hpp"
#include "tools/trace_vcd.hpp"

using tools::TraceRow;

namespace {

// A state over time: [start, end) -> value, in picoseconds (the simulator's and the VCD's
// resolution).
struct Span {
  std::int64_t start, end;
  unsigned value;
  bool operator==(const Span& o) const {
    return start == o.start && end == o.end && value == o.value;
  }
};
using Timeline = std::vector<Span>;

std::int64_t ps(double us) {
  return std::llround(us * 1e6);
}

unsigned code(const TraceRow& r) {
  return r.state == "compute" ? 1 : r.state == "communicate" ? 2 : r.state == "busy" ? 1 : 0;
}

// Non-zero spans, with touching spans of one value joined (the VCD cannot tell them apart).
void add_span(Timeline& t, std::int64_t start, std::int64_t end, unsigned value) {
  if (value == 0 || end <= start) return;
  if (!t.empty() && t.back().end == start && t.back().value == value)
    t.back().end = end;
  else
    t.push_back({start, end, value});
}

std::map<std::string, Timeline> csv_timelines(const std::vector<TraceRow>& rows) {
  std::map<std::string, Timeline> out;
  for (const TraceRow& r : rows)
    add_span(out[(r.kind == "processor" ? "processors." : "links.") + tools::vcd_name(r.name)],
             ps(r.start_us), ps(r.end_us), code(r));
  return out;
}

// Reads the signals of a SystemC VCD: $scope nesting, $var declarations, #time and value changes.
std::map<std::string, Timeline> vcd_timelines(const std::string& path) {
  std::ifstream in(path);
  std::map<std::string, std::string> name_of;                     // VCD id -> scope.name
  std::map<std::string, std::pair<std::int64_t, unsigned>> open;  // id -> (since, value)
  std::map<std::string, Timeline> out;
  std::vector<std::string> scope;
  std::int64_t now = 0;
  bool body = false;  // past $enddefinitions: only then are "1..." lines value changes
  for (std::string line; std::getline(in, line);) {
    std::istringstream s(line);
    std::string word;
    s >> word;
    if (word == "$enddefinitions") {
      body = true;
    } else if (word == "$scope") {
      std::string kind, name;
      s >> kind >> name;
      scope.push_back(name);
    } else if (word == "$upscope") {
      scope.pop_back();
    } else if (word == "$var") {
      std::string type, width, id, name;
      s >> type >> width >> id >> name;
      name_of[id] = scope.back() + "." + name;
    } else if (!word.empty() && word[0] == '#') {
      now = std::stoll(word.substr(1));
    } else if (body && !word.empty() && (word[0] == 'b' || word[0] == '0' || word[0] == '1')) {
      std::string id;
      unsigned value = 0;
      if (word[0] == 'b') {
        s >> id;
        value = unsigned(std::stoul(word.substr(1), nullptr, 2));
      } else {
        id = word.substr(1);
        value = word[0] == '1';
      }
      auto& [since, old] = open[id];
      add_span(out[name_of.at(id)], since, now, old);
      since = now;
      old = value;
    }
  }
  for (auto& [name, t] : out)
    if (t.empty()) out.erase(name);
  return out;
}

class Traces : public ::testing::Test {
 protected:
  void run(const std::string& scene_and_sets) {
    dir_ = std::filesystem::path(test_paths::binary_dir()) / "test-output" / "Traces" /
           ::testing::UnitTest::GetInstance()->current_test_info()->name();
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
    const auto o =
        cli_test::run("run " + scene_and_sets + " --json --trace-vcd " + file("t.vcd") +
                      " --trace-json " + file("t.json") + " --trace-csv " + file("t.csv"));
    ASSERT_EQ(o.exit_code, 0) << o.out;
    report_ = nlohmann::json::parse(o.out);
    rows_ = tools::read_trace_csv(file("t.csv"));
    std::ifstream chrome(file("t.json"));
    chrome_ = nlohmann::json::parse(chrome);
  }
  std::string file(const std::string& name) const { return (dir_ / name).string(); }

  // Per track: the sum of its non-idle durations in the CSV.
  std::map<std::string, double> csv_busy(const std::string& kind) const {
    std::map<std::string, double> busy;
    for (const TraceRow& r : rows_)
      if (r.kind == kind && r.state != "idle") busy[r.name] += r.end_us - r.start_us;
    return busy;
  }

  void expect_agreement() {
    // CSV against the report: busy per processor (and per state), busy per link direction.
    const auto proc_busy = csv_busy("processor");
    for (const auto& p : report_["processors"]) {
      const std::string name = p["name"];
      EXPECT_NEAR(proc_busy.count(name) ? proc_busy.at(name) : 0.0, p["busy_us"].get<double>(),
                  1e-6)
          << name;
      double compute = 0;
      for (const TraceRow& r : rows_)
        if (r.name == name && r.state == "compute") compute += r.end_us - r.start_us;
      EXPECT_NEAR(compute, p["compute_us"].get<double>(), 1e-6) << name;
    }
    // A link interval spans a message's packets and the short gaps between them (merge_gaps_below),
    // so it covers the report's busy time (packets alone) and never exceeds the run.
    const auto link_busy = csv_busy("link");
    for (const auto& l : report_["links"]) {
      const std::string name = l["name"];
      const double traced = link_busy.count(name) ? link_busy.at(name) : 0.0;
      EXPECT_GE(traced, l["busy_us"].get<double>() - 1e-6) << name;
      EXPECT_LE(traced, report_["simulated_us"].get<double>() + 1e-6) << name;
      if (l["busy_us"].get<double>() == 0) {
        EXPECT_EQ(traced, 0.0) << name;
      }
    }
    // Every processor's rows tile the run, from 0 to its end.
    std::map<std::string, double> reached;
    for (const TraceRow& r : rows_)
      if (r.kind == "processor") {
        EXPECT_NEAR(r.start_us, reached[r.name], 1e-9) << r.name;
        reached[r.name] = r.end_us;
      }
    for (const auto& [name, end] : reached)
      EXPECT_NEAR(end, report_["simulated_us"].get<double>(), 1e-6) << name;

    // Chrome JSON: one slice per non-idle CSV row, same track, times and name.
    std::map<std::pair<int, int>, std::string> track;
    std::vector<nlohmann::json> slices;
    for (const auto& e : chrome_["traceEvents"]) {
      if (e["ph"] == "M" && e["name"] == "thread_name")
        track[{e["pid"], e["tid"]}] = e["args"]["name"];
      if (e["ph"] == "X") slices.push_back(e);
    }
    std::size_t next = 0;
    for (const TraceRow& r : rows_) {
      if (r.state == "idle") continue;
      ASSERT_LT(next, slices.size());
      const auto& e = slices[next++];
      const std::string track_name = track[{e["pid"], e["tid"]}];
      EXPECT_EQ(track_name, r.name);
      EXPECT_EQ(e["pid"].get<int>(), r.kind == "processor" ? 1 : 2);
      EXPECT_EQ(e["name"], r.label.empty() ? r.state : r.label);
      EXPECT_NEAR(e["ts"].get<double>(), r.start_us, 1e-6);
      EXPECT_NEAR(e["dur"].get<double>(), r.end_us - r.start_us, 1e-6);
    }
    EXPECT_EQ(next, slices.size());

    // VCD: every signal follows the CSV to the picosecond.
    const auto from_vcd = vcd_timelines(file("t.vcd"));
    const auto from_csv = csv_timelines(rows_);
    EXPECT_EQ(from_vcd.size(), from_csv.size());
    for (const auto& [name, timeline] : from_csv) {
      ASSERT_TRUE(from_vcd.count(name)) << name;
      EXPECT_EQ(from_vcd.at(name), timeline) << name;
    }
  }

  std::filesystem::path dir_;
  nlohmann::json report_, chrome_;
  std::vector<TraceRow> rows_;
};

}  // namespace

TEST_F(Traces, PingPongTracesAgreeWithEachOtherAndTheReport) {
  run("configs/scenes/pingpong.toml --set workload.iterations=5");
  expect_agreement();
  EXPECT_FALSE(csv_busy("link").empty());
}

// Compute slices in the dynamics farm are named after the subtasks the workers evaluate.
TEST_F(Traces, DynamicsFarmTracesAgreeAndNameSubtasks) {
  run("configs/scenes/dynamics-farm.toml --set network.workers=3");
  expect_agreement();
  int labelled = 0;
  for (const TraceRow& r : rows_)
    if (r.name != "P0" && r.state == "compute") {
      EXPECT_FALSE(r.label.empty()) << r.name << " at " << r.start_us;
      labelled += !r.label.empty();
    }
  EXPECT_GT(labelled, 3);
}

TEST_F(Traces, AreWrittenForADeadlockedOrFailedRunOnlyWhenTheRunHappened) {
  dir_ = std::filesystem::path(test_paths::binary_dir()) / "test-output" / "Traces" / "bad";
  std::filesystem::create_directories(dir_);
  const auto o =
      cli_test::run("run configs/scenes/pingpong.toml --trace-csv /no/such/dir/t.csv 2>&1");
  EXPECT_EQ(o.exit_code, 2);
  EXPECT_NE(o.out.find("--trace-csv /no/such/dir/t.csv"), std::string::npos) << o.out;
}

TEST(VcdCommand, BadTraceFilesAreClearErrors) {
  const auto dir = std::filesystem::path(test_paths::binary_dir()) / "test-output" / "VcdCommand";
  std::filesystem::create_directories(dir);
  const std::string bad = (dir / "bad.csv").string();
  std::ofstream(bad) << "kind,name,state,start_us,end_us,label\nprocessor,P0,compute,5,2,\n";
  auto o = cli_test::run("vcd " + bad + " -o " + (dir / "x.vcd").string() + " 2>&1");
  EXPECT_EQ(o.exit_code, 2);
  EXPECT_NE(o.out.find("bad.csv:2"), std::string::npos) << o.out;
  o = cli_test::run("vcd " + (dir / "none.csv").string() + " -o x.vcd 2>&1");
  EXPECT_EQ(o.exit_code, 2);
  EXPECT_NE(o.out.find("none.csv"), std::string::npos) << o.out;
}
