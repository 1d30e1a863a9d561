// `t800sim asm` and `t800sim boot` end to end: programs the project assembles, booted through the
// host link onto one board or a network, served by the host, timed by the link model.
#include <gtest/gtest.h>

#include "t800/link_timing.hpp"
#include "tests/boot/boot_fixtures.hpp"
#include "tests/test_paths.hpp"

namespace {

using namespace boot_test;

const std::string kTopologies = test_paths::source_dir() + "/configs/topologies/";

TEST(Boot, HelloWritesToStdoutAndExitsWithTheProgramsStatus) {
  const auto dir = scratch("hello");
  const std::string file = assemble(dir, "hello", example_with("hello.s", {}));
  ASSERT_FALSE(file.empty());
  const Booted b = boot(dir, file);
  EXPECT_EQ(b.output.exit_code, 0) << b.output.out;
  EXPECT_NE(b.output.out.find("hello, transputer\n"), std::string::npos) << b.output.out;
  ASSERT_TRUE(b.report.is_object());
  EXPECT_EQ(b.report["workload"]["exit_status"], 999999999);  // sps.success
  EXPECT_EQ(b.report["workload"]["host_requests"], 2);        // SP.WRITE, SP.EXIT
}

TEST(Boot, AnExitStatusThatIsNotTheToolsetsIsTheExitCode) {
  const auto dir = scratch("status");
  std::string source = example_with("hello.s", {});
  const auto at = source.find(".word 999999999");
  ASSERT_NE(at, std::string::npos);
  source.replace(at, 15, ".word 7");
  const Booted b = boot(dir, assemble(dir, "seven", source));
  EXPECT_EQ(b.output.exit_code, 7) << b.output.out;
}

// A shell keeps an exit code's low 8 bits: a status of 256 or 512 must not read as success.
TEST(Boot, AnExitStatusThatDoesNotFitEightBitsIsAFailure) {
  const auto dir = scratch("wide-status");
  for (const std::string status : {"256", "512", "-1"}) {
    std::string source = example_with("hello.s", {});
    const auto at = source.find(".word 999999999");
    ASSERT_NE(at, std::string::npos);
    source.replace(at, 15, ".word " + status);
    const Booted b = boot(dir, assemble(dir, "wide", source));
    EXPECT_EQ(b.output.exit_code, 255) << status << ": " << b.output.out;
    ASSERT_TRUE(b.report.is_object()) << b.output.out;
    EXPECT_EQ(b.report["workload"]["exit_status"], std::stoi(status));  // the status itself
  }
}

// A packet whose length no SP packet has (an odd 7: a body is padded to an even length) is a
// broken host protocol: its own exit code, 5, not a halted processor's 3.
TEST(Boot, ABrokenHostProtocolHasAnExitCodeOfItsOwn) {
  const auto dir = scratch("bad-packet");
  std::string source = example_with("hello.s", {});
  const auto at = source.find("write:  .byte 26, 0");
  ASSERT_NE(at, std::string::npos);
  source.replace(at, 19, "write:  .byte 7, 0 ");
  const Booted b = boot(dir, assemble(dir, "bad", source));
  EXPECT_EQ(b.output.exit_code, 5) << b.output.out;
  EXPECT_NE(b.output.out.find("not SP requests"), std::string::npos) << b.output.out;
  ASSERT_TRUE(b.report.is_object()) << b.output.out;
  EXPECT_TRUE(b.report["workload"].contains("host_protocol_error")) << b.report["workload"];
}

TEST(Boot, TheArgumentsAfterTwoDashesAreTheProgramsCommandLine) {
  const auto dir = scratch("echo");
  const std::string file = assemble(dir, "echo", example_with("echo.s", {}));
  ASSERT_FALSE(file.empty());
  const Booted b = boot(dir, file, "-- hello there");
  EXPECT_EQ(b.output.exit_code, 0) << b.output.out;
  EXPECT_EQ(b.output.out.rfind("hello there", 0), 0u) << b.output.out;  // SP.WRITE, first
}

// A process computing while another's link transfers run: the core runs ahead of the link events
// and stops short of each, which on a 25 or 30 MHz part falls inside a processor cycle (the link's
// bits are 50 ns). The core must let the time reach such an event, not wait for it a delta at a
// time for ever (the run hung there once). The program is hello.s with a busy loop beside it.
TEST(Boot, AComputingProcessLetsLinkEventsWithinACycleHappen) {
  const auto dir = scratch("busy");
  std::string source = example_with("hello.s", {});
  const std::string start = "start:  ajw 16";
  const auto at = source.find(start);
  ASSERT_NE(at, std::string::npos);
  source.insert(at + start.size(), R"(
        ldc busy - b1          -- a low-priority loop beside the main process, for ever
        ldlp 64
        startp
b1:)");
  source += "busy:   j busy\n";
  const std::string file = assemble(dir, "busy", source);
  ASSERT_FALSE(file.empty());
  for (const std::string type : {"T800-20", "T800-25", "T800-30"}) {
    const Booted b = boot(dir, file, "--processor " + type);
    EXPECT_EQ(b.output.exit_code, 0) << type << ": " << b.output.out;
    EXPECT_NE(b.output.out.find("hello, transputer\n"), std::string::npos) << b.output.out;
  }
}

// Every processor of the chain is booted by its neighbour through the chip's boot protocol, runs
// the same loop, and the sum of the processors that ran comes back as the exit status.
TEST(Boot, AChainBootsEveryProcessorThroughItsNeighbour) {
  const auto dir = scratch("chain");
  const std::string file =
      assemble(dir, "chain", example_with("chain.s", {{"iterations", "1000"}}));
  ASSERT_FALSE(file.empty());
  const Booted b = boot(dir, file, "--network " + kTopologies + "pipeline-6.toml");
  EXPECT_EQ(b.output.exit_code, 6) << b.output.out;
  ASSERT_TRUE(b.report.is_object());
  const auto& processors = b.report["workload"]["processors"];
  ASSERT_EQ(processors.size(), 6u);
  // Instructions counted by hand from chain.s. The loop: 6 an iteration (ldl adc stl ldl cj j),
  // 5 the last time round. Before it: 11 to read hops and first, 20 to boot the next processor
  // (the last boots nobody), 2 to set the count. After it: 8 to read the sum from behind (4 on
  // the last, which has nobody behind), 5 to add its own one; then the first sends SP.EXIT, reads
  // the reply's length and starts to read its body (20 + 4 instructions: the host stops serving,
  // and the run ends, while the body comes), the others pass the sum back (5).
  const int loop = 6 * 999 + 5;
  for (int i = 0; i < 6; ++i) {
    const auto& p = processors[i];
    EXPECT_TRUE(p["booted"]) << p;
    EXPECT_EQ(p["boot_link"], 0) << p;
    const int expected = i == 0   ? 11 + 20 + 2 + loop + 8 + 5 + 20 + 4
                         : i == 5 ? 11 + 2 + loop + 4 + 5 + 5
                                  : 11 + 20 + 2 + loop + 8 + 5 + 5;
    EXPECT_EQ(p["instructions"], expected) << p;
  }
}

TEST(Boot, ATwoStageBootFileLoadsThroughThePrimaryLoader) {
  const auto dir = scratch("two-stage");
  const std::string file =
      assemble(dir, "chain", example_with("chain.s", {{"iterations", "100"}}), "--boot two-stage");
  ASSERT_FALSE(file.empty());
  // Only the first processor is booted in two stages; it boots the others with one stage each,
  // which its code, assembled for the two-stage address, does position-independently.
  const Booted b = boot(dir, file, "--network " + kTopologies + "pipeline-6.toml");
  EXPECT_EQ(b.output.exit_code, 6) << b.output.out;
}

// Ping-pong of n bytes between two booted processors, timed by the program's own microsecond
// clock, against the link model's closed form for one uncontended message (LinkTiming): each
// round is two n-byte messages, and a few instructions between them.
TEST(Boot, PingPongTakesTheLinkModelsTimeForEachMessage) {
  const auto dir = scratch("pingpong");
  for (const int bytes : {1, 100, 1000}) {
    const int rounds = 20;
    const std::string file = assemble(
        dir, "pp" + std::to_string(bytes),
        example_with("pingpong.s",
                     {{"bytes", std::to_string(bytes)}, {"rounds", std::to_string(rounds)}}));
    ASSERT_FALSE(file.empty());
    const Booted b = boot(dir, file, "--network " + kTopologies + "pair.toml");
    ASSERT_TRUE(b.report.is_object()) << b.output.out;
    const double measured_us = b.report["workload"]["exit_status"].get<double>();
    const t800::LinkTiming link(t800::LinkConfig{});
    const double links_us = rounds * 2 * link.arrival_ns(bytes) / 1000;
    // Between two messages each side runs at most 14 instructions (the loop, the next transfer's
    // operands, its out or in) of at most 8 cycles with their operand fetches, and the process is
    // rescheduled once: under 10 us a round at 20 MHz for the two. And the clock's tick.
    EXPECT_GE(measured_us, links_us - 1) << bytes << " bytes";
    EXPECT_LE(measured_us, links_us + rounds * 10 + 1) << bytes << " bytes";
  }
}

TEST(Boot, AnEmptyBootFileIsAnErrorNamingIt) {
  const auto dir = scratch("empty");
  write_text(dir / "empty.btl", "");
  const Booted b = boot(dir, (dir / "empty.btl").string());
  EXPECT_EQ(b.output.exit_code, 2) << b.output.out;
  EXPECT_NE(b.output.out.find("empty.btl is empty"), std::string::npos) << b.output.out;
}

TEST(Boot, AFirstStageShorterThanItsLengthByteNamesTheOffset) {
  const auto dir = scratch("short");
  write_text(dir / "short.btl", std::string("\x0A\x21\x22", 3));  // 10 bytes announced, 2 given
  const Booted b = boot(dir, (dir / "short.btl").string());
  EXPECT_EQ(b.output.exit_code, 2) << b.output.out;
  EXPECT_NE(b.output.out.find("truncated: the control byte 10 at byte offset 0 announces 10"),
            std::string::npos)
      << b.output.out;
}

// A two-stage file cut short: the primary loader waits for the rest of the program for ever; the
// run ends with who waits on which link, after how many of how many bytes.
TEST(Boot, ATruncatedLaterStageSaysWhoWaitsForWhat) {
  const auto dir = scratch("truncated");
  const std::string file = assemble(dir, "chain", example_with("chain.s", {}), "--boot two-stage");
  ASSERT_FALSE(file.empty());
  std::string bytes = read_text(file);
  bytes.resize(bytes.size() - 10);
  write_text(dir / "cut.btl", bytes);
  const Booted b = boot(dir, (dir / "cut.btl").string());
  EXPECT_EQ(b.output.exit_code, 1) << b.output.out;  // nothing can move: a deadlock report
  EXPECT_NE(b.output.out.find("deadlock"), std::string::npos) << b.output.out;
  EXPECT_NE(b.output.out.find("on channel #80000010 (link 0: "), std::string::npos) << b.output.out;
  EXPECT_NE(b.output.out.find(" bytes have come)"), std::string::npos) << b.output.out;
}

TEST(Boot, AnUndefinedOperationHaltsWithAReport) {
  const auto dir = scratch("undefined");
  const Booted b = boot(dir, assemble(dir, "bad", "ajw 8\nldc 1\nopr #1FE\nstopp\n"));
  EXPECT_EQ(b.output.exit_code, 3) << b.output.out;
  EXPECT_NE(b.output.out.find("P0 halted: undefined operation #1FE"), std::string::npos)
      << b.output.out;
  ASSERT_TRUE(b.report.is_object());
  EXPECT_EQ(b.report["workload"]["processors"][0]["halt"]["iptr"],
            "#80000072");  // ajw, ldc: 2 bytes
}

TEST(Boot, AStrictWildAccessHaltsWithTheAddress) {
  const auto dir = scratch("strict");
  const std::string file = assemble(dir, "wild", "ajw 8\nldc #7FFFFFF0\nldnl 0\nstopp\n");
  const Booted wrap = boot(dir, file);
  EXPECT_EQ(wrap.output.exit_code, 1) << wrap.output.out;  // wraps, reads, stops (a STOP)
  EXPECT_NE(wrap.output.out.find("stopped"), std::string::npos) << wrap.output.out;
  const Booted strict = boot(dir, file, "--strict --memory 65536");
  EXPECT_EQ(strict.output.exit_code, 3) << strict.output.out;
  EXPECT_NE(strict.output.out.find("#7FFFFFF0"), std::string::npos) << strict.output.out;
}

// Processors of different clocks in one chain (chain.s boots six), as on an IMS B012 (a T805-30,
// whose 33.33 ns cycle is no whole number of the kernel's picoseconds, beside T805-25s): each boots
// the next and they pass the sum back while the others compute. Cores that stopped within a cycle
// of each other's link events once handed each other waits of no time for ever (a livelock at 44 ms
// of the ray tracer); now the run ends, every processor reached, inside the host time it is given.
TEST(Boot, AChainOfDifferentClocksRunsToItsEnd) {
  const auto dir = scratch("mixed-clocks");
  write_text(dir / "chain.toml", R"(host = "P0.link0"
[[processor]]
name = "P0"
type = "T805-30"
[[processor]]
name = "P1"
type = "T805-25"
[[processor]]
name = "P2"
type = "T805-25"
[[processor]]
name = "P3"
type = "T800-20"
[[processor]]
name = "P4"
type = "T805-30"
[[processor]]
name = "P5"
type = "T805-25"
[[link]]
from = "P0.link1"
to = "P1.link0"
[[link]]
from = "P1.link1"
to = "P2.link0"
[[link]]
from = "P2.link1"
to = "P3.link0"
[[link]]
from = "P3.link1"
to = "P4.link0"
[[link]]
from = "P4.link1"
to = "P5.link0"
)");
  for (const std::string iterations : {"1", "1000", "33333"}) {
    const std::string file =
        assemble(dir, "chain", example_with("chain.s", {{"iterations", iterations}}));
    ASSERT_FALSE(file.empty());
    const Booted b =
        boot(dir, file, "--network " + (dir / "chain.toml").string() + " --max-host-s 60");
    EXPECT_EQ(b.output.exit_code, 6) << iterations << ": " << b.output.out;  // the processors
    ASSERT_TRUE(b.report.is_object()) << b.output.out;
    for (const auto& p : b.report["workload"]["processors"]) {
      EXPECT_TRUE(p["booted"]) << p;
      // Fewer synchronisations than instructions: a core never stops for SystemC without
      // running at least a cycle's worth.
      EXPECT_LT(p["synchronisations"].get<double>(), p["instructions"].get<double>()) << p;
    }
  }
}

// A configured program's network as the collector's map file describes it: the chain that
// chain.s boots (Pi.link1 to P(i+1).link0), every processor the type --processor gives.
TEST(Boot, AnIcollectMapIsTheNetwork) {
  const auto dir = scratch("map");
  // chain.s boots five processors behind the first.
  std::string memory_maps, wires;
  for (int p = 0; p < 6; ++p) {
    memory_maps += "Memory map for 'System[" + std::to_string(p) + "]' processor " +
                   std::to_string(p) + " T800\n";
    wires += p == 0 ? "  Connect HOST to processor 0 link 0\n"
                    : "  Connect processor " + std::to_string(p) + " link 0 to processor " +
                          std::to_string(p - 1) + " link 1\n";
  }
  const std::string map = memory_maps + "\nConnectivity for network\n\n" + wires;
  write_text(dir / "chain.map", map);
  const std::string file = assemble(dir, "chain", example_with("chain.s", {{"iterations", "100"}}));
  ASSERT_FALSE(file.empty());
  const Booted b =
      boot(dir, file, "--network " + (dir / "chain.map").string() + " --processor T805-25");
  EXPECT_EQ(b.output.exit_code, 6) << b.output.out;  // the processors that ran
  ASSERT_TRUE(b.report.is_object()) << b.output.out;
  EXPECT_EQ(b.report["workload"]["processors"].size(), 6u);
  EXPECT_NE(b.output.out.find("P5 T805-25"), std::string::npos) << b.output.out;
  // A topology file names its own types: --processor beside one would be ignored, so it is an
  // error.
  const Booted both =
      boot(dir, file, "--network " + kTopologies + "pipeline-6.toml --processor T805-25");
  EXPECT_EQ(both.output.exit_code, 2) << both.output.out;
  EXPECT_NE(both.output.out.find("a topology file names its processors' types"), std::string::npos)
      << both.output.out;
  // A configuration's source is neither: the error says what --network takes.
  write_text(dir / "net.cfs", "T800 (memory = 4M) Root;\nconnect Root.link[0] to host;\n");
  const Booted cfs = boot(dir, file, "--network " + (dir / "net.cfs").string());
  EXPECT_EQ(cfs.output.exit_code, 2) << cfs.output.out;
  EXPECT_NE(cfs.output.out.find("net.cfs:1:"), std::string::npos) << cfs.output.out;
  EXPECT_NE(cfs.output.out.find("the .map file icollect wrote"), std::string::npos)
      << cfs.output.out;
}

// A program that reads a reply field by field leaves the pad byte iserver adds to an odd body
// (SP.VERSION's five bytes go out as six); its next request abandons what it left, as t4's server
// drops it, instead of the host waiting for ever to send the last byte (POV-Ray's SP multiplexer
// reads its replies so).
TEST(Boot, AReplyLeftUnreadToItsEndIsDroppedAtTheNextRequest) {
  const auto dir = scratch("cut-short");
  const std::string file = assemble(dir, "version", R"(
link0.out = #80000000
link0.in  = #80000010
start:  ajw 16
        ldc version - v1
        ldpi
v1:     ldc 8
        ldc 5                  -- the version's fields: not the pad
        call ask
        ldc exit - e1
        ldpi
e1:     ldc 8
        ldc 6
        call ask
        stopp
-- ask: out the 8-byte packet at C, take the reply's length, then A bytes of its body.
ask:    ajw -4
        ldl 7
        ldc link0.out
        ldl 6
        out
        ldlp 0
        ldc link0.in
        ldc 2
        in
        ldlp 1
        ldc link0.in
        ldl 5
        in
        ajw 4
        ret
version: .byte 6, 0
        .byte 42               -- SP.VERSION
        .byte 0, 0, 0, 0, 0
        .align 4
exit:   .byte 6, 0
        .byte 35               -- SP.EXIT, sps.success
        .word 999999999
        .byte 0
)");
  ASSERT_FALSE(file.empty());
  const Booted b = boot(dir, file);
  EXPECT_EQ(b.output.exit_code, 0) << b.output.out;
  ASSERT_TRUE(b.report.is_object()) << b.output.out;
  EXPECT_EQ(b.report["workload"]["host_replies_cut_short"], 1) << b.report["workload"];
  EXPECT_EQ(b.report["workload"]["host_requests"], 2);
}

// Two processors compute while a high-priority process on each waits in an ALT on the link from
// the other, as the ray tracer's workers do; then P0 sends P1 a byte, P1 answers, and P0's ALT
// ends the program with status 7. Nothing a neighbour starts can be seen before its first byte
// arrives, one data packet (11 bits, 550 ns: 11 cycles of a T800-20 at 20 Mbit/s) later, so a core
// whose only outstanding business is such a guard runs that far ahead between synchronisations,
// not a cycle at a time.
TEST(Boot, AWatchedLinkLetsTheCoreRunADataPacketAhead) {
  const auto dir = scratch("alt-watch");
  const std::string file =
      assemble(dir, "watch", example_with("watch.s", {{"iterations", "20000"}}));
  ASSERT_FALSE(file.empty());
  const Booted b = boot(dir, file, "--network " + kTopologies + "pair.toml --no-run-ahead");
  EXPECT_EQ(b.output.exit_code, 7) << b.output.out;
  ASSERT_TRUE(b.report.is_object()) << b.output.out;
  for (const auto& p : b.report["workload"]["processors"]) {
    // 20,000 iterations of the loop are some 220,000 cycles with a guard watched all along.
    EXPECT_GT(p["cycles"].get<double>(), 200000) << p;
    EXPECT_LT(p["synchronisations"].get<double>(), p["cycles"].get<double>() / 8) << p;
  }
}

// Running ahead (workloads/boot/iss_node.cpp, "running ahead") changes only where cores
// synchronise, on which only where DMA stalls fall depends (docs/iss.md, "Running ahead"): these
// programs must run exactly as with the look-ahead alone (--no-run-ahead), processor for
// processor, cycle for cycle -- their instructions, cycles, DMA stalls, where they end and when.
// watch.s is the case it is for: both cores compute with a guard watched; made to count twice on
// P1, it has P0's byte arrive while P1 has run ahead, so that run must be undone. pingpong.s and
// chain.s move data all the time, so little can run ahead: what does must come out the same.
TEST(Boot, RunningAheadRunsEveryProgramAsTheLookAheadAloneDoes) {
  const auto dir = scratch("run-ahead");
  struct Case {
    std::string name, source, topology;
  };
  const std::string watch = example_with("watch.s", {{"iterations", "20000"}});
  std::string longer = watch;
  const std::string p1_counts = "        call count\n        stopp\n-- spawn";
  ASSERT_NE(longer.find(p1_counts), std::string::npos);
  longer.replace(longer.find(p1_counts), p1_counts.size(),
                 "        call count\n        call count\n        stopp\n-- spawn");
  const std::vector<Case> cases = {
      {"watch", watch, "pair.toml"},
      {"watch-longer", longer, "pair.toml"},
      {"pingpong", example_with("pingpong.s", {{"bytes", "100"}, {"rounds", "20"}}), "pair.toml"},
      {"chain", example_with("chain.s", {{"iterations", "2000"}}), "pipeline-6.toml"},
  };
  for (const Case& c : cases) {
    const std::string file = assemble(dir, c.name, c.source);
    ASSERT_FALSE(file.empty()) << c.name;
    const std::string network = "--network " + kTopologies + c.topology;
    const Booted ahead = boot(dir, file, network);
    const Booted alone = boot(dir, file, network + " --no-run-ahead");
    ASSERT_TRUE(ahead.report.is_object()) << c.name << ": " << ahead.output.out;
    ASSERT_TRUE(alone.report.is_object()) << c.name << ": " << alone.output.out;
    EXPECT_EQ(ahead.output.exit_code, alone.output.exit_code) << c.name;
    EXPECT_EQ(ahead.report["simulated_us"], alone.report["simulated_us"]) << c.name;
    // The utilisation trace and the links' traffic: the same intervals, the same messages.
    EXPECT_EQ(ahead.report["processors"], alone.report["processors"]) << c.name;
    EXPECT_EQ(ahead.report["links"], alone.report["links"]) << c.name;
    const auto& w = ahead.report["workload"];
    const auto& v = alone.report["workload"];
    EXPECT_EQ(w["exit_status"], v["exit_status"]) << c.name;
    EXPECT_EQ(w["ended"], v["ended"]) << c.name;
    EXPECT_EQ(w["instructions"], v["instructions"]) << c.name;
    ASSERT_EQ(w["processors"].size(), v["processors"].size()) << c.name;
    std::int64_t runs = 0, undone = 0, syncs_ahead = 0, syncs_alone = 0;
    for (std::size_t i = 0; i < w["processors"].size(); ++i) {
      const auto& p = w["processors"][i];
      const auto& q = v["processors"][i];
      for (const char* key : {"instructions", "cycles", "dma_stall_cycles", "state"})
        EXPECT_EQ(p[key], q[key]) << c.name << " " << p["name"] << " " << key;
      EXPECT_EQ(q["runs_ahead"], 0) << c.name;
      runs += p["runs_ahead"].get<std::int64_t>();
      undone += p["runs_ahead_undone"].get<std::int64_t>();
      syncs_ahead += p["synchronisations"].get<std::int64_t>();
      syncs_alone += q["synchronisations"].get<std::int64_t>();
    }
    if (c.name == "watch") {
      // Some 220,000 cycles each with a guard watched: slices of 1 ms (20,000 cycles), not data
      // packets of 11 cycles.
      EXPECT_GT(runs, 10) << w;
      EXPECT_LT(syncs_ahead * 50, syncs_alone) << w;
    }
    if (c.name == "watch-longer") {
      EXPECT_GE(undone, 1) << w;  // P1's run over P0's byte
    }
  }
}

// A core that has run ahead when another processor's limit ends the run is brought back to the
// instant the run ended: what it reports ran before the end, as with the look-ahead alone.
TEST(Boot, ACoreAheadWhenTheRunEndsReportsWhereTheEndFoundIt) {
  const auto dir = scratch("run-ahead-stopped");
  const std::string file =
      assemble(dir, "watch", example_with("watch.s", {{"iterations", "20000"}}));
  ASSERT_FALSE(file.empty());
  const Booted b =
      boot(dir, file, "--network " + kTopologies + "pair.toml --max-instructions 60000");
  ASSERT_TRUE(b.report.is_object()) << b.output.out;
  const double end_ns = b.report["simulated_us"].get<double>() * 1000;
  for (const auto& p : b.report["workload"]["processors"]) {
    // A T800-20's cycle is 50 ns; a data packet (550 ns) and an instruction is as far as the
    // look-ahead takes a core past the end.
    const double at_ns = p["cycles"].get<double>() * 50;
    EXPECT_LE(at_ns, end_ns + 1000) << p;
    EXPECT_GE(at_ns, end_ns - 1000) << p;
  }
  EXPECT_GT(b.report["workload"]["processors"][1]["runs_ahead"].get<int>(), 0);
}

// A run stopped by a limit still says what ran: instructions and cycles per processor, and where
// each one was.
TEST(Boot, AStoppedRunReportsWhatRan) {
  const auto dir = scratch("stopped");
  const std::string file = assemble(dir, "forever", "ajw 8\nloop: j loop\n");
  const Booted b = boot(dir, file, "--max-simulated-s 0.0015");
  EXPECT_EQ(b.output.exit_code, 4) << b.output.out;
  ASSERT_TRUE(b.report.is_object()) << b.output.out;
  EXPECT_EQ(b.report["stopped_by"], "max_sim_time");
  const auto& p = b.report["workload"]["processors"][0];
  // The loop is a backward jump of two bytes, nfix 0; j 14: the prefix's cycle and j's 3 (T800
  // datasheet). 1.5 ms of a T800-20's 50 ns cycles is 30,000 cycles, less the few the boot took:
  // some 7,500 jumps, and no more: the core runs ahead of SystemC, but not past the limit (the
  // instruction under way at the limit finishes, 4 cycles at most).
  EXPECT_NEAR(p["instructions"].get<double>(), 30000.0 / 4, 20) << p;
  EXPECT_LE(p["cycles"].get<double>(), 30000 + 4) << p;
  EXPECT_NE(p["state"].get<std::string>().find("running at Iptr"), std::string::npos) << p;
  EXPECT_NE(b.output.out.find("P0: running at Iptr"), std::string::npos) << b.output.out;
}

// SP.TIME twice, 2.5 simulated seconds apart (a low-priority timer wait of 39,063 ticks of 64 us),
// and SP.EXIT with (second - first) + (first - 1,000,000,000) as the status: 2 when the clock is
// the simulated one started at --clock-start 1000000000 (the run's start plus the whole simulated
// seconds), whatever the host's clock says and however fast the host runs.
constexpr const char* kTimeTwice = R"(
link0.out = #80000000
link0.in  = #80000010

start:  ajw 32
        ldc 0                  -- the clocks start (a booted chip's are stopped until sttimer)
        sttimer
        call clock
        ldl 3                  -- UTC, the reply's second INT32
        stl 10
        ldtimer                -- 2.5 s of low-priority ticks
        ldc 39063
        sum
        tin
        call clock
        ldl 3
        stl 11
        ldl 11                 -- the status
        ldl 10
        diff
        ldl 10
        ldc 1000000000
        diff
        sum
        stl 21
        ldc 6                  -- SP.EXIT: length 6, tag 35, the status, a pad; from byte 1 of
        ldlp 20                -- ws[20] so that the status is the word ws[21]
        adc 1
        sb
        ldc 0
        ldlp 20
        adc 2
        sb
        ldc 35
        ldlp 20
        adc 3
        sb
        ldc 0
        stl 22
        ldlp 20
        adc 1
        ldc link0.out
        ldc 8
        out
        ldlp 0                 -- its reply, as every request's: the host sends it, then exits
        ldc link0.in
        ldc 2
        in
        ldlp 1
        ldc link0.in
        ldc 6
        in
        stopp

-- clock: SP.TIME; the reply's result byte into ws[1] of the caller's frame, its local time and
-- UTC into ws[2] and ws[3]. Four words of its own below the four call pushed (Iptr, A, B, C).
clock:  ajw -4
        ldc time - t1
        ldpi
t1:     ldc link0.out
        ldc 8
        out
        ldc 0
        stl 0
        ldlp 0                 -- the reply's length
        ldc link0.in
        ldc 2
        in
        ldlp 9                 -- its result byte: ws[1] of the caller
        ldc link0.in
        ldc 1
        in
        ldlp 10                -- local time and UTC: the caller's ws[2], ws[3]
        ldc link0.in
        ldl 0
        adc -1
        in
        ajw 4
        ret
        .align 4
time:   .byte 6, 0, 33, 0, 0, 0, 0, 0
)";

TEST(Boot, SpTimeTellsTheSimulatedClock) {
  const auto dir = scratch("clock");
  const std::string file = assemble(dir, "clock", kTimeTwice);
  ASSERT_FALSE(file.empty());
  const Booted simulated = boot(dir, file, "--clock-start 1000000000");
  EXPECT_EQ(simulated.output.exit_code, 2) << simulated.output.out;
  // Waiting for the timer, the processor is idle, not busy: 2.5 s of the run's 2.5 s and a bit.
  ASSERT_TRUE(simulated.report.is_object()) << simulated.output.out;
  const auto& p0 = simulated.report["processors"][0];
  EXPECT_GT(p0["idle_us"].get<double>(), 2.5e6 - 100) << p0;
  EXPECT_LT(p0["busy_us"].get<double>(), 1000) << p0;
  const Booted host = boot(dir, file, "--clock host");
  EXPECT_NE(host.output.exit_code, 2) << host.output.out;
  const Booted wrong = boot(dir, file, "--clock wall");
  EXPECT_EQ(wrong.output.exit_code, 2) << wrong.output.out;  // a usage error
  EXPECT_NE(wrong.output.out.find("--clock"), std::string::npos) << wrong.output.out;
}

// A profile counts what ran as the datasheet prices it: a loop of 100 rounds around hello.s's
// SP.WRITE. adc -1 is nfix 0; adc 15, one cycle each (T800 datasheet); cj is 2 cycles when it
// falls through (99 times) and 4 when it jumps (once). While the host answers, the processor waits
// for its host link.
TEST(Boot, AProfileTalliesOperationsAsTheDatasheetPricesThem) {
  const auto dir = scratch("profile");
  std::string source = example_with("hello.s", {});
  const std::string start = "start:  ajw 16";
  const auto at = source.find(start);
  ASSERT_NE(at, std::string::npos);
  source.insert(at + start.size(), R"(
        ldc 100
        stl 0
round:  ldl 0
        adc -1
        stl 0
        ldl 0
        cj rounds.done
        j round
rounds.done:)");
  const std::string file = assemble(dir, "loop", source);
  ASSERT_FALSE(file.empty());
  const fs::path profile = dir / "profile.json";
  const Booted b = boot(dir, file, "--profile " + profile.string());
  EXPECT_EQ(b.output.exit_code, 0) << b.output.out;
  std::ifstream in(profile);
  ASSERT_TRUE(in) << b.output.out;
  const auto json = nlohmann::json::parse(in);
  const auto& p = json["processors"][0];
  auto op = [&](const std::string& name) {
    for (const auto& o : p["operations"])
      if (o["op"] == name) return o;
    return nlohmann::json{};
  };
  EXPECT_EQ(op("adc")["count"], 100) << p;
  EXPECT_EQ(op("adc")["cycles"], 100 * (1 + 1)) << p;
  EXPECT_EQ(op("cj")["count"], 100) << p;
  EXPECT_EQ(op("cj")["cycles"], 99 * 2 + 4) << p;
  EXPECT_EQ(op("j")["count"], 99) << p;
  std::int64_t counted = 0;
  for (const auto& o : p["operations"]) counted += o["count"].get<std::int64_t>();
  EXPECT_EQ(counted, p["instructions"].get<std::int64_t>()) << p;
  const double host_wait = p["waiting_us"]["link 0 (host) input"].get<double>();
  EXPECT_GT(host_wait, 0) << p;
  // Waiting for the host's reply, the CPU is idle: in the report as in the profile.
  const auto& reported = b.report["processors"][0];
  EXPECT_GE(reported["idle_us"].get<double>(), host_wait - 1e-6) << reported;
  ASSERT_FALSE(p["hot_code"].empty()) << p;
  // The loop is the hottest code: its block holds the first instruction of the loop.
  const auto loop = std::stoul(p["hot_code"][0]["from"].get<std::string>().substr(1), nullptr, 16);
  EXPECT_LE(loop, 0x80000070u + 16) << p;
  // And tools/plot draws it (where Debian's python3-matplotlib is installed, as the plot tests).
  if (std::system("/usr/bin/python3 -c 'import matplotlib' 2>/dev/null") != 0) return;
  const std::string plot = "cd " + test_paths::source_dir() +
                           " && timeout 120 tools/plot profile " + profile.string() + " -o " +
                           (dir / "profile.png").string();
  EXPECT_EQ(std::system(plot.c_str()), 0) << plot;
  EXPECT_TRUE(fs::exists(dir / "profile.png"));
}

TEST(Boot, InputOnALinkToNothingIsADeadlockNamingTheProcess) {
  const auto dir = scratch("deadlock");
  const Booted b = boot(dir, assemble(dir, "wait", "ajw 8\nldlp 0\nldc #80000014\nldc 4\nin\n"));
  EXPECT_EQ(b.output.exit_code, 1) << b.output.out;
  EXPECT_NE(b.output.out.find("input on channel #80000014"), std::string::npos) << b.output.out;
}

TEST(Boot, LimitsEndAProgramThatNeverStops) {
  const auto dir = scratch("forever");
  const std::string file = assemble(dir, "forever", "ajw 8\nloop: j loop\n");
  const Booted by_count = boot(dir, file, "--max-instructions 100000");
  EXPECT_EQ(by_count.output.exit_code, 4) << by_count.output.out;
  EXPECT_NE(by_count.output.out.find("--max-instructions 100000"), std::string::npos);
  const Booted by_time = boot(dir, file, "--max-simulated-s 0.01");
  EXPECT_EQ(by_time.output.exit_code, 4) << by_time.output.out;
  EXPECT_NE(by_time.output.out.find("--max-simulated-s"), std::string::npos);
}

TEST(Boot, ASceneRunsABootFileAsAWorkload) {
  const auto dir = scratch("scene");
  const std::string file = assemble(dir, "chain", example_with("chain.s", {{"iterations", "500"}}));
  write_text(dir / "chain.toml", "name = \"boot-chain\"\n[network]\ntopology = \"" + kTopologies +
                                     "pipeline-6.toml\"\n[workload]\nkind = \"boot\"\nfile = \"" +
                                     file + "\"\n");
  const auto o =
      cli_test::run("run " + (dir / "chain.toml").string() + " --json --max-wall-time 60 2>&1");
  EXPECT_EQ(o.exit_code, 0) << o.out;
  EXPECT_NE(o.out.find("\"exit_status\": 6"), std::string::npos) << o.out;
}

TEST(Asm, AnErrorInTheSourceNamesLineAndColumn) {
  const auto dir = scratch("asm");
  write_text(dir / "bad.s", "ajw 8\n  ldc nowhere\n");
  const auto o = cli_test::run("asm " + (dir / "bad.s").string() + " -o " +
                               (dir / "bad.btl").string() + " 2>&1");
  EXPECT_EQ(o.exit_code, 2) << o.out;
  EXPECT_NE(o.out.find("bad.s:2:"), std::string::npos) << o.out;
  EXPECT_FALSE(fs::exists(dir / "bad.btl"));
}

}  // namespace
