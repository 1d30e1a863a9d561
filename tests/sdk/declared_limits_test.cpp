// A program past the stated process and channel limits (network/limits.hpp) is refused where it
// declares the one too many, naming the limit, instead of SystemC failing to set up a stack (E518)
// or the host running out of memory. Nothing here runs a simulation.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "network/limits.hpp"
#include "sdk_fixtures.hpp"

namespace {

using namespace t800sim;

// The message a declaration throws, "" when it is accepted.
template <class Declare>
std::string refusal(Declare declare) {
  try {
    declare();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

const Process::IndexedBody kIdle = [](Process&, int) {};

TEST(DeclaredLimits, ProcessesUpToTheLimitAreDeclaredAndOneMoreIsRefused) {
  const network::Topology topology = sdk_test::chain(2);
  Builder b(topology);
  EXPECT_EQ(refusal([&] { b.processes("w", network::kMaxProcesses - 1, kIdle); }), "");
  EXPECT_EQ(refusal([&] { b.process("last", [](Process&) {}); }), "");
  const std::string e = refusal([&] { b.process("one_more", [](Process&) {}); });
  EXPECT_NE(e.find("process one_more: the program would have " +
                   std::to_string(network::kMaxProcesses + 1) + " processes, more than the " +
                   std::to_string(network::kMaxProcesses) + " one simulation holds"),
            std::string::npos)
      << e;
}

TEST(DeclaredLimits, AHugeGroupIsRefusedBeforeAnythingIsAllocatedForIt) {
  const network::Topology topology = sdk_test::chain(2);
  Builder b(topology);
  const std::string e = refusal([&] { b.processes("w", 1000000000, kIdle); });
  EXPECT_NE(e.find("process w (a group of 1000000000): the program would have 1000000000 "
                   "processes"),
            std::string::npos)
      << e;
  EXPECT_TRUE(b.declared_processes().empty());
  // The refused group left nothing behind: its name is free and the count unchanged.
  EXPECT_EQ(refusal([&] { b.processes("w", network::kMaxProcesses, kIdle); }), "");
}

TEST(DeclaredLimits, ChannelsUpToTheLimitAreDeclaredAndOneMoreIsRefused) {
  const network::Topology topology = sdk_test::chain(2);
  Builder b(topology);
  b.process("a", [](Process&) {});
  b.process("b", [](Process&) {});
  EXPECT_EQ(refusal([&] { b.channels<int>("c", int(network::kMaxChannels), "a", "b"); }), "");
  const std::string e = refusal([&] { b.channel<int>("one_more", "a", "b"); });
  EXPECT_NE(e.find("channel one_more: the program would have more than the " +
                   std::to_string(network::kMaxChannels) + " channels one simulation holds"),
            std::string::npos)
      << e;
  // Naming a channel already declared is no new channel: its other end is still accepted.
  EXPECT_EQ(refusal([&] { b.input<int>("c[7]", "b"); }), "");
  EXPECT_EQ(b.declared_channels().size(), std::size_t(network::kMaxChannels));
}

}  // namespace
