// Plugins named by a scene (workload.plugin): `run`, `check` and `sweep` load them before the
// workload's kind is looked up; a missing file, a library that is not a plugin and one built
// against another SDK version are errors at the scene's line that names them, exit 2, nothing run.
// The plugins are built in the test tree from tests/sdk/plugins/tiny_plugin.cpp.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "../cli/cli_fixtures.hpp"
#include "plugin_scene.hpp"

namespace {

namespace fs = std::filesystem;
using plugin_test::PluginScene;

TEST(SdkPlugin, RunLoadsThePluginRelativeToTheSceneAndRunsItsKind) {
  const PluginScene scene("tiny", "plugins/tiny.so");
  const auto o = cli_test::run("run " + scene.file.string() + " --json");  // stdout only: the JSON
  ASSERT_EQ(o.exit_code, 0) << o.out;
  const auto report = nlohmann::json::parse(o.out);
  EXPECT_EQ(report["workload"]["kind"], "tiny_busy");
  // 2000 cycles of a 20 MHz T800 (50 ns each): 100 us.
  EXPECT_NEAR(report["workload"]["end_us"].get<double>(), 2000 * 0.050, 1e-9);
}

TEST(SdkPlugin, CheckAndSweepLoadThePluginToo) {
  const PluginScene scene("tiny", "plugins/tiny.so");
  const auto checked = cli_test::run("check " + scene.file.string() + " 2>&1");
  EXPECT_EQ(checked.exit_code, 0) << checked.out;
  EXPECT_NE(checked.out.find("tiny_busy"), std::string::npos) << checked.out;
  const fs::path csv = scene.dir / "sweep.csv";
  const auto swept =
      cli_test::run("sweep " + scene.file.string() + " --vary workload.cycles=1000,4000 -j 1 -o " +
                    csv.string() + " 2>&1");
  ASSERT_EQ(swept.exit_code, 0) << swept.out;
  std::ifstream in(csv);
  int lines = 0;
  for (std::string line; std::getline(in, line);) ++lines;
  EXPECT_EQ(lines, 3);  // a header and a row per point
}

// Each bad plugin: exit 2, the scene's file and line 6 and the plugin's path in the message, and no
// report (nothing ran).
void expect_refused(const PluginScene& scene, const std::string& plugin_path,
                    const std::string& why) {
  const auto o = cli_test::run("run " + scene.file.string() + " --json 2>&1");
  EXPECT_EQ(o.exit_code, 2) << o.out;
  EXPECT_NE(o.out.find(scene.plugin_line()), std::string::npos) << o.out;
  EXPECT_NE(o.out.find(plugin_path), std::string::npos) << o.out;
  EXPECT_NE(o.out.find(why), std::string::npos) << o.out;
  EXPECT_EQ(o.out.find("simulated_us"), std::string::npos) << o.out;
}

TEST(SdkPlugin, AMissingPluginIsAnErrorAtItsLine) {
  const PluginScene scene("", "plugins/absent.so");
  expect_refused(scene, "plugins/absent.so", "not found");
}

TEST(SdkPlugin, ALibraryWithoutT800simPluginIsRefused) {
  const PluginScene scene("tiny_not_a_plugin", "plugins/tiny_not_a_plugin.so");
  expect_refused(scene, "plugins/tiny_not_a_plugin.so", "is not a t800sim plugin");
}

TEST(SdkPlugin, AFileThatIsNoLibraryIsRefused) {
  const PluginScene scene("", "plugins/text.so");
  std::ofstream(scene.dir / "plugins" / "text.so") << "not a shared library\n";
  expect_refused(scene, "plugins/text.so", "is not a t800sim plugin");
}

TEST(SdkPlugin, APluginOfAnotherSdkVersionIsRefused) {
  const PluginScene scene("tiny_other_version", "plugins/tiny_other_version.so");
  expect_refused(scene, "plugins/tiny_other_version.so", "built against t800sim SDK 0.0-other");
}

TEST(SdkPlugin, AnEmptyPluginPathIsAnErrorAtItsLine) {
  const PluginScene scene("", "");
  expect_refused(scene, "workload.plugin", "is empty");
}

TEST(SdkPlugin, APluginRegisteringAKindThatExistsIsRefused) {
  const PluginScene scene("tiny_clash", "plugins/tiny_clash.so");
  expect_refused(scene, "plugins/tiny_clash.so", "workload kind pingpong is registered twice");
}

}  // namespace
