// Mistakes a new user makes, and what t800sim says: what was wrong, where (file:line or the flag),
// and what would be valid. Defaults that change results are stated in every report.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "cli_fixtures.hpp"
#include "tests/test_paths.hpp"
#include "workloads/params.hpp"
#include "workloads/registry.hpp"

using cli_test::run;

namespace {

namespace fs = std::filesystem;

bool has(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

// A scratch directory for one test, under the build tree.
std::string scratch() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const fs::path dir = fs::path(test_paths::binary_dir()) / "test-output" / info->name();
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir.string();
}

std::string write(const std::string& path, const std::string& text) {
  std::ofstream(path) << text;
  return path;
}

int line_of(const std::string& path, const std::string& needle) {
  std::ifstream in(path);
  std::string line;
  for (int n = 1; std::getline(in, line); ++n)
    if (has(line, needle)) return n;
  return 0;
}

}  // namespace

TEST(Messages, CheckOfABadSceneSaysOnlyWhatIsWrong) {
  const std::string scene = write(scratch() + "/bad.toml",
                                  "name = \"bad\"\n[network]\nfamily = 3\n[workload]\nkind = "
                                  "\"pingpong\"\n");
  const auto o = run("check " + scene + " 2>&1");
  EXPECT_EQ(o.exit_code, 2) << o.out;
  EXPECT_FALSE(has(o.out, "ok:")) << o.out;
  EXPECT_TRUE(has(o.out, scene + ":3:")) << o.out;
  // A scene without [workload] is still read as a scene, not as a topology with unknown keys.
  const std::string no_workload =
      write(scratch() + "/nw.toml", "[network]\nfamily = \"tree\"\nworkers = 3\n");
  const auto n = run("check " + no_workload + " 2>&1");
  EXPECT_EQ(n.exit_code, 2);
  EXPECT_TRUE(has(n.out, "no [workload] table")) << n.out;
}

TEST(Messages, AnUnknownCommandIsNamedWithTheValidOnes) {
  const auto o = run("frobnicate 2>&1");
  EXPECT_EQ(o.exit_code, 2);
  EXPECT_TRUE(has(o.out, "unknown command 'frobnicate'")) << o.out;
  for (const char* command : {"run", "check", "paper", "sweep", "dynamics"})
    EXPECT_TRUE(has(o.out, command)) << command << "\n" << o.out;
  const auto none = run("2>&1");
  EXPECT_EQ(none.exit_code, 2);
  EXPECT_TRUE(has(none.out, "give a command")) << none.out;
  EXPECT_TRUE(has(none.out, "run, check")) << none.out;
}

// `run --workers 9 SCENE` used to blame the (valid) scene file as an unexpected argument.
TEST(Messages, AnUnknownOptionIsNamedAndTheSceneKeySuggested) {
  const auto o = run("run --workers 9 configs/scenes/dynamics-farm.toml 2>&1");
  EXPECT_EQ(o.exit_code, 2);
  EXPECT_TRUE(has(o.out, "unknown option --workers")) << o.out;
  EXPECT_TRUE(has(o.out, "--set network.workers=9")) << o.out;
  EXPECT_TRUE(has(o.out, "--json")) << o.out;  // the valid options
  EXPECT_FALSE(has(o.out, "not expected")) << o.out;
  const auto w = run("run configs/scenes/pingpong.toml --bytes=64 2>&1");
  EXPECT_TRUE(has(w.out, "--set workload.bytes=64")) << w.out;
}

TEST(Messages, RunWithoutASceneListsTheShippedScenes) {
  const auto o = run("run 2>&1");
  EXPECT_EQ(o.exit_code, 2);
  EXPECT_TRUE(has(o.out, "needs a scene file")) << o.out;
  int scenes = 0;
  for (const auto& e :
       fs::directory_iterator(fs::path(test_paths::source_dir()) / "configs/scenes"))
    if (e.path().extension() == ".toml") {
      ++scenes;
      EXPECT_TRUE(has(o.out, e.path().filename().string())) << e.path() << "\n" << o.out;
    }
  EXPECT_GE(scenes, 5);
}

