// Whatever the input, the loaders answer with a ConfigError: never a crash, never another
// exception.
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <random>

#include "network/topology_file.hpp"
#include "test_util.hpp"
#include "tests/test_files.hpp"
#include "tools/scene.hpp"

namespace {

using nettest::write_file;

// Each loader must either succeed or throw ConfigError; anything else fails the test.
void expect_clean(const std::string& path, bool may_succeed) {
  const std::function<void()> loaders[] = {[&] { network::load_topology(path); },
                                           [&] { tools::load_scene(path); },
                                           [&] { tools::check_file(path); }};
  for (const auto& load : loaders) {
    try {
      load();
      EXPECT_TRUE(may_succeed) << path << " loaded";
    } catch (const network::ConfigError& e) {
      EXPECT_EQ(e.where().file.empty(), false) << e.what();
    } catch (const std::exception& e) {
      ADD_FAILURE() << path << ": not a ConfigError: " << e.what();
    }
  }
}

using test_files::read_file;

TEST(NetworkGarbage, RandomBytes) {
  std::mt19937 rng(800);
  for (int round = 0; round < 200; ++round) {
    std::string bytes(rng() % 600, '\0');
    for (char& c : bytes) c = static_cast<char>(rng() % 256);
    expect_clean(write_file("random.toml", bytes), false);
  }
}

TEST(NetworkGarbage, RandomPrintableText) {
  // Closer to TOML than random bytes, so the parser gets further before giving up.
  const std::string alphabet = "ab.=[]{}\"', \n#0123456789-+eP_linkhost";
  std::mt19937 rng(20);
  for (int round = 0; round < 300; ++round) {
    std::string text(rng() % 200, ' ');
    for (char& c : text) c = alphabet[rng() % alphabet.size()];
    expect_clean(write_file("printable.toml", text), true);
  }
}

TEST(NetworkGarbage, EveryTruncationOfValidFiles) {
  for (const char* name : {"tree-3.toml", "mesh-3x3.toml"}) {
    const std::string text = read_file(nettest::source_dir() + "/configs/topologies/" + name);
    ASSERT_FALSE(text.empty());
    for (std::size_t n = 0; n <= text.size(); n += 3)
      expect_clean(write_file("cut.toml", text.substr(0, n)), true);
  }
}

TEST(NetworkGarbage, MutatedScene) {
  const std::string scene =
      "name = \"m\"\n[network]\nfamily = \"tree\"\nworkers = 3\nlink_speed_mbps = 10\n"
      "[workload]\nkind = \"link-stream\"\nbytes = 100\ndirection = \"both\"\nfrom = \"P1\"\n";
  std::mt19937 rng(3);
  for (int round = 0; round < 400; ++round) {
    std::string text = scene;
    for (int k = 0; k < 3; ++k) text[rng() % text.size()] = static_cast<char>(rng() % 128);
    expect_clean(write_file("mutated.toml", text), true);
  }
}

TEST(NetworkGarbage, ExtremeValues) {
  const char* const texts[] = {
      "[[processor]]\nname = \"P0\"\nmemory = { wait_states = 9223372036854775807 }\n",
      "host = \"P0.link99999999999999999999\"\n[[processor]]\nname = \"P0\"\n",
      "[network]\nfamily = \"chain\"\nworkers = -9223372036854775808\n[workload]\nkind = "
      "\"pingpong\"\n",
      "[network]\nfamily = \"chain\"\nworkers = 2\nlink_speed_mbps = nan\n[workload]\nkind = "
      "\"pingpong\"\n",
      "[network]\nfamily = \"chain\"\nworkers = 2\nlink_speed_mbps = 1e308\n[workload]\nkind = "
      "\"pingpong\"\n",
      "[network]\nfamily = \"chain\"\nworkers = 2\nlink_speed_mbps = 9007199254740993\n[workload]\n"
      "kind = \"pingpong\"\n",
      "[network]\nfamily = \"chain\"\nworkers = 2\n[workload]\nkind = \"pingpong\"\nbytes = -inf\n",
      "[workload]\nkind = \"\"\n",
      "x = "
      "[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[["
      "[[[[[["
      "[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[["
      "[[[[[[[[["
      "[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[["
      "[[[[[[[[[\n",
      "\xef\xbb\xbfname = \"bom\"\n",
      "name = \"\xff\xfe\"\n",
  };
  for (const char* text : texts) expect_clean(write_file("extreme.toml", text), false);
}

TEST(NetworkGarbage, EmptyFile) {
  const std::string path = write_file("empty.toml", "");
  expect_clean(path, false);
  EXPECT_THROW(network::load_topology(path), network::ConfigError);
}

TEST(NetworkGarbage, DirectoryAndMissingFile) {
  const std::string dir = nettest::scratch_dir().string();
  const std::string missing = dir + "/does-not-exist.toml";
  for (const std::string& path : {dir, missing}) {
    expect_clean(path, false);
    try {
      tools::load_scene(path);
    } catch (const network::ConfigError& e) {
      EXPECT_EQ(e.where().file, path);
      EXPECT_EQ(e.where().line, 0);
    }
  }
}

}  // namespace
