// Topology files: every error names file:line:column and says what would be valid.
#include "network/topology_file.hpp"

#include <gtest/gtest.h>

#include <toml++/toml.h>

#include "test_util.hpp"

namespace {

using nettest::fails_at;
using nettest::write_file;
using network::load_topology;

// Two processors and one link, line by line; tests splice in one mistake.
const char* const kHead = R"(name = "t"
host = "P0.link0"

[[processor]]
name = "P0"

[[processor]]
name = "P1"
)";

std::string with_link(const std::string& from, const std::string& to,
                      const std::string& extra = "") {
  // [[link]] is on line 10, from on 11, to on 12, extra on 13.
  return std::string(kHead) + "\n[[link]]\nfrom = \"" + from + "\"\nto = \"" + to + "\"\n" + extra;
}

// Writes `text` and expects load_topology to fail at line:column with every part in the message.
::testing::AssertionResult bad_file(const std::string& text, int line, int column,
                                    std::initializer_list<std::string> parts) {
  const std::string path = write_file("bad.toml", text);
  return fails_at([&] { load_topology(path); }, path, line, column, parts);
}

TEST(TopologyFile, LoadsAFullExample) {
  const std::string path = write_file("ok.toml", R"(name = "demo"
description = "two processors"
host = "P0.link0"
[[processor]]
name = "P0"
type = "T800-25"
memory = { data = "external", code = "onchip", wait_states = 2 }
[[processor]]
name = "P1"
[[link]]
from = "P0.link2"
to = "P1.link3"
speed_mbps = 10
)");
  const network::Topology t = load_topology(path);
  EXPECT_EQ(t.name, "demo");
  EXPECT_EQ(t.description, "two processors");
  EXPECT_EQ(t.source, path);
  ASSERT_EQ(t.processors.size(), 2u);
  EXPECT_EQ(t.processors[0].config.type, t800::ProcessorType::T800_25);
  EXPECT_EQ(t.processors[0].config.memory.data, t800::Placement::external);
  EXPECT_EQ(t.processors[0].config.memory.code, t800::Placement::on_chip);
  EXPECT_EQ(t.processors[0].config.memory.wait_states, 2);
  EXPECT_EQ(t.processors[1].config.type, t800::ProcessorType::T800_20);  // the default
  EXPECT_EQ(t.processors[1].where.line, 9);
  ASSERT_EQ(t.connections.size(), 1u);
  EXPECT_EQ(t.connections[0].a, (network::LinkEnd{0, 2}));
  EXPECT_EQ(t.connections[0].b, (network::LinkEnd{1, 3}));
  EXPECT_EQ(t.connections[0].speed_mbps, 10.0);
  EXPECT_EQ(t.connections[0].where.line, 10);
  EXPECT_EQ(t.host, (network::LinkEnd{0, 0}));
}

TEST(TopologyFile, NameDefaultsToFileStemAndSpeedToUnset) {
  std::string text = with_link("P0.link1", "P1.link0");
  text.erase(0, text.find('\n') + 1);  // drop name = "t"
  const network::Topology t = load_topology(write_file("my-net.toml", text));
  EXPECT_EQ(t.name, "my-net");
  EXPECT_FALSE(t.connections[0].speed_mbps.has_value());
}

TEST(TopologyFile, ParseTopologyFromATable) {
  const toml::table table = toml::parse(std::string_view(with_link("P0.link1", "P1.link0")),
                                        std::string_view("inline.toml"));
  const network::Topology t = network::parse_topology(table, "inline.toml");
  EXPECT_EQ(t.processors.size(), 2u);
  EXPECT_EQ(t.source, "inline.toml");
}

// Everything validate() checks, reported at the offending item.

TEST(TopologyFile, DuplicateProcessorName) {
  EXPECT_TRUE(bad_file(std::string(kHead) + "\n[[processor]]\nname = \"P1\"\n", 11, 8,
                       {"duplicate processor name 'P1'", ":8:8)"}));
}

TEST(TopologyFile, LinkIndexOutsideRange) {
  EXPECT_TRUE(bad_file(with_link("P0.link1", "P1.link4"), 12, 6,
                       {"link index 4 in 'P1.link4' is outside 0-3", "link0 to link3"}));
}

