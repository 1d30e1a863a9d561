// Errors found once the scene has been read (a setting the network rules out, a non-finite number,
// a missing robot file) name the scene line that gave the setting, or the --set flag; and `check`
// finds everything `run` would, so that check saying ok means run does not fail on its input.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "cli_fixtures.hpp"
#include "network/config_error.hpp"
#include "tests/test_paths.hpp"
#include "tools/paper_data.hpp"
#include "tools/run_inputs.hpp"
#include "tools/scene.hpp"

namespace {

namespace fs = std::filesystem;

std::string source(const std::string& relative) {
  return test_paths::source_dir() + "/" + relative;
}

std::string scene_file(const std::string& text) {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const fs::path dir =
      fs::path(test_paths::binary_dir()) / "test-output" / info->test_suite_name() / info->name();
  fs::create_directories(dir);
  const std::string path = (dir / "scene.toml").string();
  std::ofstream(path) << text;
  return path;
}

// What `run` checks before simulating, and what `check` does.
network::ConfigError error_of(const std::string& path,
                              const std::vector<std::string>& overrides = {}) {
  try {
    tools::inputs_from(tools::load_scene(path, overrides));
  } catch (const network::ConfigError& e) {
    return e;
  }
  ADD_FAILURE() << "no error";
  return network::ConfigError({}, "");
}

::testing::AssertionResult at(const network::ConfigError& e, const std::string& file, int line,
                              int column, const std::string& part) {
  if (e.where().file != file || e.where().line != line || e.where().column != column ||
      e.message().find(part) == std::string::npos)
    return ::testing::AssertionFailure() << "got " << e.what();
  return ::testing::AssertionSuccess();
}

std::string pingpong(const std::string& topology, const std::string& workload) {
  return "[network]\ntopology = \"" + source("configs/topologies/" + topology) +
         "\"\n[workload]\nkind = \"pingpong\"\n" + workload;
}

TEST(SettingErrors, ProcessorsThatAreNotNeighboursNameTheLineOrFlag) {
  const std::string path = scene_file(pingpong("chain-5.toml", "from = \"P0\"\nto = \"P3\"\n"));
  EXPECT_TRUE(at(error_of(path), path, 6, 6, "workload.from and workload.to must be neighbours"));
  const std::string plain = scene_file(pingpong("chain-5.toml", ""));
  EXPECT_TRUE(at(error_of(plain, {"workload.to=P2", "workload.from=P4"}), "--set workload.to=P2", 0,
                 0, "must be neighbours: P4 and P2 are not linked"));
}

TEST(SettingErrors, ANetworkWithoutNeighboursNamesWhereTheNetworkWasGiven) {
  const std::string path = scene_file(pingpong("single.toml", ""));
  EXPECT_TRUE(at(error_of(path), path, 2, 12, "processor P0 has no neighbour"));
}

TEST(SettingErrors, NonFiniteNumbersAreCaughtLikeNan) {
  for (const char* value : {"nan", "inf", "-inf"}) {
    const std::string flag = std::string("workload.q=[0.1, 0.2, 0.5, 0.3, ") + value + ", 0.5]";
    EXPECT_TRUE(at(error_of(source("configs/scenes/dynamics-farm.toml"), {flag}), "--set " + flag,
                   0, 0, "give finite numbers"))
        << value;
  }
}

// Values at the edges of their type are quoted as given: an integer exactly (it was once printed
// through a double, 2^63-1 as 9223372036854775808.), a float as the shortest text that reads back.
TEST(SettingErrors, ValuesAtTheEdgesAreQuotedAsGiven) {
  const std::string scene = source("configs/scenes/pingpong.toml");
  EXPECT_TRUE(at(error_of(scene, {"workload.bytes=9223372036854775807"}),
                 "--set workload.bytes=9223372036854775807", 0, 0,
                 "workload.bytes = 9223372036854775807 is outside the valid range"));
  EXPECT_TRUE(at(error_of(scene, {"network.link_speed_mbps=9223372036854775807"}),
                 "--set network.link_speed_mbps=9223372036854775807", 0, 0,
                 "link speed 9223372036854775807 Mbit/s"));
  EXPECT_TRUE(at(error_of(scene, {"network.link_speed_mbps=5e-324"}),
                 "--set network.link_speed_mbps=5e-324", 0, 0, "link speed 5e-324 Mbit/s"));
}

TEST(SettingErrors, TooFewLevel2ProcessorsNameTheLine) {
  const std::string path =
      scene_file("[network]\ntopology = \"" + source("configs/topologies/elimination-m2.toml") +
                 "\"\n[workload]\nkind = \"elimination\"\nm = 4\nrobot = \"" +
                 source("configs/robots/stanford.toml") + "\"\n");
  EXPECT_TRUE(
      at(error_of(path), path, 5, 5, "workload.m = 4 but the topology elimination-m2 has 2"));
  const std::string trajectory = source("configs/scenes/trajectory.toml");
  EXPECT_TRUE(at(error_of(trajectory, {"workload.m=5"}), "--set workload.m=5", 0, 0,
                 "workload.m = 5 but the topology trajectory-9-m3 has 3"));
}

TEST(SettingErrors, AnEmptyCalibrationFileNameNamesTheLine) {
  const std::string path = scene_file(pingpong("pair.toml", "") + "[calibration]\nfile = \"\"\n");
  try {
    tools::load_scene(path);
    FAIL() << "accepted";
  } catch (const network::ConfigError& e) {
    EXPECT_TRUE(at(e, path, 6, 8, "calibration file '' not found"));
  }
}

TEST(SettingErrors, ConfigErrorsWithoutAFileDoNotStartWithAColon) {
  EXPECT_EQ(std::string(network::ConfigError({}, "why").what()), "error: why");
}

// A dynamics farm on a generated tree with the shipped robot, unless `workload` names another (a
// key repeated in a TOML table is an error, so a case's robot line comes instead of the default's).
std::string farm(const std::string& workload) {
  const bool robot = workload.rfind("robot", 0) == 0;
  return "[network]\nfamily = \"tree\"\nworkers = 3\n[workload]\nkind = \"dynamics-farm\"\n" +
         (robot ? "" : "robot = \"" + source("configs/robots/stanford.toml") + "\"\n") + workload;
}

// `check` opens the robot file and builds the workload, as `run` does: what run would refuse, check
// refuses with the same message, and check saying ok means run does not fail on its input.
TEST(CheckCommand, FindsWhatRunWouldFind) {
  struct Case {
    std::string workload, says;
  };
  const std::string broken_robot =
      source("configs/topologies/pair.toml");  // a TOML file, not a robot
  for (const Case& c :
       {Case{"robot = \"missing.toml\"\n", "no such robot file"},
        Case{"robot = \"" + broken_robot + "\"\n", "in the robot file"},
        Case{"schedule = \"explicit\"\n", "needs workload.allocation"},
        Case{"q = [0, 0, 0, 0, 0, 0]\n", "outside the joint limits"}, Case{"", ""}}) {
    const std::string path = scene_file(farm(c.workload));
    const auto check = cli_test::run("check " + path + " 2>&1");
    const auto run = cli_test::run("run " + path + " 2>&1");
    if (c.says.empty()) {
      EXPECT_EQ(check.exit_code, 0) << check.out;
      EXPECT_EQ(run.exit_code, 0) << run.out;
      continue;
    }
    EXPECT_EQ(check.exit_code, 2) << check.out;
    EXPECT_EQ(run.exit_code, 2) << run.out;
    EXPECT_NE(check.out.find(c.says), std::string::npos) << check.out;
    EXPECT_NE(run.out.find(c.says), std::string::npos) << run.out;
  }
}

// Found by fuzzing (fuzz/corpus/config/crash-paper-data-count-beyond-int): a count in the paper's
// data was converted to int whatever its value (undefined beyond int's range); table 5's rows took
// any non-number as 0.
TEST(PaperData, CountsAndPercentagesMustBeWhatTheySay) {
  const std::string base =
      "[table4]\nworkers = [1]\ntp_ms = [2.0]\n[table6]\nm = [1]\ntp_ms = [1.0]\n";
  struct Case {
    std::string text, says;
    int line, column;
  };
  for (const Case& c :
       {Case{"[table5]\nworkers = [3e16]\nutilisation_pct = [[1]]\n", "whole number", 2, 12},
        Case{"[table5]\nworkers = [1.5]\nutilisation_pct = [[1]]\n", "whole number", 2, 12},
        Case{"[table5]\nworkers = [1]\nutilisation_pct = [[\"x\"]]\n", "expected a number", 3, 21},
        Case{"[table5]\nworkers = [1]\nutilisation_pct = [7]\n", "an array of numbers per row", 3,
             20},
        Case{"[table5]\nworkers = [1]\nutilisation_pct = [[nan]]\n", "finite", 3, 21}}) {
    const std::string path = scene_file(c.text + base);
    try {
      tools::load_paper_tables(path);
      ADD_FAILURE() << c.text << " accepted";
    } catch (const network::ConfigError& e) {
      EXPECT_TRUE(at(e, path, c.line, c.column, c.says)) << c.text;
    }
  }
}

}  // namespace

