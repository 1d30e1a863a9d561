// Step reuse (fidelity.reuse_steps, workloads/trajectory/trajectory.cpp): a run that reuses the
// timing of steps proven identical to simulated ones gives what the run that simulates every step
// gives -- the same final state bit for bit, the same time for every step, the same busy time of
// every processor and bytes of every link direction -- and it re-simulates a step whose pivots
// differ. Each case runs `t800sim run` twice (one simulation per process: SystemC cannot restart).
//
// Busy and link times are compared to 1e-9 relative, not exactly: the accounting sums differences
// of absolute times in double microseconds, so the same stretch of work at another time can differ
// in the last bits (the step times and the simulated end are exact: they come from exact
// sc_time differences). The pipeline's Tp (solve_us) is such a difference too.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>
#include "tests/test_files.hpp"
#include "tests/test_paths.hpp"

namespace {

struct Outcome {
  nlohmann::json report;
  std::vector<std::vector<std::string>> rows;  // the output CSV: one row per step, then the end
  std::vector<std::string> header;
  std::string trace;  // the CSV trace, when asked for
};

using test_files::read_file;

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream s(line);
  for (std::string cell; std::getline(s, cell, ',');) out.push_back(cell);
  return out;
}

// `t800sim run configs/scenes/trajectory.toml --json` with the overrides, reuse on or off.
Outcome run_steps(const std::vector<std::string>& overrides, bool reuse, bool trace = false) {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  std::string name = info->name();
  std::replace(name.begin(), name.end(), '/', '-');  // parameterised tests: Case/Param
  const std::string base =
      test_paths::binary_dir() + "/step-reuse-" + name + (reuse ? "-on" : "-off");
  std::string command = std::string("cd ") + test_paths::source_dir() +
                        " && SYSTEMC_DISABLE_COPYRIGHT_MESSAGE=1 " + test_paths::binary_dir() +
                        "/t800sim run configs/scenes/trajectory.toml --json --set "
                        "fidelity.reuse_steps=" +
                        (reuse ? "true" : "false") + " --set workload.output_csv=" + base + ".csv";
  if (trace) command += " --trace-csv " + base + "-trace.csv";
  for (const std::string& o : overrides) command += " --set '" + o + "'";
  FILE* pipe = popen(command.c_str(), "r");
  std::string out;
  char buffer[4096];
  while (std::size_t n = fread(buffer, 1, sizeof buffer, pipe)) out.append(buffer, n);
  EXPECT_EQ(pclose(pipe), 0) << command << "\n" << out;
  Outcome r;
  r.report = nlohmann::json::parse(out);
  std::stringstream csv(read_file(base + ".csv"));
  std::string line;
  std::getline(csv, line);
  r.header = split(line);
  while (std::getline(csv, line)) r.rows.push_back(split(line));
  if (trace) r.trace = read_file(base + "-trace.csv");
  return r;
}

void expect_close(double a, double b, const std::string& what) {
  EXPECT_LE(std::abs(a - b), 1e-9 * std::max(1.0, std::abs(b))) << what << ": " << a << " vs " << b;
}

const nlohmann::json& reuse_of(const Outcome& r) {
  return r.report["workload"]["step_reuse"];
}

