// `t800sim sweep` and `t800sim merge` end to end: rows, failures, resuming, speed-up, jobs for GNU
// parallel.
#include <gtest/gtest.h>

#include "sweep_fixtures.hpp"
#include "tools/sweep_csv.hpp"

using cli_test::run;
using sweep_test::fresh_dir;
using sweep_test::lines;
using sweep_test::read_file;
using sweep_test::column;
using sweep_test::table;

namespace {

const std::string kChain = "tests/sweep/chain-pingpong.toml";

}  // namespace

TEST(SweepCommand, OneRowPerPointWithTheDocumentedColumns) {
  const std::string out = fresh_dir() + "/r.csv";
  const auto o =
      run("sweep configs/scenes/pingpong.toml --vary workload.bytes=16..64:x2 --vary "
          "workload.iterations=2,4 -j 2 -o " +
          out + " 2>&1");
  ASSERT_EQ(o.exit_code, 0) << o.out;
  const auto t = table(out);
  ASSERT_EQ(t.size(), 7u);
  EXPECT_EQ(lines(read_file(out))[0],
            "workload.bytes,workload.iterations,workload,precision,network,processor,processors,"
            "tp_us,speedup,efficiency,util_min,util_mean,util_max,wall_s,status");
  EXPECT_EQ(t[1][0], "16");
  EXPECT_EQ(t[1][1], "2");
  EXPECT_EQ(t[6][0], "64");
  EXPECT_EQ(t[6][1], "4");
  for (std::size_t r = 1; r < t.size(); ++r) {
    EXPECT_EQ(t[r][column(t, "status")], "ok");
    EXPECT_GT(std::stod(t[r][column(t, "tp_us")]), 0);
    EXPECT_LE(std::stod(t[r][column(t, "util_min")]), std::stod(t[r][column(t, "util_max")]));
  }
  // Twice the iterations, twice the time (same message size).
  const std::size_t tp = column(t, "tp_us");
  EXPECT_NEAR(std::stod(t[2][tp]), 2 * std::stod(t[1][tp]), 0.01 * std::stod(t[1][tp]));
  // What each point ran on: the scene's pair of T800-20s, wired as the 1-worker chain/tree.
  EXPECT_EQ(t[1][column(t, "workload")], "pingpong");
  EXPECT_EQ(t[1][column(t, "processor")], "T800-20");
  EXPECT_EQ(t[1][column(t, "processors")], "2");
  // Not a terminal: one progress line per point.
  EXPECT_NE(o.out.find("[6/6]"), std::string::npos) << o.out;
}

TEST(SweepCommand, AFailingPointIsReportedAndTheOthersRun) {
  const std::string out = fresh_dir() + "/r.csv";
  const auto o =
      run("sweep configs/scenes/pingpong.toml --vary workload.bytes=0,64 -o " + out + " 2>&1");
  EXPECT_EQ(o.exit_code, 1) << o.out;
  const auto t = table(out);
  ASSERT_EQ(t.size(), 3u);
  const std::string status = t[1][column(t, "status")];
  EXPECT_EQ(status.rfind("error: ", 0), 0u) << status;
  EXPECT_NE(status.find("workload.bytes=0"), std::string::npos) << status;
  EXPECT_EQ(status.find("--set"), std::string::npos) << status;  // named as the varied key
  EXPECT_EQ(t[2][column(t, "status")], "ok");
}

TEST(SweepCommand, RerunningSkipsTheOkPointsAndRetriesTheFailedOnes) {
  const std::string dir = fresh_dir();
  const std::string out = dir + "/r.csv";
  run("sweep configs/scenes/pingpong.toml --vary workload.bytes=0,16,32 -o " + out + " 2>&1");
  const auto first = table(out);
  // The same sweep, wider: the two ok points are kept as they were, the failed one and the new one
  // run.
  const auto o = run("sweep configs/scenes/pingpong.toml --vary workload.bytes=0,16,32,48 -o " +
                     out + " 2>&1");
  EXPECT_NE(o.out.find("2 of 4 points already in"), std::string::npos) << o.out;
  EXPECT_NE(o.out.find("[2/2]"), std::string::npos) << o.out;
  EXPECT_EQ(o.out.find("[3/"), std::string::npos) << o.out;
  const auto second = table(out);
  ASSERT_EQ(second.size(), 5u);
  EXPECT_EQ(second[2], first[2]);  // wall time included: not rerun
  EXPECT_EQ(second[3], first[3]);
  EXPECT_EQ(second[4][0], "48");
  EXPECT_EQ(second[4][column(second, "status")], "ok");
}