namespace {

// A short trajectory whose robot is the shipped one; `workload` adds keys.
std::string trajectory(const std::string& workload) {
  return "[network]\ntopology = \"" + source("configs/topologies/trajectory-9-m3.toml") +
         "\"\n[workload]\nkind = \"trajectory\"\nsteps = 1\nrobot = \"" +
         source("configs/robots/stanford.toml") + "\"\n" + workload;
}

bool names(const network::ConfigError& e, const std::string& path, int line,
           const std::string& part) {
  return e.where().file == path && e.where().line == line &&
         std::string(e.what()).find(part) != std::string::npos;
}

}  // namespace

// Files a workload names are parameter types: an input file is looked for next to the scene and
// must be there before anything runs; an output file must be writable before anything runs.
TEST(ParameterTypes, AnInputFileIsRelativeToTheSceneAndMustExist) {
  const std::string path = scene_file(trajectory("torque = \"csv\"\ntorque_csv = \"here.csv\"\n"));
  fs::remove(fs::path(path).parent_path() / "here.csv");  // from an earlier run of this test
  EXPECT_TRUE(names(error_of(path), path, 8, "no such file"));
  // The same name, once the file is next to the scene, is found whatever the working directory.
  fs::copy_file(source("configs/scenes/trajectory-torque.csv"),
                fs::path(path).parent_path() / "here.csv", fs::copy_options::overwrite_existing);
  const auto check = cli_test::run("check " + path + " 2>&1");
  EXPECT_EQ(check.exit_code, 0) << check.out;
}

TEST(ParameterTypes, AnOutputFileIsCheckedBeforeTheRun) {
  const std::string path = scene_file(trajectory("output_csv = \"no/such/dir/out.csv\"\n"));
  EXPECT_TRUE(names(error_of(path), path, 7, "output_csv"));
}

TEST(ParameterTypes, APrecisionIsOneOfTheTwoAndSetsTheMachine) {
  const std::string path = scene_file(trajectory("precision = \"real16\"\n"));
  try {
    tools::load_scene(path);
    FAIL() << "accepted";
  } catch (const network::ConfigError& e) {
    EXPECT_TRUE(names(e, path, 7, "choose one of real32, real64")) << e.what();
  }
  const auto chosen = tools::inputs_from(tools::load_scene(path, {"workload.precision=real64"}));
  EXPECT_EQ(chosen.options.precision, t800::Precision::real64);
  EXPECT_EQ(chosen.precision_source, "workload.precision");
  const auto fallback = tools::inputs_from(tools::load_scene(scene_file(trajectory(""))));
  EXPECT_EQ(fallback.options.precision, t800::Precision::real32);  // the trajectory's default
  EXPECT_NE(fallback.precision_source.find("default of workload trajectory"), std::string::npos);
}
