// tools/plot on generated inputs: each picture is written, in the format the -o extension asks for,
// and bad inputs are one-line errors. Skipped where Debian's python3-matplotlib is missing
// (scripts/setup.sh installs it).
#include <gtest/gtest.h>

#include "sweep_fixtures.hpp"
#include "tests/test_paths.hpp"

using sweep_test::fresh_dir;
using sweep_test::read_file;

namespace {

cli_test::Output plot(const std::string& args) {
  const std::string command = std::string("cd ") + test_paths::source_dir() +
                              " && timeout 120 tools/plot " + args + " 2>&1";
  cli_test::Output o;
  FILE* pipe = popen(command.c_str(), "r");
  char buffer[4096];
  while (std::size_t n = fread(buffer, 1, sizeof buffer, pipe)) o.out.append(buffer, n);
  const int status = pclose(pipe);
  o.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return o;
}

bool is_png(const std::string& path) {
  return read_file(path).rfind("\x89PNG\r\n\x1a\n", 0) == 0;
}

class Plot : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!sweep_test::available("/usr/bin/python3 -c 'import matplotlib'"))
      GTEST_SKIP() << "python3-matplotlib is not installed";
    dir_ = fresh_dir();
  }
  std::string dir_;
};

}  // namespace

TEST_F(Plot, GanttFromARunsCsvTrace) {
  ASSERT_EQ(
      cli_test::run("run configs/scenes/pingpong.toml --set workload.iterations=3 --trace-csv " +
                    dir_ + "/t.csv")
          .exit_code,
      0);
  const auto o = plot("gantt " + dir_ + "/t.csv -o " + dir_ + "/g.png");
  ASSERT_EQ(o.exit_code, 0) << o.out;
  EXPECT_TRUE(is_png(dir_ + "/g.png"));
}

const std::string kHeader =
    "workload,precision,network,processor,processors,tp_us,speedup,efficiency,util_min,util_mean,"
    "util_max,wall_s,status\n";

TEST_F(Plot, SpeedupFromASweepWithThePaperOverlaid) {
  sweep_test::write_file(
      dir_ + "/r.csv", "network.workers," + kHeader +
                           "1,dynamics-farm,real32,tree,T800-20,2,25600,1,1,0.1,0.5,1,0.1,ok\n"
                           "3,dynamics-farm,real32,tree,T800-20,4,9000,2.84,0.95,0.1,0.5,1,0.1,ok\n"
                           "6,dynamics-farm,real32,tree,T800-20,7,4600,5.57,0.93,0.1,0.5,1,0.1,ok\n"
                           "9,,,,,,,,,,,0.1,\"error: x\"\n");
  auto o = plot("speedup " + dir_ + "/r.csv --paper -o " + dir_ + "/s.svg");
  ASSERT_EQ(o.exit_code, 0) << o.out;
  const std::string svg = read_file(dir_ + "/s.svg");
  EXPECT_NE(svg.find("<svg"), std::string::npos);
  o = plot("speedup " + dir_ + "/r.csv -o " + dir_ + "/s.png");
  ASSERT_EQ(o.exit_code, 0) << o.out;
  EXPECT_TRUE(is_png(dir_ + "/s.png"));
}

