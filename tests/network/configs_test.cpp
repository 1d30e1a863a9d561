// Every shipped configuration loads, and the examples in the format documentation are valid.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "network/topology_file.hpp"
#include "test_util.hpp"
#include "tools/scene.hpp"

namespace {

namespace fs = std::filesystem;

std::vector<std::string> toml_files(const std::string& folder) {
  std::vector<std::string> files;
  const fs::path dir = fs::path(nettest::source_dir()) / "configs" / folder;
  if (!fs::is_directory(dir)) return files;
  for (const auto& entry : fs::directory_iterator(dir))
    if (entry.is_regular_file() && entry.path().extension() == ".toml")
      files.push_back(entry.path().string());
  std::sort(files.begin(), files.end());
  return files;
}

// The ```toml blocks of a README: each is a complete file, so documentation cannot drift.
std::vector<std::string> toml_blocks(const std::string& readme) {
  std::ifstream in(fs::path(nettest::source_dir()) / readme);
  std::vector<std::string> blocks;
  std::string line, block;
  bool inside = false;
  while (std::getline(in, line)) {
    if (!inside && line == "```toml") {
      inside = true;
      block.clear();
    } else if (inside && line == "```") {
      inside = false;
      blocks.push_back(block);
    } else if (inside) {
      block += line + "\n";
    }
  }
  return blocks;
}

TEST(NetworkConfigs, EveryTopologyLoads) {
  const std::vector<std::string> files = toml_files("topologies");
  EXPECT_GE(files.size(), 10u);
  for (const std::string& file : files) {
    SCOPED_TRACE(file);
    EXPECT_NO_THROW({
      const network::Topology t = network::load_topology(file);
      EXPECT_EQ(t.name, fs::path(file).stem().string());  // names match file names
      EXPECT_FALSE(t.description.empty());
    });
    EXPECT_NO_THROW(tools::check_file(file));
  }
}

TEST(NetworkConfigs, EverySceneLoads) {
  const std::vector<std::string> files = toml_files("scenes");
  if (files.empty()) GTEST_SKIP() << "configs/scenes has no .toml files yet";
  for (const std::string& file : files) {
    SCOPED_TRACE(file);
    EXPECT_NO_THROW(tools::load_scene(file));
    EXPECT_NO_THROW(tools::check_file(file));
  }
}

TEST(NetworkConfigs, PaperTree9SaysItIsReconstructed) {
  const network::Topology t =
      network::load_topology(nettest::source_dir() + "/configs/topologies/tree-9.toml");
  EXPECT_NE(t.description.find("Fig. 5"), std::string::npos);
  EXPECT_NE(t.description.find("reconstructed"), std::string::npos);
}

TEST(NetworkConfigs, TopologyReadmeExamplesAreValid) {
  const std::vector<std::string> blocks = toml_blocks("configs/topologies/README.md");
  ASSERT_FALSE(blocks.empty());
  for (std::size_t i = 0; i < blocks.size(); ++i) {
    const std::string path =
        nettest::write_file("example" + std::to_string(i) + ".toml", blocks[i]);
    EXPECT_NO_THROW(network::load_topology(path)) << blocks[i];
  }
}

TEST(NetworkConfigs, SceneReadmeExamplesAreValid) {
  const std::vector<std::string> blocks = toml_blocks("configs/scenes/README.md");
  ASSERT_FALSE(blocks.empty());
  // Scenes name topologies as ../topologies/x.toml: give them that neighbourhood.
  const fs::path root = nettest::scratch_dir();
  fs::create_directories(root / "topologies");
  for (const std::string& file : toml_files("topologies"))
    fs::copy_file(file, root / "topologies" / fs::path(file).filename(),
                  fs::copy_options::overwrite_existing);
  for (std::size_t i = 0; i < blocks.size(); ++i) {
    const std::string path =
        nettest::write_file("scenes/example" + std::to_string(i) + ".toml", blocks[i]);
    EXPECT_NO_THROW(tools::load_scene(path)) << blocks[i];
  }
}

}  // namespace
