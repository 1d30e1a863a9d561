// Commstime (examples/commstime/, built here as a plugin from the same source) against its cost
// derived by hand from the T800 datasheet's instruction table (docs/t800-timing.md sections 2 and
// 3), and on four processors against the time its ring of links cannot beat.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "../cli/cli_fixtures.hpp"
#include "tests/test_paths.hpp"

namespace {

constexpr double kCycleUs = 0.050;  // a T800-20: 20 MHz

// One internal channel communication of an INT (one word), as the simulator's model compiles it
// (ldlp buffer; ldl channel; ldc length; in/out): the first party's in/out deschedules (19 cycles),
// the second copies the word (2w + 19 = 21). ldlp and ldc 4 take 1 cycle, ldl 2.
constexpr int kFirstParty = 1 + 2 + 1 + 19;
constexpr int kSecondParty = 1 + 2 + 1 + (2 * 1 + 19);
constexpr int kCommunication = kFirstParty + kSecondParty;
// The code around the communications, as the plugin charges it through the operation-mix model: a
// loop-closing jump priced as a taken cj (4), adc (1), lend looping (10); startp 12, endp 13.
constexpr int kJump = 4, kAdc = 1, kLend = 10, kStartp = 12, kEndp = 13;

nlohmann::json run_commstime(const std::string& scene, const std::string& settings) {
  const auto o = cli_test::run("run examples/commstime/" + scene +
                               " --json --set workload.plugin=" + test_paths::plugin_dir() +
                               "/commstime.so " + settings);  // stdout only: the JSON
  EXPECT_EQ(o.exit_code, 0) << o.out;
  return nlohmann::json::parse(o.out)["workload"];
}

// A loop on one processor: four communications, three WHILE TRUE jumps (prefix, delta, successor),
// successor's adc, consume's lend; with PAR delta, two branches started and ended. The processor is
// never idle, so a loop takes exactly the sum; the timed window may start and end at different
// points of a loop, which is less than one loop over the whole run.
TEST(Commstime, OneProcessorLoopIsTheSumOfItsInstructions) {
  const int loops = 1000;
  const int seq_cycles = 4 * kCommunication + 3 * kJump + kAdc + kLend;
  const int par_cycles = seq_cycles + 2 * kStartp + 2 * kEndp;
  for (const auto& [delta, cycles] : {std::pair{"seq", seq_cycles}, std::pair{"par", par_cycles}}) {
    const auto w =
        run_commstime("commstime-1.toml", "--set workload.loops=" + std::to_string(loops) +
                                              " --set workload.delta=" + delta);
    const double loop_us = cycles * kCycleUs;
    EXPECT_NEAR(w["us_per_loop"].get<double>(), loop_us, loop_us / loops) << delta;
    EXPECT_EQ(w["last_value"].get<int>(), 16 + loops - 1);  // consume got every value, in order
  }
}

// One process per processor: a loop cannot be shorter than its ring (prefix -> delta -> successor
// -> prefix), three link hops, each the writer's out instruction (it loads the link engine: 23
// cycles) and four bytes on a 20 Mbit/s link (each byte an 11-bit packet: 2.2 us).
TEST(Commstime, FourProcessorLoopIsBoundByItsRingOfLinks) {
  const double hop_us = kFirstParty * kCycleUs + 4 * 11 / 20.0;
  const auto w = run_commstime("commstime-4.toml", "--set workload.loops=500");
  EXPECT_GE(w["us_per_loop"].get<double>(), 3 * hop_us);
  EXPECT_EQ(w["last_value"].get<int>(), 16 + 500 - 1);
}

}  // namespace