// The paper's Table 4 is drawn only against rows that run its network (the tree) and processor
// (T800-20); a sweep of other networks gets an error saying so.
TEST_F(Plot, ThePaperIsOverlaidOnlyWhereTheSweepRunsItsNetwork) {
  sweep_test::write_file(dir_ + "/chain.csv",
                         "network.workers," + kHeader +
                             "1,dynamics-farm,real32,chain,T800-20,2,25600,1,1,0.1,0.5,1,0.1,ok\n"
                             "3,dynamics-farm,real32,chain,T800-20,4,9500,,,0.1,0.5,1,0.1,ok\n");
  auto o = plot("speedup " + dir_ + "/chain.csv --paper -o " + dir_ + "/s.png");
  EXPECT_EQ(o.exit_code, 2) << o.out;
  EXPECT_NE(o.out.find("no series"), std::string::npos) << o.out;
  EXPECT_NE(o.out.find("tree"), std::string::npos) << o.out;
  o = plot("speedup " + dir_ + "/chain.csv -o " + dir_ + "/s.png");
  EXPECT_EQ(o.exit_code, 0) << o.out;
  sweep_test::write_file(dir_ + "/t25.csv",
                         "network.workers," + kHeader +
                             "1,dynamics-farm,real32,tree,T800-25,2,20000,1,1,0.1,0.5,1,0.1,ok\n");
  o = plot("speedup " + dir_ + "/t25.csv --paper -o " + dir_ + "/s.png");
  EXPECT_EQ(o.exit_code, 2) << o.out;
}

// A sweep over topology files is plotted against their processor counts, each point named.
TEST_F(Plot, SpeedupOfASweepOverTopologyFiles) {
  sweep_test::write_file(
      dir_ + "/topo.csv",
      "network.topology," + kHeader +
          "../topologies/tree-3.toml,dynamics-farm,real32,tree,T800-20,4,8556,,,0.1,0.5,1,0.1,ok\n"
          "../topologies/mesh-3x3.toml,dynamics-farm,real32,mesh,T800-20,9,3617,,,0.1,0.5,1,0.1,"
          "ok\n");
  const auto o = plot("speedup " + dir_ + "/topo.csv --paper -o " + dir_ + "/s.png");
  ASSERT_EQ(o.exit_code, 0) << o.out;
  EXPECT_TRUE(is_png(dir_ + "/s.png"));
}

TEST_F(Plot, UtilisationFromARunReport) {
  const auto run = cli_test::run("run configs/scenes/pingpong.toml --json");
  ASSERT_EQ(run.exit_code, 0);
  sweep_test::write_file(dir_ + "/report.json", run.out);
  const auto o = plot("utilisation " + dir_ + "/report.json -o " + dir_ + "/u.png");
  ASSERT_EQ(o.exit_code, 0) << o.out;
  EXPECT_TRUE(is_png(dir_ + "/u.png"));
}

// The fidelity benchmark's CSV as the README shows it (docs/bench-fidelity.csv), whose trajectory
// points lie side by side at the same error.
TEST_F(Plot, BenchFromTheFidelityBenchmarksCsv) {
  const auto o = plot("bench docs/bench-fidelity.csv -o " + dir_ + "/f.svg");
  ASSERT_EQ(o.exit_code, 0) << o.out;
  const std::string svg = read_file(dir_ + "/f.svg");
  EXPECT_NE(svg.find("<svg"), std::string::npos);
}

TEST_F(Plot, BadInputsAreOneLineErrors) {
  sweep_test::write_file(dir_ + "/r.csv", "workload.bytes,tp_us,status\n1,2,ok\n");
  auto o = plot("speedup " + dir_ + "/r.csv -o " + dir_ + "/s.png");
  EXPECT_EQ(o.exit_code, 2);
  EXPECT_NE(o.out.find("no column network.workers"), std::string::npos) << o.out;
  o = plot("gantt " + dir_ + "/missing.csv -o " + dir_ + "/g.png");
  EXPECT_EQ(o.exit_code, 2);
  EXPECT_NE(o.out.find("missing.csv"), std::string::npos) << o.out;
  o = plot("utilisation " + dir_ + "/r.csv -o " + dir_ + "/u.png");
  EXPECT_EQ(o.exit_code, 2);
  EXPECT_NE(o.out.find("not a t800sim run --json report"), std::string::npos) << o.out;
  o = plot("gantt " + dir_ + "/r.csv -o " + dir_ + "/g.jpg");
  EXPECT_EQ(o.exit_code, 2);
  EXPECT_NE(o.out.find(".png or .svg"), std::string::npos) << o.out;
  EXPECT_EQ(o.out.find("Traceback"), std::string::npos) << o.out;
}