// Everything the two runs report agrees: exactly where it can, to 1e-9 relative otherwise.
void expect_same(const Outcome& on, const Outcome& off) {
  const nlohmann::json &w_on = on.report["workload"], &w_off = off.report["workload"];
  ASSERT_FALSE(on.report.contains("deadlock"));
  ASSERT_FALSE(w_on.contains("failure"));
  EXPECT_EQ(w_on["steps"], w_off["steps"]);
  for (const char* key : {"final_q", "final_qd"})
    for (std::size_t i = 0; i < 6; ++i)
      EXPECT_EQ(w_on[key][i].get<double>(), w_off[key][i].get<double>()) << key << i + 1;
  EXPECT_EQ(on.report["simulated_us"].get<double>(), off.report["simulated_us"].get<double>());
  // Every step: the state exactly, the step time exactly, its split to 1e-9.
  ASSERT_EQ(on.rows.size(), off.rows.size());
  for (std::size_t n = 0; n < on.rows.size(); ++n)
    for (std::size_t c = 0; c < on.header.size(); ++c) {
      const std::string& name = on.header[c];
      const std::string what = "step " + std::to_string(n + 1) + " " + name;
      if (name == "dynamics_us" || name == "solve_us" || name == "integration_us" ||
          name == "communication_us")
        expect_close(std::stod(on.rows[n][c]), std::stod(off.rows[n][c]), what);
      else
        EXPECT_EQ(on.rows[n][c], off.rows[n][c]) << what;
    }
  const nlohmann::json &p_on = on.report["processors"], &p_off = off.report["processors"];
  ASSERT_EQ(p_on.size(), p_off.size());
  for (std::size_t i = 0; i < p_on.size(); ++i)
    for (const char* key : {"busy_us", "compute_us", "communicate_us"})
      expect_close(p_on[i][key], p_off[i][key], p_on[i]["name"].get<std::string>() + " " + key);
  const nlohmann::json &l_on = on.report["links"], &l_off = off.report["links"];
  ASSERT_EQ(l_on.size(), l_off.size());
  for (std::size_t i = 0; i < l_on.size(); ++i) {
    const std::string name = l_on[i]["name"];
    EXPECT_EQ(l_on[i]["bytes"], l_off[i]["bytes"]) << name;
    EXPECT_EQ(l_on[i]["messages"], l_off[i]["messages"]) << name;
    expect_close(l_on[i]["busy_us"], l_off[i]["busy_us"], name + " busy_us");
  }
  EXPECT_FALSE(reuse_of(off)["enabled"].get<bool>());
  EXPECT_EQ(reuse_of(off)["reused_steps"], 0);
  EXPECT_EQ(reuse_of(on)["simulated_steps"].get<int>() + reuse_of(on)["reused_steps"].get<int>(),
            w_on["steps"].get<int>());
}

// The PD gains of trajectory_test's PdDrivesTheArmTowardItsTarget (stable at these steps).
const std::vector<std::string> kPd = {"workload.torque=pd", "workload.kp=[300, 100, 2000, 5, 5, 2]",
                                      "workload.kd=[40, 20, 200, 0.5, 0.5, 0.2]",
                                      "workload.target=[0.3, 0.2, 0.5, 0.3, 0.4, 0.7]"};

