// A T800 message's count is one word, loaded as an INT: a message of more than 2^31 - 1 bytes is
// an error at the send naming the channel, not a wrapped count (2^32 bytes once took 1.55 us).
#include <gtest/gtest.h>

#include <cstdint>
#include <string>

#include "sdk_fixtures.hpp"

// A protocol whose one value is the number of bytes it claims, so a test can send a message of
// any length without holding it.
struct Claimed {};
namespace t800sim {
template <>
struct protocol<Claimed> {
  using value_type = std::int64_t;
  static constexpr bool single = true;
  static std::int64_t bytes(const value_type& v) { return v; }
  static std::string name() { return "CLAIMED"; }
  static void send(detail::Wire& w, value_type v) { detail::send_one(w, v, v); }
  static value_type receive(detail::Wire& w) { return detail::take<value_type>(w); }
};
}  // namespace t800sim

namespace {

using namespace t800sim;

// What a run of one message of `bytes` over a link says: "" when it ran, else its error.
std::string send_error(std::int64_t bytes, double* simulated_us = nullptr) {
  try {
    const sdk_test::Outcome o = sdk_test::run(
        new sdk_test::Lambda([bytes](Builder& b) {
          const auto c = b.channel<Claimed>("big", "writer", "reader");
          b.process("writer", [c, bytes](Process& p) { p.out(c, bytes); }).placed_on("P0");
          b.process("reader", [c](Process& p) { p.in(c); }).placed_on("P1");
        }),
        sdk_test::chain(2));
    if (simulated_us) *simulated_us = o.simulated_us;
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

TEST(MessageSize, TheLargestCountRunsAndTakesItsTime) {
  double us = 0;
  EXPECT_EQ(send_error(2147483647, &us), "");
  // 2^31 - 1 bytes on a 20 Mbit/s link: far more than a second.
  EXPECT_GT(us, 1e6);
}

// One simulation per process: one length per test.
void expect_refused(std::int64_t bytes) {
  const std::string e = send_error(bytes);
  EXPECT_NE(e.find("process writer: a message of " + std::to_string(bytes) +
                   " bytes on channel big: a T800 message is 0 to 2147483647 bytes"),
            std::string::npos)
      << e;
}

TEST(MessageSize, OneByteMoreThanTheLargestCountIsAnErrorNamingTheChannel) {
  expect_refused(2147483648);
}

// Once 1.55 us, less than one byte takes.
TEST(MessageSize, TwoToTheThirtySecondBytesIsAnError) {
  expect_refused(4294967296);
}

}  // namespace
