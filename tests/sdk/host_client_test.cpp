// A process on the host (ProcessDecl::placed_on_host): a built-in workload's client, spawned by the
// simulator's caller, declared in the program only so that its channels reach it -- as Table 6's
// host feeds the elimination pipeline.
#include <gtest/gtest.h>

#include "network/machine.hpp"
#include "sdk/realise.hpp"
#include "sdk_fixtures.hpp"

namespace {

using namespace t800sim;

// The host sends 7 to a worker on P1 (two hops: host - P0 - P1), which sends back 7 * 6.
TEST(HostClient, AProcessOnTheHostTalksToTheProgramOverTheHostLink) {
  const network::Topology topology = sdk_test::chain(1);
  network::Machine machine(topology, {});
  Builder b(topology);
  const Chan<INT> to = b.channel<INT>("to", "client", "worker");
  const Chan<INT> back = b.channel<INT>("back", "worker", "client");
  b.process("client", nullptr).placed_on_host();
  b.process("worker", [to, back](Process& p) { p.out(back, 6 * p.in(to)); }).placed_on("P1");
  const auto placed = detail::realise("test", b, machine, {});
  ASSERT_EQ(placed.size(), 2u);
  EXPECT_EQ(placed[0].node, network::Machine::kHost);
  EXPECT_EQ(placed[0].placed_by, "the program (the host)");
  INT got = 0;
  machine.spawn(network::Machine::kHost, "client", t800::Priority::low,
                [&](network::Process& impl) {
                  Process p(impl);
                  p.out(to, 7);
                  got = p.in(back);
                });
  EXPECT_TRUE(machine.run().empty());
  EXPECT_EQ(got, 42);
}

// Only a process its caller spawns runs on the host: one with a body there is an error.
TEST(HostClient, AProcessWithABodyIsNotPlacedOnTheHost) {
  const network::Topology topology = sdk_test::chain(1);
  network::Machine machine(topology, {});
  Builder b(topology);
  b.process("client", [](Process&) {}).placed_on_host();
  EXPECT_THROW(detail::realise("test", b, machine, {}), std::invalid_argument);
}

}  // namespace