TEST(TopologyFile, HostLinkIndexOutsideRange) {
  std::string text = kHead;
  text.replace(text.find("P0.link0"), 8, "P0.link9");
  EXPECT_TRUE(bad_file(text, 2, 8, {"link index 9 in 'P0.link9' is outside 0-3"}));
}

TEST(TopologyFile, LinkEndUsedTwice) {
  const std::string text =
      with_link("P0.link1", "P1.link0") + "\n[[link]]\nfrom = \"P0.link2\"\nto = \"P1.link0\"\n";
  EXPECT_TRUE(bad_file(
      text, 14, 1, {"P1.link0 is already connected to P0.link1", ":10:1)", "only one connection"}));
}

TEST(TopologyFile, LinkEndUsedByTheHost) {
  EXPECT_TRUE(bad_file(with_link("P0.link0", "P1.link0"), 10, 1,
                       {"P0.link0 is already connected to the host"}));
}

TEST(TopologyFile, SelfLoop) {
  const std::string text =
      with_link("P0.link1", "P1.link0") + "\n[[link]]\nfrom = \"P1.link1\"\nto = \"P1.link2\"\n";
  EXPECT_TRUE(bad_file(text, 14, 1, {"connects processor 'P1' to itself"}));
}

TEST(TopologyFile, BadLinkSpeed) {
  EXPECT_TRUE(bad_file(with_link("P0.link1", "P1.link0", "speed_mbps = 15\n"), 13, 14,
                       {"link speed 15 Mbit/s is not supported", "5, 10 or 20 Mbit/s"}));
  EXPECT_TRUE(bad_file(with_link("P0.link1", "P1.link0", "speed_mbps = 2.5\n"), 13, 14,
                       {"link speed 2.5 Mbit/s"}));
}

TEST(TopologyFile, UnreachableProcessorsAreNamed) {
  const std::string text = std::string(kHead) + "\n[[processor]]\nname = \"P2\"\n";
  EXPECT_TRUE(bad_file(text, 8, 8, {"processors P1, P2 cannot be reached from the host"}));
}

TEST(TopologyFile, NoHost) {
  std::string text = with_link("P0.link1", "P1.link0");
  text.replace(text.find("host"), 17, "");
  EXPECT_TRUE(bad_file(text, 1, 1, {"no host connection", "host = \"P0.link0\""}));
}

TEST(TopologyFile, NoProcessors) {
  EXPECT_TRUE(
      bad_file("name = \"x\"\nhost = \"P0.link0\"\n", 1, 1, {"no processors", "[[processor]]"}));
  EXPECT_TRUE(bad_file("processor = []\n", 1, 1, {"no processors"}));
}

// Errors only a file can have.

TEST(TopologyFile, UnknownKeysAtEveryLevel) {
  EXPECT_TRUE(bad_file("nmae = \"x\"\n", 1, 1,
                       {"unknown key 'nmae' in a topology",
                        "valid keys are name, description, host, processor, link"}));
  EXPECT_TRUE(
      bad_file(std::string(kHead) + "speed = 3\n", 9, 1,
               {"unknown key 'speed' in [[processor]]", "valid keys are name, type, memory"}));
  EXPECT_TRUE(bad_file(std::string(kHead) + "memory = { data = \"onchip\", fast = true }\n", 9, 29,
                       {"unknown key 'fast' in memory", "data, code, wait_states"}));
  EXPECT_TRUE(bad_file(with_link("P0.link1", "P1.link0", "speed = 10\n"), 13, 1,
                       {"unknown key 'speed' in [[link]]", "from, to, speed_mbps"}));
}

