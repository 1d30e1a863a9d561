// icollect's map files as networks: the processors of the memory maps and the wires of the
// connectivity section, every error at its line and column.
#include "network/icollect_map.hpp"

#include <gtest/gtest.h>

#include "test_util.hpp"

namespace {

using network::is_icollect_map;
using network::parse_icollect_map;
using t800::ProcessorType;

// A map in icollect's layout for three processors in a chain, written for these tests: the host
// on P0.link0 and each processor's link 2 wired to the next one's link 1, as on a B012.
std::string chain_map(
    const std::string& type2 = "T800",
    const std::string& last_wire = "  Connect processor 2 link 1 to processor 1 link 2\n") {
  return "icollect : INMOS toolset collector\n"           // 1
         "\n"                                             // 2
         "Memory map for 'System[0]' processor 0 T800\n"  // 3
         "Load Start is 80000150,  HALT ON ERROR\n"       // 4
         "Memory map for 'System[1]' processor 1 T800\n"  // 5
         "Memory map for 'System[2]' processor 2 " +
         type2 +
         "\n"                                                      // 6
         "\n"                                                      // 7
         "Boot path for network\n"                                 // 8
         "  Boot processor 0 down link 0 from HOST\n"              // 9
         "\n"                                                      // 10
         "Connectivity for network\n"                              // 11
         "\n"                                                      // 12
         "  Connect HOST to processor 0 link 0\n"                  // 13
         "  Connect processor 1 link 1 to processor 0 link 2\n" +  // 14
         last_wire;                                                // 15
}

network::Topology read_map(const std::string& text,
                           std::optional<ProcessorType> each = std::nullopt) {
  return parse_icollect_map(text, "net.map", each);
}

::testing::AssertionResult bad(const std::string& text, int line, int column,
                               std::initializer_list<std::string> parts,
                               std::optional<ProcessorType> each = std::nullopt) {
  return nettest::fails_at([&] { read_map(text, each); }, "net.map", line, column, parts);
}

TEST(IcollectMap, ReadsTheProcessorsAndTheWiresOfAChain) {
  const network::Topology t = read_map(chain_map());
  ASSERT_EQ(t.processors.size(), 3u);
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(t.processors[i].name, "P" + std::to_string(i));
    EXPECT_EQ(t.processors[i].config.type, ProcessorType::T800_20);  // the family at 20 MHz
  }
  ASSERT_TRUE(t.host);
  EXPECT_EQ(*t.host, (network::LinkEnd{0, 0}));
  ASSERT_EQ(t.connections.size(), 2u);
  EXPECT_EQ(t.connections[0].a, (network::LinkEnd{1, 1}));
  EXPECT_EQ(t.connections[0].b, (network::LinkEnd{0, 2}));
  EXPECT_EQ(t.connections[1].a, (network::LinkEnd{2, 1}));
  EXPECT_EQ(t.connections[1].b, (network::LinkEnd{1, 2}));
  EXPECT_EQ(t.connections[1].where.line, 15);
  EXPECT_EQ(t.source, "net.map");
}

TEST(IcollectMap, AGivenProcessorTypeIsEveryProcessorOfItsFamily) {
  const network::Topology t = read_map(chain_map(), ProcessorType::T805_25);
  for (const network::ProcessorSpec& p : t.processors)
    EXPECT_EQ(p.config.type, ProcessorType::T805_25) << p.name;
}

TEST(IcollectMap, AT414MapIsT414s) {
  std::string text = chain_map("T414");
  EXPECT_TRUE(bad(text, 6, 40, {"T414", "T800-20", "without a floating-point unit"},
                  ProcessorType::T800_20));
  for (std::size_t at; (at = text.find("T800")) != std::string::npos;) text.replace(at, 4, "T414");
  EXPECT_EQ(read_map(text).processors[1].config.type, ProcessorType::T414_20);
}

TEST(IcollectMap, AFamilyNotModelledIsAnError) {
  EXPECT_TRUE(bad(chain_map("T425"), 6, 40, {"'T425'", "T800, T805 and T414"}));
}

TEST(IcollectMap, AWireToAProcessorWithNoMemoryMapIsAnError) {
  EXPECT_TRUE(bad(chain_map("T800", "  Connect processor 7 link 1 to processor 1 link 2\n"), 15, 21,
                  {"processor 7", "no memory map"}));
}

TEST(IcollectMap, ALinkNumberPastThreeIsAnError) {
  EXPECT_TRUE(bad(chain_map("T800", "  Connect processor 2 link 4 to processor 1 link 2\n"), 15, 28,
                  {"link 4", "links 0 to 3"}));
}

TEST(IcollectMap, AWireThatCannotBeReadSaysWhatWouldBe) {
  EXPECT_TRUE(bad(chain_map("T800", "  Connect processor 2 link 1 with processor 1 link 2\n"), 15,
                  3, {"Connect processor N link L to processor M link K"}));
  EXPECT_TRUE(bad(chain_map("T800", "  Connect processor 2 link one to processor 1 link 2\n"), 15,
                  28, {"expected a link number", "'one'"}));
}

TEST(IcollectMap, ALinkUsedTwiceIsAnError) {
  EXPECT_TRUE(bad(chain_map("T800", "  Connect processor 2 link 1 to processor 0 link 2\n"), 15, 3,
                  {"P0.link2"}));
}

TEST(IcollectMap, ATextWithoutAConnectivitySectionIsNotAMap) {
  const std::string toml = "name = \"x\"\nhost = \"P0.link0\"\n[[processor]]\nname = \"P0\"\n";
  EXPECT_FALSE(is_icollect_map(toml));
  EXPECT_TRUE(is_icollect_map(chain_map()));
  EXPECT_TRUE(bad(toml, 0, 0, {"Connectivity for network", "not an icollect map"}));
}

TEST(IcollectMap, AMapWithoutTheHostSaysWhereNothingBoots) {
  std::string text = chain_map();
  text.erase(text.find("  Connect HOST"),
             std::string("  Connect HOST to processor 0 link 0\n").size());
  EXPECT_TRUE(bad(text, 0, 0, {"Connect HOST"}));
}

TEST(IcollectMap, AProcessorNoWireReachesIsAnError) {
  std::string text = chain_map("T800", "");
  EXPECT_TRUE(bad(text, 6, 1, {"P2"}));
}

}  // namespace