// A scene copied elsewhere loses its calibration file: the error points at the scene's line.
TEST(Messages, AMissingCalibrationFileIsReportedAtTheSceneLine) {
  const std::string copy = scratch() + "/farm.toml";
  fs::copy_file(fs::path(test_paths::source_dir()) / "configs/scenes/dynamics-farm.toml", copy);
  const int line = line_of(copy, "file = ");
  ASSERT_GT(line, 0);
  const auto o = run("run " + copy + " 2>&1");
  EXPECT_EQ(o.exit_code, 2);
  EXPECT_TRUE(has(o.out, copy + ":" + std::to_string(line) + ":")) << o.out;
  EXPECT_TRUE(has(o.out, "calibration file")) << o.out;
  EXPECT_TRUE(has(o.out, "relative to the scene")) << o.out;
}

TEST(Messages, PaperSaysWhereTable6IsAnalysed) {
  const auto o = run("paper --table 6 2>&1");
  ASSERT_EQ(o.exit_code, 0) << o.out;
  EXPECT_TRUE(has(o.out, "docs/table6.md")) << o.out;
  EXPECT_TRUE(fs::exists(fs::path(test_paths::source_dir()) / "docs/table6.md"));
}

// The precision changes every compute cost: a report always says which one ran and why.
TEST(Messages, EveryReportStatesThePrecisionAndWhereItCameFrom) {
  const auto ping = run("run configs/scenes/pingpong.toml 2>&1");
  ASSERT_EQ(ping.exit_code, 0) << ping.out;
  EXPECT_TRUE(has(ping.out,
                  "precision       real64 (the simulator's default; workload pingpong "
                  "declares no precision)"))
      << ping.out;
  const std::string dir = scratch();
  const std::string scene =
      write(dir + "/farm.toml",
            std::string("[network]\nfamily = \"tree\"\nworkers = 1\n[workload]\nkind = "
                        "\"dynamics-farm\"\nrobot = \"") +
                test_paths::source_dir() + "/configs/robots/stanford.toml\"\n");
  const auto dflt = run("run " + scene + " --json 2>&1");
  ASSERT_EQ(dflt.exit_code, 0) << dflt.out;
  const auto& declared =
      workloads::find_workload("dynamics-farm")->find("precision")->default_value;
  EXPECT_TRUE(has(dflt.out, "\"value\": \"" + std::get<std::string>(declared) + "\"")) << dflt.out;
  EXPECT_TRUE(has(dflt.out, "the default of workload dynamics-farm")) << dflt.out;
  const auto set = run("run " + scene + " --set workload.precision=real64 --json 2>&1");
  EXPECT_TRUE(has(set.out, "\"value\": \"real64\", \"source\": \"workload.precision\"")) << set.out;
}

// The paper's simplified model is derived for the robot at hand, and refused where its assumption
// fails, naming the assumption.
TEST(Messages, ThePaperModelIsRefusedForARobotItDoesNotFit) {
  const std::string dir = scratch();
  const std::string scene =
      write(dir + "/puma.toml",
            std::string(
                "[network]\nfamily = \"tree\"\nworkers = 3\n[workload]\nkind = \"dynamics-farm\"\n"
                "model = \"paper\"\nrobot = \"") +
                test_paths::source_dir() + "/configs/robots/puma560.toml\"\n");
  const auto o = run("run " + scene + " 2>&1");
  EXPECT_EQ(o.exit_code, 2) << o.out;
  for (const char* words : {"model \"paper\" does not fit", "Puma 560", "axial inertia",
                            "negligible", "model \"full\""})
    EXPECT_TRUE(has(o.out, words)) << words << "\n" << o.out;
  const auto full = run("run " + scene + " --set workload.model=full 2>&1");
  EXPECT_EQ(full.exit_code, 0) << full.out;
}