TEST(TopologyFile, WrongTypes) {
  EXPECT_TRUE(bad_file("name = 5\n", 1, 8, {"'name': expected a string, got integer"}));
  EXPECT_TRUE(bad_file("description = [1]\n", 1, 15, {"expected a string, got array"}));
  EXPECT_TRUE(bad_file("host = 0\n[[processor]]\nname = \"P0\"\n", 1, 8,
                       {"expected a string, got integer"}));
  EXPECT_TRUE(
      bad_file("[[processor]]\nname = true\n", 2, 8, {"'name': expected a string, got boolean"}));
  EXPECT_TRUE(bad_file("[processor]\nname = \"P0\"\n", 1, 1,
                       {"'processor' must be written [[processor]]", "got table"}));
  EXPECT_TRUE(bad_file("processor = [1]\n", 1, 14, {"got an element of type integer"}));
  EXPECT_TRUE(bad_file(std::string(kHead) + "type = 800\n", 9, 8,
                       {"'type': expected a string, got integer"}));
  EXPECT_TRUE(bad_file(std::string(kHead) + "memory = 4\n", 9, 10,
                       {"'memory': expected a placement or a table, got integer"}));
  EXPECT_TRUE(bad_file(std::string(kHead) + "memory = { wait_states = 1.5 }\n", 9, 26,
                       {"'wait_states': expected an integer, got floating-point number"}));
  EXPECT_TRUE(bad_file(with_link("P0.link1", "P1.link0", "speed_mbps = \"fast\"\n"), 13, 14,
                       {"'speed_mbps': expected a number, got string"}));
}

TEST(TopologyFile, UnknownProcessorInLinkEnd) {
  EXPECT_TRUE(bad_file(with_link("P0.link1", "P7.link0"), 12, 6,
                       {"unknown processor 'P7' in link end 'P7.link0'", "processors are P0, P1"}));
}

TEST(TopologyFile, MalformedLinkEnd) {
  // One digit only: "link01" is not read as link1, nor "link12" as some link of a T800.
  for (const char* end : {"P1link0", "P1.lnk0", ".link0", "P1.link", "P1.link-1", "P1.linkX",
                          "P1.link01", "P1.link12"})
    EXPECT_TRUE(bad_file(with_link("P0.link1", end), 12, 6,
                         {"malformed link end '" + std::string(end) + "'", "expected NAME.linkN"}))
        << end;
}

TEST(TopologyFile, LinkWithoutBothEnds) {
  std::string text = with_link("P0.link1", "P1.link0");
  text.erase(text.find("to = "));
  EXPECT_TRUE(bad_file(text, 10, 1, {"[[link]] has no 'to'"}));
}

TEST(TopologyFile, ProcessorWithoutOrWithBadName) {
  EXPECT_TRUE(bad_file("host = \"P0.link0\"\n[[processor]]\ntype = \"T800-20\"\n", 2, 1,
                       {"[[processor]] has no name"}));
  EXPECT_TRUE(bad_file("host = \"P0.link0\"\n[[processor]]\nname = \"P 0\"\n", 3, 8,
                       {"processor name 'P 0' is not valid", "letters, digits"}));
}

TEST(TopologyFile, UnknownProcessorType) {
  EXPECT_TRUE(bad_file(std::string(kHead) + "type = \"T414\"\n", 9, 8,
                       {"unknown processor type 'T414'", "T800-20, T800-25, T800-30"}));
}

TEST(TopologyFile, BadMemory) {
  EXPECT_TRUE(bad_file(std::string(kHead) + "memory = { code = \"dram\" }\n", 9, 19,
                       {"unknown memory placement 'dram' for code", "onchip, external"}));
  EXPECT_TRUE(bad_file(std::string(kHead) + "memory = { wait_states = -1 }\n", 9, 26,
                       {"wait_states = -1 is negative", "0 or more"}));
}

TEST(TopologyFile, SyntaxErrorHasPosition) {
  EXPECT_TRUE(bad_file("name = \"t\"\nhost = \n", 2, 8, {"expected value"}));
  EXPECT_TRUE(bad_file("name = \"t\"\nname = \"u\"\n", 2, 8, {"redefine"}));
}

TEST(TopologyFile, MissingFileAndDirectory) {
  const std::string missing = (nettest::scratch_dir() / "nope.toml").string();
  EXPECT_TRUE(fails_at([&] { load_topology(missing); }, missing, 0, 0, {"no such topology file"}));
  const std::string dir = nettest::scratch_dir().string();
  EXPECT_TRUE(fails_at([&] { load_topology(dir); }, dir, 0, 0, {"directory"}));
}

}  // namespace
