// Mixed networks: processes of an SDK program beside a processor that runs real machine code,
// talking over the link between them in bytes (t800sim/byte_link.hpp, docs/iss.md).
#include <gtest/gtest.h>

#include "sdk_fixtures.hpp"
#include "t800/asm/assembler.hpp"
#include "t800sim/byte_link.hpp"

namespace {

using t800sim::Builder;
using t800sim::Bytes;
using t800sim::Process;

// P0 wired to the host and, through its link 1, to P1's link 0; P2 behind P1 when asked for.
network::Topology line(int processors) {
  network::Topology t;
  t.name = "line";
  t.source = "test";
  for (int i = 0; i < processors; ++i) {
    network::ProcessorSpec p;
    p.name = "P" + std::to_string(i);
    t.processors.push_back(p);
  }
  for (int i = 0; i + 1 < processors; ++i) t.connections.push_back({{i, 1}, {i + 1, 0}, {}, {}});
  t.host = network::LinkEnd{0, 0};
  network::validate(t);
  return t;
}

// Booted through link 0, it reads two INT32s from it and sends back their sum: 18 instructions.
Bytes adder_boot_block() {
  const auto program = t800::assembly::assemble(R"(
link0.out = #80000000
link0.in  = #80000010
        ajw 16
        ldlp 0
        ldc link0.in
        ldc 4
        in
        ldlp 1
        ldc link0.in
        ldc 4
        in
        ldl 0
        ldl 1
        add
        stl 2
        ldlp 2
        ldc link0.out
        ldc 4
        out
        stopp
)",
                                                {0x80000070, "adder.s"});
  Bytes block{std::uint8_t(program.bytes.size())};  // one boot stage: its length, then its code
  block.insert(block.end(), program.bytes.begin(), program.bytes.end());
  return block;
}

// The feeder boots P1, sends it two numbers and reads the sum back, as a host program would.
class Feeder : public t800sim::Program {
 public:
  explicit Feeder(std::string feeder_on = "P0", std::string booted = "P1")
      : feeder_on_(std::move(feeder_on)), booted_(std::move(booted)) {}
  void build(Builder& b) override {
    b.booted(booted_);
    const t800sim::ByteLink wire = b.byte_link("feed", "feeder", booted_);
    b.process("feeder", [this, wire](Process& p) {
       p.out(wire, adder_boot_block());
       p.out(wire, t800sim::bytes_of<std::int32_t>(30000));
       p.out(wire, t800sim::bytes_of<std::int32_t>(-12));
       const Bytes low = p.in(wire, 2);  // one output, taken in two pieces
       Bytes all = p.in(wire, 2);
       all.insert(all.begin(), low.begin(), low.end());
       sum_ = t800sim::value_from<std::int32_t>(all);
     }).placed_on(feeder_on_);
  }
  void results(t800sim::Results& r) const override { r.set("sum", std::int64_t(sum_)); }
  std::int32_t sum_ = 0;

 private:
  std::string feeder_on_, booted_;
};

// Running `program` on `topology` is refused before it starts, with `message` in the error.
::testing::AssertionResult refused(t800sim::Program* program, const network::Topology& topology,
                                   const std::string& message) {
  try {
    sdk_test::run(program, topology);
  } catch (const std::invalid_argument& e) {
    if (std::string(e.what()).find(message) != std::string::npos)
      return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << "the error says: " << e.what();
  }
  return ::testing::AssertionFailure() << "no error";
}

TEST(Booted, AProcessBootsItsNeighbourAndTalksToItsProgram) {
  auto* program = new Feeder;
  const sdk_test::Outcome o = sdk_test::run(program, line(2));
  ASSERT_TRUE(o.blocked.empty());
  ASSERT_TRUE(o.results.get("sum"));
  EXPECT_EQ(o.results.get("sum")->number(), 29988);
  const workloads::ResultValue* booted = o.results.get("booted");
  ASSERT_TRUE(booted);
  ASSERT_EQ(booted->items().size(), 1u);
  const workloads::ResultValue& p1 = booted->items()[0];
  EXPECT_EQ(p1.get("name")->to_json(), "\"P1\"");
  EXPECT_EQ(p1.get("booted")->to_json(), "true");
  EXPECT_EQ(p1.get("instructions")->number(), 18);  // counted by hand from the program above
  // The feeder waited for the link: the boot block of 44 bytes, two words out, one back, each byte
  // an 11-bit packet at 20 Mbit/s, is at least 52 x 0.55 us.
  EXPECT_GT(o.simulated_us, 52 * 0.55);
}

TEST(Booted, AProcessOnABootedProcessorIsAnError) {
  EXPECT_TRUE(
      refused(new Feeder("P1", "P1"), line(2), "process feeder is placed on P1, which is booted"));
}

TEST(Booted, AByteLinkMustJoinNeighbours) {
  EXPECT_TRUE(refused(new Feeder("P0", "P2"), line(3), "is on P0, which is not wired to P2"));
}

TEST(Booted, AProcessorTheNetworkDoesNotHaveIsAnError) {
  EXPECT_TRUE(refused(new Feeder("P0", "P9"), line(2),
                      "P9 is not in the network; its processors are P0, P1"));
}

TEST(Booted, AChannelRoutedThroughABootedProcessorIsAnError) {
  auto* program = new sdk_test::Lambda([](Builder& b) {
    b.booted("P1");
    const auto c = b.channel<t800sim::INT>("across", "left", "right");
    b.process("left", [c](Process& p) { p.out(c, 1); }).placed_on("P0");
    b.process("right", [c](Process& p) { p.in(c); }).placed_on("P2");
  });
  EXPECT_TRUE(refused(program, line(3), "channel across is routed through P1, which is booted"));
}

// The T800 holds values little-endian, integers in two's complement and reals in IEEE 754
// (1.5 = #3FF8000000000000, 1.0 as REAL32 = #3F800000).
TEST(Booted, ValuesGoOnTheWireAsTheT800HoldsThem) {
  EXPECT_EQ(t800sim::bytes_of<std::int32_t>(-12), (Bytes{0xF4, 0xFF, 0xFF, 0xFF}));
  EXPECT_EQ(t800sim::bytes_of<double>(1.5), (Bytes{0, 0, 0, 0, 0, 0, 0xF8, 0x3F}));
  EXPECT_EQ(t800sim::bytes_of<float>(1.0f), (Bytes{0, 0, 0x80, 0x3F}));
  EXPECT_EQ(t800sim::bytes_of<bool>(true), (Bytes{1}));
  EXPECT_EQ(t800sim::value_from<std::int16_t>(Bytes{0x34, 0x12}), 0x1234);
  EXPECT_EQ(t800sim::value_from<double>(Bytes{9, 0, 0, 0, 0, 0, 0, 0xF8, 0x3F}, 1), 1.5);
  EXPECT_THROW(t800sim::value_from<std::int32_t>(Bytes{1, 2, 3}), std::out_of_range);
}

}  // namespace
