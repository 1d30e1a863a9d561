// A scene in a fresh temporary directory that names a plugin, for the plugin tests: the plugin file
// `variant` of the test tree (built from tests/sdk/plugins/) is copied to DIR/plugins/ first, if
// given; `plugin` (relative to the scene) is on the scene's line 6, then the workload's other keys.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include "tests/test_paths.hpp"

namespace plugin_test {

namespace fs = std::filesystem;

constexpr int kPluginLine = 6;

struct PluginScene {
  fs::path dir, file;
  PluginScene(const std::string& variant, const std::string& plugin,
              const std::string& workload = "kind = \"tiny_busy\"\ncycles = 2000\n",
              const std::string& topology = "single") {
    dir = fs::temp_directory_path() /
          ("t800sim-plugin-test-" + std::to_string(getpid()) + "-" +
           ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir);
    fs::create_directories(dir / "plugins");
    if (!variant.empty())
      fs::copy_file(fs::path(test_paths::plugin_dir()) / (variant + ".so"),
                    dir / "plugins" / (variant + ".so"));
    file = dir / "scene.toml";
    std::ofstream(file) << std::string(
                               "[network]\n"
                               "topology = \"") +
                               test_paths::source_dir() + "/configs/topologies/"
                        << topology
                        << ".toml\"\n"
                           "processor = \"T800-20\"\n"
                           "\n"
                           "[workload]\n"
                           "plugin = \""
                        << plugin << "\"\n"
                        << workload;
  }
  ~PluginScene() { fs::remove_all(dir); }
  // "DIR/scene.toml:6:", where a message about the plugin begins.
  std::string plugin_line() const {
    return file.string() + ":" + std::to_string(kPluginLine) + ":";
  }
};

}  // namespace plugin_test
