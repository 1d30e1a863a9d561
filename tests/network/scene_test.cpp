// Scene files: network choice, workload parameters, --set overrides, check_file.
#include "tools/scene.hpp"

#include <gtest/gtest.h>

#include "test_util.hpp"
#include "workloads/registry.hpp"

namespace {

using nettest::fails_at;
using nettest::write_file;
using tools::load_scene;

std::string pair_path() {
  return nettest::source_dir() + "/configs/topologies/pair.toml";
}

// A pingpong scene over the pair topology; [workload] starts on line 6.
std::string pingpong(const std::string& workload_extra = "") {
  return "name = \"pp\"\n[network]\ntopology = \"" + pair_path() +
         "\"\nlink_speed_mbps = 20\n\n[workload]\nkind = \"pingpong\"\n" + workload_extra;
}

::testing::AssertionResult bad_scene(const std::string& text, int line, int column,
                                     std::initializer_list<std::string> parts,
                                     const std::vector<std::string>& overrides = {}) {
  const std::string path = write_file("bad.toml", text);
  return fails_at([&] { load_scene(path, overrides); }, path, line, column, parts);
}

// An override's errors point at the flag, not the file.
::testing::AssertionResult bad_override(const std::string& text, const std::string& flag,
                                        std::initializer_list<std::string> parts) {
  const std::string path = write_file("scene.toml", text);
  return fails_at([&] { load_scene(path, {flag}); }, "--set " + flag, 0, 0, parts);
}

TEST(Scene, LoadsATopologyFileSceneWithDefaults) {
  const std::string path = write_file("s.toml", pingpong("bytes = 128\n"));
  const tools::Scene s = load_scene(path);
  EXPECT_EQ(s.file, path);
  EXPECT_EQ(s.name, "pp");
  EXPECT_EQ(s.topology.name, "pair");
  EXPECT_EQ(s.topology.processors.size(), 2u);
  EXPECT_EQ(s.link.speed_mbps, 20.0);
  EXPECT_EQ(s.link.protocol, t800::LinkProtocol::overlapped);
  EXPECT_EQ(s.workload_kind, "pingpong");
  EXPECT_EQ(s.workload.integer("bytes"), 128);
  EXPECT_EQ(s.workload.integer("iterations"), 100);  // the declared default
  EXPECT_EQ(s.workload.text("from"), "");
  EXPECT_EQ(s.workload.values().size(), 4u);
}

TEST(Scene, TopologyPathIsRelativeToTheSceneFile) {
  write_file("nets/two.toml",
             "host = \"A.link0\"\n[[processor]]\nname = \"A\"\n[[processor]]\n"
             "name = \"B\"\n[[link]]\nfrom = \"A.link1\"\nto = \"B.link0\"\n");
  const std::string path =
      write_file("scenes/s.toml",
                 "[network]\ntopology = \"../nets/two.toml\"\n"
                 "link_speed_mbps = 10\nlink_protocol = \"t414\"\n"
                 "[workload]\nkind = \"pingpong\"\nfrom = \"B\"\nto = \"A\"\n");
  const tools::Scene s = load_scene(path);
  EXPECT_EQ(s.name, "s");  // defaults to the file's stem
  EXPECT_EQ(s.topology.name, "two");
  EXPECT_EQ(s.link.speed_mbps, 10.0);
  EXPECT_EQ(s.link.protocol, t800::LinkProtocol::t414);
  EXPECT_EQ(s.workload.text("from"), "B");
}

TEST(Scene, GeneratedFamily) {
  const std::string path =
      write_file("s.toml",
                 "[network]\nfamily = \"tree\"\nworkers = 6\n"
                 "processor = \"T800-25\"\n[workload]\nkind = \"link-stream\"\n"
                 "direction = \"both\"\n");
  const tools::Scene s = load_scene(path);
  EXPECT_EQ(s.topology.processors.size(), 7u);
  EXPECT_EQ(s.topology.processors[6].config.type, t800::ProcessorType::T800_25);
  EXPECT_EQ(s.workload.text("direction"), "both");
  EXPECT_EQ(s.workload.integer("messages"), 64);
}

TEST(Scene, InlineTopology) {
  const std::string path = write_file("s.toml",
                                      "name = \"inline\"\n[topology]\nhost = \"X.link0\"\n"
                                      "[[topology.processor]]\nname = \"X\"\n"
                                      "[workload]\nkind = \"pingpong\"\n");
  const tools::Scene s = load_scene(path);
  EXPECT_EQ(s.topology.processors.size(), 1u);
  EXPECT_EQ(s.topology.source, path);
}

TEST(Scene, InlineTopologyErrorsPointIntoTheScene) {
  EXPECT_TRUE(
      bad_scene("[topology]\nhost = \"X.link0\"\n[[topology.processor]]\nname = \"X\"\n"
                "[[topology.link]]\nfrom = \"X.link1\"\nto = \"Y.link0\"\n"
                "[workload]\nkind = \"pingpong\"\n",
                7, 6, {"unknown processor 'Y'"}));
}

TEST(Scene, ErrorsInTheTopologyFileNameThatFile) {
  const std::string topo = write_file("net.toml", "host = \"P0.link0\"\n[[processor]]\nname = 3\n");
  EXPECT_TRUE(fails_at(
      [&] {
        load_scene(write_file("s.toml",
                              "[network]\ntopology = \"net.toml\"\n"
                              "[workload]\nkind = \"pingpong\"\n"));
      },
      topo, 3, 8, {"expected a string, got integer"}));
}

TEST(Scene, NetworkMustBeGivenExactlyOnce) {
  EXPECT_TRUE(bad_scene("[network]\nlink_speed_mbps = 10\n[workload]\nkind = \"pingpong\"\n", 1, 1,
                        {"no network given", "network.topology", "network.family", "[topology]"}));
  EXPECT_TRUE(bad_scene("[workload]\nkind = \"pingpong\"\n", 1, 1, {"no network given"}));
  EXPECT_TRUE(bad_scene("[network]\ntopology = \"" + pair_path() +
                            "\"\nfamily = \"tree\"\nworkers = 3\n[workload]\nkind = \"pingpong\"\n",
                        3, 10, {"give only one of", "both network.topology and network.family"}));
  EXPECT_TRUE(
      bad_scene("[network]\nfamily = \"tree\"\nworkers = 3\n[topology]\nhost = \"P0.link0\"\n"
                "[workload]\nkind = \"pingpong\"\n",
                4, 1, {"both network.family and [topology]"}));
}

TEST(Scene, InlineTopologyMustBeATable) {
  EXPECT_TRUE(bad_scene("topology = \"pair.toml\"\n[workload]\nkind = \"pingpong\"\n", 1, 12,
                        {"expected a table, got string", "use network.topology"}));
}

TEST(Scene, FamilyKeysNeedAFamily) {
  EXPECT_TRUE(bad_scene("[network]\ntopology = \"" + pair_path() +
                            "\"\nworkers = 3\n[workload]\nkind = \"pingpong\"\n",
                        3, 11, {"network.workers applies only to a generated network"}));
}

// network.processor and network.memory set every processor of a topology file too.
TEST(Scene, ProcessorKeysOverrideATopologyFile) {
  const std::string path =
      write_file("override.toml", "[network]\ntopology = \"" + pair_path() +
                                      "\"\nprocessor = \"T805-30\"\nmemory = \"external\"\n"
                                      "wait_states = 2\n[workload]\nkind = \"pingpong\"\n");
  const tools::Scene s = tools::load_scene(path);
  for (const auto& p : s.topology.processors) {
    EXPECT_EQ(p.config.type, t800::ProcessorType::T805_30);
    EXPECT_EQ(p.config.memory.code, t800::Placement::external);
    EXPECT_EQ(p.config.memory.data, t800::Placement::external);
    EXPECT_EQ(p.config.memory.wait_states, 2);
  }
}

TEST(Scene, FamilyErrors) {
  EXPECT_TRUE(
      bad_scene("[network]\nfamily = \"torus\"\nworkers = 3\n[workload]\nkind = \"pingpong\"\n", 2,
                10, {"unknown network family 'torus'", "tree, chain, ring, mesh, hypercube"}));
  EXPECT_TRUE(bad_scene("[network]\nfamily = \"tree\"\n[workload]\nkind = \"pingpong\"\n", 2, 10,
                        {"needs network.workers"}));
  EXPECT_TRUE(
      bad_scene("[network]\nfamily = \"tree\"\nworkers = 2.0\n[workload]\nkind = \"pingpong\"\n", 3,
                11, {"expected an integer, got floating-point number"}));
  EXPECT_TRUE(
      bad_scene("[network]\nfamily = \"hypercube\"\nworkers = 5\n[workload]\n"
                "kind = \"pingpong\"\n",
                3, 11, {"hypercube of 5 workers is not possible", "1, 3, 7, 15"}));
  EXPECT_TRUE(
      bad_scene("[network]\nfamily = \"chain\"\nworkers = 99999999999\n[workload]\n"
                "kind = \"pingpong\"\n",
                3, 11, {"out of range"}));
  EXPECT_TRUE(
      bad_scene("[network]\nfamily = \"chain\"\nworkers = 2\nprocessor = \"T9000\"\n"
                "[workload]\nkind = \"pingpong\"\n",
                4, 13, {"unknown processor type 'T9000'", "T800-20, T800-25, T800-30"}));
}

TEST(Scene, TopologyFileNotFound) {
  EXPECT_TRUE(bad_scene("[network]\ntopology = \"missing.toml\"\n[workload]\nkind = \"pingpong\"\n",
                        2, 12, {"topology file 'missing.toml' not found", "looked for"}));
}

TEST(Scene, LinkSettings) {
  std::string text = pingpong();
  text.replace(text.find("= 20"), 4, "= 15");
  EXPECT_TRUE(bad_scene(text, 4, 19, {"link speed 15 Mbit/s is not supported", "5, 10 or 20"}));
  text = pingpong();
  text.replace(text.find("= 20"), 4, "= \"20\"");
  EXPECT_TRUE(bad_scene(text, 4, 19, {"expected a number, got string"}));
  text = pingpong();
  text.replace(text.find("link_speed_mbps = 20"), 20, "link_protocol = \"fast\"");
  EXPECT_TRUE(bad_scene(text, 4, 17, {"unknown link protocol 'fast'", "overlapped, t414"}));
}

TEST(Scene, UnknownKeysAnywhere) {
  EXPECT_TRUE(bad_scene(
      "nmae = \"x\"\n" + pingpong(), 1, 1,
      {"unknown key 'nmae' in a scene", "name, description, network, topology, workload"}));
  std::string text = pingpong();
  text.replace(text.find("link_speed_mbps"), 15, "speed");
  EXPECT_TRUE(bad_scene(text, 4, 1, {"unknown key 'speed' in [network]", "link_speed_mbps"}));
  EXPECT_TRUE(bad_scene(
      pingpong("byte = 3\n"), 8, 1,
      {"unknown key 'byte' in [workload] of kind pingpong", "kind, bytes, iterations, from, to"}));
}

TEST(Scene, WorkloadKind) {
  EXPECT_TRUE(bad_scene("[network]\nfamily = \"chain\"\nworkers = 1\n", 1, 1,
                        {"no [workload] table", "link-stream, livermore7, pingpong"}));
  EXPECT_TRUE(bad_scene("[network]\nfamily = \"chain\"\nworkers = 1\n[workload]\nbytes = 3\n", 4, 1,
                        {"[workload] has no kind"}));
  std::string text = pingpong();
  text.replace(text.find("\"pingpong\""), 10, "\"pong\"");
  EXPECT_TRUE(
      bad_scene(text, 7, 8, {"unknown workload kind 'pong'", "link-stream, livermore7, pingpong"}));
  EXPECT_TRUE(bad_scene("workload = 5\n[network]\nfamily = \"chain\"\nworkers = 1\n", 1, 12,
                        {"'workload': expected a table, got integer"}));
}

TEST(Scene, ParameterTypes) {
  EXPECT_TRUE(bad_scene(pingpong("bytes = 6.5\n"), 8, 9,
                        {"'workload.bytes': expected an integer, got floating-point number"}));
  EXPECT_TRUE(bad_scene(pingpong("bytes = \"64\"\n"), 8, 9, {"expected an integer, got string"}));
  EXPECT_TRUE(bad_scene(pingpong("from = 1\n"), 8, 8, {"expected a processor name, got integer"}));
}

TEST(Scene, ParameterRangesAndChoices) {
  EXPECT_TRUE(bad_scene(pingpong("bytes = 0\n"), 8, 9,
                        {"workload.bytes = 0 is outside the valid range 1 to 10000000"}));
  EXPECT_TRUE(bad_scene(pingpong("iterations = 20000000\n"), 8, 14, {"outside the valid range"}));
  std::string text = pingpong();
  text.replace(text.find("\"pingpong\""), 10, "\"link-stream\"");
  EXPECT_TRUE(bad_scene(text + "direction = \"sideways\"\n", 8, 13,
                        {"workload.direction = \"sideways\" is not valid", "one, both"}));
}

TEST(Scene, ProcessorNamesMustExist) {
  EXPECT_TRUE(
      bad_scene(pingpong("to = \"P9\"\n"), 8, 6, {"no processor 'P9'", "processors are P0, P1"}));
  EXPECT_NO_THROW(load_scene(write_file("ok.toml", pingpong("from = \"P1\"\nto = \"\"\n"))));
}

// The catalog may or may not declare real parameters; when it does, an integer is a valid real.
TEST(Scene, IntegerAcceptedForReal) {
  for (const workloads::WorkloadInfo& w : workloads::workload_catalog()) {
    for (const workloads::ParamSpec& p : w.params) {
      if (p.type != workloads::ParamType::real) continue;
      const auto value = static_cast<long long>(p.min ? *p.min : (p.max ? *p.max : 1.0));
      const std::string path = write_file(
          "real.toml", "[network]\nfamily = \"chain\"\nworkers = 3\n[workload]\nkind = \"" +
                           w.kind + "\"\n" + p.name + " = " + std::to_string(value) + "\n");
      const tools::Scene s = load_scene(path);
      EXPECT_EQ(s.workload.real(p.name), static_cast<double>(value)) << w.kind << "." << p.name;
      return;
    }
  }
  GTEST_SKIP() << "no workload declares a real parameter yet";
}

TEST(SceneOverrides, Applied) {
  const std::string path = write_file("s.toml", pingpong());
  const tools::Scene s =
      load_scene(path, {"workload.bytes=4000", "network.link_speed_mbps=10", "workload.from=P1",
                        "workload.to = \"P0\"", "name=renamed"});
  EXPECT_EQ(s.workload.integer("bytes"), 4000);
  EXPECT_EQ(s.link.speed_mbps, 10.0);
  EXPECT_EQ(s.workload.text("from"), "P1");  // not TOML: taken as a bare string
  EXPECT_EQ(s.workload.text("to"), "P0");
  EXPECT_EQ(s.name, "renamed");
}

TEST(SceneOverrides, ChangeTheGeneratedNetwork) {
  const std::string path = write_file("s.toml",
                                      "[network]\nfamily = \"tree\"\nworkers = 3\n"
                                      "[workload]\nkind = \"pingpong\"\n");
  EXPECT_EQ(load_scene(path, {"network.workers=6"}).topology.processors.size(), 7u);
  EXPECT_EQ(load_scene(path, {"network.family=ring"}).topology.connections.size(), 4u);
}

TEST(SceneOverrides, CreateMissingTables) {
  const std::string path = write_file("s.toml",
                                      "[topology]\nhost = \"X.link0\"\n"
                                      "[[topology.processor]]\nname = \"X\"\n");
  const tools::Scene s =
      load_scene(path, {"network.link_protocol=t414", "workload.kind=link-stream"});
  EXPECT_EQ(s.link.protocol, t800::LinkProtocol::t414);
  EXPECT_EQ(s.workload_kind, "link-stream");
}

TEST(SceneOverrides, SwitchTheTopologyFile) {
  const std::string path = write_file("s.toml", pingpong());
  const std::string tree = nettest::source_dir() + "/configs/topologies/tree-3.toml";
  EXPECT_EQ(load_scene(path, {"network.topology=" + tree}).topology.processors.size(), 4u);
}

TEST(SceneOverrides, Malformed) {
  const std::string path = write_file("s.toml", pingpong());
  for (const char* flag : {"workload.bytes", "=5", "workload..bytes=5", ".bytes=1", "a b=1"})
    EXPECT_TRUE(fails_at([&] { load_scene(path, {flag}); }, "--set " + std::string(flag), 0, 0,
                         {"malformed override"}))
        << flag;
}

TEST(SceneOverrides, ValueErrorsNameTheFlag) {
  EXPECT_TRUE(bad_override(pingpong(), "workload.bytes=0", {"workload.bytes = 0 is outside"}));
  EXPECT_TRUE(bad_override(pingpong(), "workload.bytes=1.5", {"expected an integer"}));
  EXPECT_TRUE(bad_override(pingpong(), "workload.to=P7", {"no processor 'P7'"}));
  EXPECT_TRUE(bad_override(pingpong(), "network.link_speed_mbps=12", {"12 Mbit/s"}));
  EXPECT_TRUE(bad_override(pingpong(), "workload.byts=3", {"unknown key 'byts'"}));
  EXPECT_TRUE(bad_override(pingpong(), "network.workers=3", {"network.workers applies only"}));
  EXPECT_TRUE(bad_override(pingpong("bytes = 3\n"), "workload.bytes.x=1",
                           {"cannot set 'workload.bytes.x'", "is an integer, not a table"}));
  EXPECT_TRUE(bad_override(pingpong(), "network.topology=nowhere.toml", {"not found"}));
  // The what() text starts with the flag, as a file would.
  try {
    load_scene(write_file("s.toml", pingpong()), {"workload.bytes=0"});
    FAIL() << "no error";
  } catch (const network::ConfigError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("--set workload.bytes=0: error: ", 0), 0u) << e.what();
  }
}

TEST(SceneOverrides, FileErrorsStillNameTheFile) {
  // An override elsewhere does not move errors that are the file's.
  EXPECT_TRUE(bad_scene(pingpong("bytes = 0\n"), 8, 9, {"outside"}, {"workload.iterations=5"}));
}

TEST(SceneCheckFile, SummarisesScenesAndTopologies) {
  EXPECT_EQ(tools::check_file(nettest::source_dir() + "/configs/topologies/tree-3.toml"),
            "topology tree-3: 4 processors, 3 links, host P0.link0");
  EXPECT_EQ(tools::check_file(write_file("pingpong.toml", pingpong())),
            "scene pp: 2 processors, 1 link, workload pingpong");
}

TEST(SceneCheckFile, ReportsErrors) {
  const std::string path = write_file("bad.toml", pingpong("bytes = -1\n"));
  EXPECT_TRUE(fails_at([&] { tools::check_file(path); }, path, 8, 9, {"outside"}));
  const std::string topo = write_file("t.toml", "host = \"P0.link0\"\n");
  EXPECT_TRUE(fails_at([&] { tools::check_file(topo); }, topo, 1, 1, {"no processors"}));
}

}  // namespace
