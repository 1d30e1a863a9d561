// occam's STOP through the SDK (Process::stop): the process stops for ever where it is -- nothing
// after it runs, it takes no more processor time -- and the run's report of blocked processes names
// it with the reason, and the partner left waiting for it.
#include <gtest/gtest.h>

#include "sdk_fixtures.hpp"

namespace {

using namespace t800sim;
using sdk_test::Lambda;

const network::BlockedProcess* find(const std::vector<network::BlockedProcess>& blocked,
                                    const std::string& name) {
  for (const auto& b : blocked)
    if (b.process == name) return &b;
  return nullptr;
}

TEST(SdkStop, AStoppedProcessEndsWhereItIsAndTheReportSaysWhy) {
  bool went_on = false;
  double stopped_us = -1, other_done_us = -1;
  auto* program = new Lambda([&](Builder& b) {
    const auto c = b.channel<INT>("c", "checker", "reader");
    b.process("checker", [&, c](Process& p) {
      stopped_us = p.now_us();
      p.stop("row number 9 out of range");
      went_on = true;  // never
      p.out(c, 1);
    });
    // On the same processor: had the stopped process kept the CPU, 2000 cycles at 20 MHz would
    // take longer than 100 us.
    b.process("other", [&](Process& p) {
      p.compute(2000);
      other_done_us = p.now_us();
    });
    b.process("reader", [c](Process& p) { p.in(c); }).placed_on("P1");
  });
  const auto o = sdk_test::run(program, sdk_test::chain(1));
  EXPECT_FALSE(went_on);
  EXPECT_GE(stopped_us, 0);
  EXPECT_GE(other_done_us, 100.0);
  EXPECT_LT(other_done_us, 101.0);  // + starting the processes (a few cycles)
  ASSERT_EQ(o.blocked.size(), 2u);
  const auto* checker = find(o.blocked, "checker");
  ASSERT_NE(checker, nullptr);
  EXPECT_NE(checker->status.find("row number 9 out of range"), std::string::npos)
      << checker->status;
  ASSERT_NE(find(o.blocked, "reader"), nullptr);  // waits on c for ever
}

}  // namespace
