// OutputOrFail / InputOrFail through the SDK: a communication with a deadline succeeds as out / in
// does when the partner is there in time, gives up at the deadline when it is not, and leaves the
// process free to go on; a protocol's items share the deadline.
#include <gtest/gtest.h>

#include "sdk_fixtures.hpp"

namespace {

using namespace t800sim;
using sdk_test::Lambda;

using Row = Counted<INT, REAL64>;

// A reader on P1 that takes the row in time: the output reports success and the row arrives whole.
TEST(SdkReliable, AnOutputTakenInTimeSucceeds) {
  const value_of<Row> row{1.0, -2.0, 3.5};
  bool ok = false;
  value_of<Row> got;
  auto* program = new Lambda([&](Builder& b) {
    const auto c = b.channel<Row>("c", "sender", "receiver");
    b.process("sender", [&, c](Process& p) { ok = p.out_or_fail(c.out(), row, 1e6); });
    b.process("receiver", [&, c](Process& p) { got = p.in(c); }).placed_on("P1");
  });
  ASSERT_TRUE(sdk_test::run(program, sdk_test::chain(1)).blocked.empty());
  EXPECT_TRUE(ok);
  EXPECT_EQ(got, row);
}

// Nobody reads: the output gives up at its deadline and the sender goes on.
TEST(SdkReliable, AnOutputNobodyTakesFailsAtItsDeadline) {
  bool ok = true;
  double gave_up_us = 0;
  auto* program = new Lambda([&](Builder& b) {
    const auto c = b.channel<INT>("c", "sender", "receiver");
    b.process("sender", [&, c](Process& p) {
      ok = p.out_or_fail(c.out(), 7, 250.0);
      gave_up_us = p.now_us();
    });
    b.process("receiver", [](Process&) {}).placed_on("P1");
  });
  ASSERT_TRUE(sdk_test::run(program, sdk_test::chain(1)).blocked.empty());
  EXPECT_FALSE(ok);
  EXPECT_GE(gave_up_us, 250.0);
  EXPECT_LT(gave_up_us, 260.0);
}

// Nothing arrives: the input gives up at its deadline; something arrives in time: it is the value.
TEST(SdkReliable, AnInputGivesUpAtItsDeadlineOrReturnsTheValue) {
  std::optional<INT> late, early;
  double gave_up_us = 0;
  auto* program = new Lambda([&](Builder& b) {
    const auto c = b.channel<INT>("c", "sender", "receiver");
    b.process("sender",
              [c](Process& p) {
                p.wait_after(p.timer() + 400);  // high priority: 1 us ticks
                p.out(c, 5);
              })
        .placed_on("P1")
        .high();
    b.process("receiver", [&, c](Process& p) {
      late = p.in_or_fail(c.in(), 100.0);
      gave_up_us = p.now_us();
      early = p.in_or_fail(c.in(), 1000.0);
    });
  });
  ASSERT_TRUE(sdk_test::run(program, sdk_test::chain(1)).blocked.empty());
  EXPECT_FALSE(late.has_value());
  EXPECT_GE(gave_up_us, 100.0);
  EXPECT_LT(gave_up_us, 110.0);
  ASSERT_TRUE(early.has_value());
  EXPECT_EQ(*early, 5);
}

// A sequential protocol nobody reads: its first item gives up at the deadline and the second is
// not attempted (the sender goes on at the deadline, not after a second wait).
TEST(SdkReliable, AProtocolGivesUpAtItsFirstItem) {
  bool ok = true;
  double gave_up_us = 0;
  auto* program = new Lambda([&](Builder& b) {
    const auto c = b.channel<Sequential<INT, REAL64>>("c", "sender", "receiver");
    b.process("sender", [&, c](Process& p) {
      ok = p.out_or_fail(c.out(), {1, 2.0}, 300.0);
      gave_up_us = p.now_us();
    });
    b.process("receiver", [](Process&) {}).placed_on("P1");
  });
  ASSERT_TRUE(sdk_test::run(program, sdk_test::chain(1)).blocked.empty());
  EXPECT_FALSE(ok);
  EXPECT_GE(gave_up_us, 300.0);
  EXPECT_LT(gave_up_us, 310.0);
}

// An ALT's InputOrFail guard: chosen when the message arrives, its branch gets the value (the
// writer on another processor, the timer guard later); a false pre-condition leaves the timer.
TEST(SdkReliable, AnAltInputOrFailGuardDeliversTheValue) {
  std::optional<INT> got;
  int chosen = -1, hidden = -1;
  auto* program = new Lambda([&](Builder& b) {
    const auto c = b.channel<INT>("c", "sender", "receiver");
    b.process("sender", [c](Process& p) { p.out(c, 9); }).placed_on("P1");
    b.process("receiver", [&, c](Process& p) {
       hidden = Alt(p)
                    .input_or_fail(
                        c.in(), 50.0, [&](std::optional<INT> v) { got = v; }, false)
                    .after(p.timer() + 5, [] {})
                    .select();
       EXPECT_FALSE(got.has_value());
       chosen = Alt(p)
                    .input_or_fail(c.in(), 50.0, [&](std::optional<INT> v) { got = v; })
                    .after(p.timer() + 100000, [] {})
                    .select();
     }).high();
  });
  ASSERT_TRUE(sdk_test::run(program, sdk_test::chain(1)).blocked.empty());
  EXPECT_EQ(hidden, 1);
  EXPECT_EQ(chosen, 0);
  ASSERT_TRUE(got.has_value());
  EXPECT_EQ(*got, 9);
}

}  // namespace
