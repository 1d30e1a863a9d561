// Variables shared by a process's PAR branches (t800sim::Shared): a branch waiting for a condition
// gives up the processor until another branch changes the variables and notifies, then goes on in
// that same instant; the wait and the notify take no simulated time, and the condition is looked
// at only when the branch starts to wait and when notified (no polling).
#include <gtest/gtest.h>

#include "sdk_fixtures.hpp"
#include "t800sim/shared.hpp"

namespace {

using namespace t800sim;
using sdk_test::Lambda;

// The producer first waits for its TIMER, so the waiter certainly runs, finds nothing and waits;
// then the producer computes 2000 cycles (100 us at 20 MHz) with the processor to itself.
TEST(SdkShared, AWaitingBranchGoesOnOnceNotifiedAndTakesNoProcessorMeanwhile) {
  double computing_us = -1, stored_us = -1, woke_us = -1;
  int looks = 0;
  auto* program = new Lambda([&](Builder& b) {
    b.process("p", [&](Process& p) {
      Shared shared;
      int stored = 0;
      p.par({[&](Process& q) {
               q.wait_after(q.timer() + 1);
               computing_us = q.now_us();
               q.compute(2000);
               stored = 1;
               stored_us = q.now_us();
               shared.notify();
             },
             [&](Process& q) {
               shared.wait_until(q, [&] {
                 ++looks;
                 return stored > 0;
               });
               woke_us = q.now_us();
             }});
    });
  });
  const auto o = sdk_test::run(program, sdk_test::chain(1));
  ASSERT_TRUE(o.blocked.empty());
  EXPECT_NEAR(stored_us - computing_us, 100.0, 1e-9);
  // The waiter goes on at once (within a context switch). It looked three times, however long it
  // waited: on the call, once off the processor, and on the one notify.
  EXPECT_GE(woke_us, stored_us);
  EXPECT_LT(woke_us - stored_us, 1.0);
  EXPECT_EQ(looks, 3);
}

TEST(SdkShared, AConditionAlreadyTrueDoesNotWait) {
  double before_us = -1, after_us = -1;
  int looks = 0;
  auto* program = new Lambda([&](Builder& b) {
    b.process("p", [&](Process& p) {
      Shared shared;
      p.compute(100);
      before_us = p.now_us();
      shared.wait_until(p, [&] {
        ++looks;
        return true;
      });
      after_us = p.now_us();
    });
  });
  ASSERT_TRUE(sdk_test::run(program, sdk_test::chain(1)).blocked.empty());
  EXPECT_EQ(after_us, before_us);
  EXPECT_EQ(looks, 1);
}

}  // namespace