TEST(SweepCommand, AnOutputOfAnotherSweepIsNotOverwritten) {
  const std::string out = fresh_dir() + "/r.csv";
  run("sweep configs/scenes/pingpong.toml --vary workload.bytes=16 -o " + out);
  const std::string before = read_file(out);
  const auto o =
      run("sweep configs/scenes/pingpong.toml --vary workload.iterations=2 -o " + out + " 2>&1");
  EXPECT_EQ(o.exit_code, 2);
  EXPECT_NE(o.out.find("other parameters"), std::string::npos) << o.out;
  EXPECT_EQ(read_file(out), before);
}

// The chain's workload uses only P0 and P1, so Tp does not depend on the number of workers.
TEST(SweepCommand, SpeedupAndEfficiencyAgainstTheFewestWorkers) {
  const std::string out = fresh_dir() + "/r.csv";
  const auto o = run("sweep " + kChain + " --vary network.workers=1..4 -j 2 -o " + out + " 2>&1");
  ASSERT_EQ(o.exit_code, 0) << o.out;
  const auto t = table(out);
  ASSERT_EQ(t.size(), 5u);
  for (int w = 1; w <= 4; ++w) {
    EXPECT_EQ(t[std::size_t(w)][0], std::to_string(w));
    EXPECT_DOUBLE_EQ(std::stod(t[std::size_t(w)][column(t, "speedup")]), 1.0);
    EXPECT_NEAR(std::stod(t[std::size_t(w)][column(t, "efficiency")]), 1.0 / w, 1e-6);
  }
}

TEST(SweepCommand, BadVarySyntaxNamesTheFlagAndTheForms) {
  const auto o =
      run("sweep configs/scenes/pingpong.toml --vary workload.bytes=1...x -o /dev/null 2>&1");
  EXPECT_EQ(o.exit_code, 2);
  EXPECT_NE(o.out.find("--vary workload.bytes=1...x"), std::string::npos) << o.out;
  EXPECT_NE(o.out.find("A..B:xF"), std::string::npos) << o.out;
}

// A wrong value in a --vary is reported as that flag (not as the --set the point becomes), with the
// valid forms.
TEST(SweepCommand, BadVaryValuesNameTheVaryFlagAndTheForms) {
  for (const char* vary : {"network.workers=1-8", "network.workers=a,b"}) {
    const auto o = run(std::string("sweep configs/scenes/dynamics-farm.toml --vary ") + vary +
                       " -o /dev/null 2>&1");
    EXPECT_EQ(o.exit_code, 2) << o.out;
    EXPECT_NE(o.out.find(std::string("--vary ") + vary), std::string::npos) << o.out;
    EXPECT_NE(o.out.find("valid forms"), std::string::npos) << o.out;
    EXPECT_NE(o.out.find("A..B"), std::string::npos) << o.out;
    EXPECT_EQ(o.out.find("--set"), std::string::npos) << o.out;
  }
}

// A user's own topology files are swept as a list; each row says what network it ran. A topology
// file wired as a family gives that family's Tp (tree-3.toml is the generated 3-worker tree).
TEST(SweepCommand, TopologyFilesCanBeSwept) {
  const std::string out = fresh_dir() + "/r.csv";
  const auto o =
      run("sweep configs/scenes/dynamics-farm.toml --vary "
          "network.topology=../topologies/tree-3.toml,../topologies/chain-5.toml -o " +
          out + " 2>&1");
  ASSERT_EQ(o.exit_code, 0) << o.out;
  const auto t = table(out);
  ASSERT_EQ(t.size(), 3u);
  EXPECT_EQ(t[1][column(t, "network")], "tree");
  EXPECT_EQ(t[1][column(t, "processors")], "4");
  EXPECT_EQ(t[2][column(t, "network")], "chain");
  EXPECT_EQ(t[2][column(t, "processors")], "5");
  const auto family =
      run("run configs/scenes/dynamics-farm.toml --set network.workers=3 --json 2>&1");
  ASSERT_EQ(family.exit_code, 0) << family.out;
  EXPECT_NEAR(std::stod(t[1][column(t, "tp_us")]), cli_test::json_number(family.out, "tp_us"),
              1e-3);
}