std::vector<std::string> with(std::vector<std::string> a, const std::vector<std::string>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

// Block compute fidelity has no timeslice clock, so every step after the first of its signature is
// provably translation-invariant and is reused.
struct Case {
  const char* name;
  std::vector<std::string> overrides;
};

void PrintTo(const Case& c, std::ostream* os) {
  *os << c.name;
}

class StepReuse : public ::testing::TestWithParam<Case> {};

TEST_P(StepReuse, GivesWhatSimulatingEveryStepGives) {
  const auto overrides =
      with({"fidelity.compute=block", "workload.steps=30"}, GetParam().overrides);
  const Outcome on = run_steps(overrides, true), off = run_steps(overrides, false);
  expect_same(on, off);
  EXPECT_TRUE(reuse_of(on)["enabled"].get<bool>());
  EXPECT_GT(reuse_of(on)["reused_steps"].get<int>(), 20) << reuse_of(on).dump();
}

INSTANTIATE_TEST_SUITE_P(
    Trajectory, StepReuse,
    ::testing::Values(Case{"Rk4ZeroTorque", {}}, Case{"Rk4Pd", kPd},
                      Case{"SemiImplicitEulerZeroTorque",
                           {"workload.integrator=semi-implicit-euler"}},
                      Case{"SemiImplicitEulerPdReal64Partial",
                           with({"workload.integrator=semi-implicit-euler",
                                 "workload.precision=real64", "workload.pivoting=partial"},
                                kPd)}),
    [](const ::testing::TestParamInfo<Case>& info) { return std::string(info.param.name); });

// Partial pivoting on the falling arm (zero torque, dt = 2 ms; the state the default start reaches
// at t = 1.54 s, REAL32 values): the pivot rows change at the 7th and 8th step from here. Each new
// signature is simulated (and recorded), never replayed from another's timing; the step times
// differ, and the run still equals the one that simulates every step.
TEST(StepReuse, ANewPivotPatternIsSimulated) {
  const std::vector<std::string> overrides = {
      "fidelity.compute=block",
      "workload.steps=20",
      "workload.dt=0.002",
      "workload.pivoting=partial",
      "workload.q=[0.083621852099895477, 0.069127000868320465, -10.977685928344727, "
      "1.2865180969238281, 1.0319352149963379, -0.3430715799331665]",
      "workload.qd=[-0.009274238720536232, -0.05708220973610878, -14.996444702148438, "
      "0.20436160266399384, 0.42257809638977051, -0.11439169943332672]"};
  const Outcome on = run_steps(overrides, true), off = run_steps(overrides, false);
  expect_same(on, off);
  EXPECT_GE(reuse_of(on)["signatures_recorded"].get<int>(), 2) << reuse_of(on).dump();
  EXPECT_GT(reuse_of(on)["reused_steps"].get<int>(), 0);
  std::vector<std::string> step_times;
  for (std::size_t n = 0; n + 1 < on.rows.size(); ++n) step_times.push_back(on.rows[n][19]);
  ASSERT_EQ(on.header[19], "step_us");
  EXPECT_NE(std::count(step_times.begin(), step_times.end(), step_times.front()),
            std::ptrdiff_t(step_times.size()))
      << "the new pivots should change the step time";
}

// The default compute fidelity (auto) timeslices the CPUs that run several processes. Reuse must
// then be proven against the clock; whatever it decides, the run equals the fully simulated one,
// and every simulated step says why.
TEST(StepReuse, AutoComputeFidelityStillEqualsSimulatingEveryStep) {
  const std::vector<std::string> overrides = {"workload.steps=20"};
  const Outcome on = run_steps(overrides, true), off = run_steps(overrides, false);
  expect_same(on, off);
  int explained = 0;
  for (const auto& row : reuse_of(on)["simulated_because"]) explained += row["steps"].get<int>();
  EXPECT_EQ(explained, reuse_of(on)["simulated_steps"].get<int>());
}

// With a trace, a reused step's intervals are the recorded ones shifted in time: the trace has the
// same rows, at the same times (to 1e-6 us: the shifts are double arithmetic).
TEST(StepReuse, TracesReplayTheRecordedIntervals) {
  const std::vector<std::string> overrides = {"fidelity.compute=block", "workload.steps=6",
                                              "workload.integrator=semi-implicit-euler"};
  const Outcome on = run_steps(overrides, true, true), off = run_steps(overrides, false, true);
  expect_same(on, off);
  EXPECT_GT(reuse_of(on)["reused_steps"].get<int>(), 0);
  std::stringstream a(on.trace), b(off.trace);
  std::string la, lb;
  int rows = 0;
  while (std::getline(a, la)) {
    ASSERT_TRUE(std::getline(b, lb));
    const auto ca = split(la), cb = split(lb);
    ASSERT_EQ(ca.size(), cb.size()) << la << " | " << lb;
    for (std::size_t c = 0; c < ca.size(); ++c) {
      if (rows > 0 && (c == 3 || c == 4))
        EXPECT_NEAR(std::stod(ca[c]), std::stod(cb[c]), 1e-6) << la << " | " << lb;
      else
        EXPECT_EQ(ca[c], cb[c]) << la << " | " << lb;
    }
    ++rows;
  }
  EXPECT_FALSE(std::getline(b, lb));
  EXPECT_GT(rows, 1000);
}

}  // namespace