TEST(SweepCommand, InputErrorsAreClearAndRunNothing) {
  const std::string dir = fresh_dir();
  struct Case {
    std::string args, expect;
  };
  for (const Case& c : std::vector<Case>{
           {"configs/scenes/none.toml --vary workload.bytes=1 -o x.csv", "none.toml"},
           {"configs/scenes/pingpong.toml --vary workload.bytes=1", "-o FILE is required"},
           {"configs/scenes/pingpong.toml --vary workload.bytes=1 --set workload.bytes=2 -o x.csv",
            "same key"},
           {"configs/scenes/pingpong.toml --vary workload.bytes=1 -j 0 -o x.csv", "-j 0"},
           {"configs/scenes/pingpong.toml --vary workload.bytes=1 --set workload.nope=1 -o x.csv",
            "nope"},
           {"configs/scenes/pingpong.toml -o x.csv", "--vary"},
           // A misspelt varied key fails every point alike: one error, before any child runs.
           {"configs/scenes/pingpong.toml --vary workload.nope=1,2 -o x.csv",
            "unknown key 'nope'"}}) {
    const auto o = run("sweep " + c.args + " 2>&1");
    EXPECT_EQ(o.exit_code, 2) << c.args << "\n" << o.out;
    EXPECT_NE(o.out.find(c.expect), std::string::npos) << c.args << "\n" << o.out;
  }
}

// The jobs file run by GNU parallel, merged, gives the table a local sweep gives (wall times
// aside).
TEST(SweepJobs, GnuParallelAndMergeMatchALocalSweep) {
  if (!sweep_test::available("parallel --version")) GTEST_SKIP() << "GNU parallel is not installed";
  const std::string dir = fresh_dir();
  const std::string sweep =
      "sweep " + kChain + " --vary network.workers=1..3 --vary workload.bytes=8,0";
  ASSERT_EQ(run(sweep + " --emit-jobs " + dir + "/jobs.txt --jobs-dir " + dir + "/results 2>&1")
                .exit_code,
            0);
  EXPECT_EQ(lines(read_file(dir + "/jobs.txt")).size(), 6u);
  const int status =
      std::system(("cd " + dir + " && parallel -j 2 < jobs.txt > parallel.log 2>&1").c_str());
  EXPECT_EQ(WEXITSTATUS(status), 3)
      << "parallel exits with the number of failed jobs: the bytes=0 points\n"
      << read_file(dir + "/parallel.log");
  ASSERT_EQ(run("merge " + dir + "/results -o " + dir + "/merged.csv 2>&1").exit_code, 0);
  run(sweep + " -o " + dir + "/local.csv 2>&1");
  const auto merged = table(dir + "/merged.csv");
  const auto local = table(dir + "/local.csv");
  ASSERT_EQ(merged.size(), local.size());
  ASSERT_EQ(merged.size(), 7u);
  const std::size_t wall = column(local, "wall_s");
  for (std::size_t r = 0; r < local.size(); ++r) {
    auto m = merged[r], l = local[r];
    m[wall] = l[wall] = "";
    EXPECT_EQ(m, l) << "row " << r;
  }
}

TEST(SweepJobs, OnePointWritesItsJsonResult) {
  const std::string dir = fresh_dir();
  const auto o = run("sweep " + kChain + " --vary network.workers=1,2 --point 1 -o " + dir +
                     "/p/one.json 2>&1");
  ASSERT_EQ(o.exit_code, 0) << o.out;
  const std::string json = read_file(dir + "/p/one.json");
  EXPECT_NE(json.find(R"("params":[["network.workers","2"]])"), std::string::npos) << json;
  EXPECT_NE(json.find(R"("status":"ok")"), std::string::npos) << json;
  EXPECT_NE(json.find(R"("report":{)"), std::string::npos) << json;
  EXPECT_EQ(
      run("sweep " + kChain + " --vary network.workers=1,2 --point 2 -o x.json 2>&1").exit_code, 2);
}

TEST(MergeCommand, RefusesFilesThatAreNotResults) {
  const std::string dir = fresh_dir();
  sweep_test::write_file(dir + "/bad.json", "{\"simulated_us\": 3}");
  auto o = run("merge " + dir + "/bad.json -o " + dir + "/m.csv 2>&1");
  EXPECT_EQ(o.exit_code, 2);
  EXPECT_NE(o.out.find("bad.json: not a sweep point result"), std::string::npos) << o.out;
  sweep_test::write_file(dir + "/broken.json", "{\"params\": [");
  o = run("merge " + dir + "/broken.json -o " + dir + "/m.csv 2>&1");
  EXPECT_EQ(o.exit_code, 2);
  EXPECT_NE(o.out.find("broken.json: not JSON"), std::string::npos) << o.out;
  o = run("merge " + dir + "/missing -o " + dir + "/m.csv 2>&1");
  EXPECT_EQ(o.exit_code, 2);
  EXPECT_NE(o.out.find("missing: no such file"), std::string::npos) << o.out;
}
