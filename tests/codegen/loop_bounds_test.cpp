// A SEQ's bounds and the range checks of its subscripts, against the shapes the INMOS occam
// compiler gives them: a bare replicator index into an array holding every index the SEQ takes
// is not checked when the SEQ's first index and count are constants (the compiler proves it in
// range), every other subscript is (ldc n; csub0); a count the PROC computes is stored in the
// control block and tested before the loop (ldl count; mint; csub0 stops a negative count, cj
// jumps over a loop of none). With the loop's control block in words 0 and 1, variables a..h are
// words 4..11 and the arrays' pointers x, y words 12 and 13.
#include <gtest/gtest.h>

#include <algorithm>
#include <stdexcept>

#include "tests/codegen/codegen_fixtures.hpp"
#include "workloads/occam/subscript.hpp"

namespace {

using namespace codegen_test;
using Seq = std::vector<std::string>;

long count_of(const Seq& code, const std::string& op) {
  return long(std::count(code.begin(), code.end(), op));
}

// CWG: y[i] is i; y; wsub; the element by ldnl 0. a, loaded by one instruction, goes last.
const Seq kUncheckedBody{"ldl 0", "ldl 13", "wsub",   "ldnl 0", "ldl 4",
                         "add",   "ldl 0",  "ldl 12", "wsub",   "stnl 0"};

TEST(LoopBounds, ABareIndexOfAKnownSeqIsNotChecked) {
  const Seq code = body_code(
      compile_int([](Int& a, auto&, auto&, auto&, auto&, auto&, auto&, auto&, auto& x, auto& y) {
        for (std::size_t i : occam::seq<Int>(8)) x[i] = y[i] + a;
      }));
  // ldc 0; stl 0; ldc 8; stl 1, then the body, ldlp 0; ldc back; lend, eight times.
  ASSERT_EQ(code.size(), 4u + 8u * (kUncheckedBody.size() + 3u));
  EXPECT_EQ(Seq(code.begin() + 4, code.begin() + 4 + long(kUncheckedBody.size())), kUncheckedBody);
  EXPECT_EQ(count_of(code, "csub0"), 0);
}

// The same loop over a part of the arrays (SEQ i = 2 FOR 6 reaches x[7], the last element).
TEST(LoopBounds, AKnownSeqInsideTheArrayIsNotCheckedEither) {
  const Seq code = body_code(
      compile_int([](Int& a, auto&, auto&, auto&, auto&, auto&, auto&, auto&, auto& x, auto& y) {
        for (std::size_t i : occam::seq<Int>(2, 6)) x[i] = y[i] + a;
      }));
  EXPECT_EQ(count_of(code, "csub0"), 0);
  EXPECT_EQ(count_of(code, "lend"), 6);
}

// i + 1 and 6 - i are checked although they stay in range: the compiler proves only the bare
// index (oc checks c[6 - i] in Horner's rule).
TEST(LoopBounds, ASubscriptComputedFromTheIndexIsChecked) {
  const Seq code = body_code(
      compile_int([](Int& a, auto&, auto&, auto&, auto&, auto&, auto&, auto&, auto& x, auto& y) {
        for (std::size_t i : occam::seq<Int>(7)) x[i] = y[i + 1] + a;
      }));
  EXPECT_EQ(count_of(code, "csub0"), 7);  // y[i+1] each iteration; x[i] never
  const Seq by_int = body_code(
      compile_int([](Int& a, auto&, auto&, auto&, auto&, auto&, auto&, auto&, auto& x, auto& y) {
        for (Int i : occam::seq<Int>(7)) occam::at(x, i) = occam::at(y, Int(6) - i) + a;
      }));
  EXPECT_EQ(count_of(by_int, "csub0"), 7);
  // Without run-time checks, none.
  const Seq unchecked = body_code(compile_int(
      [](Int& a, auto&, auto&, auto&, auto&, auto&, auto&, auto&, auto& x, auto& y) {
        for (std::size_t i : occam::seq<Int>(7)) x[i] = y[i + 1] + a;
      },
      Target{true, false}));
  EXPECT_EQ(count_of(unchecked, "csub0"), 0);
}

// SEQ i = 0 FOR n, n a variable (h = 8): the count is loaded into the control block and tested
// (oc's DAXPY over open arrays), and the index's subscripts are checked, as the compiler cannot
// prove them.
TEST(LoopBounds, AVariableCountIsTestedAndItsSubscriptsChecked) {
  const CodeUnit u =
      compile_int([](Int& a, auto&, auto&, auto&, auto&, auto&, auto&, Int& n, auto& x, auto& y) {
        for (std::size_t i : occam::seq<Int>(n)) x[i] = y[i] + a;
      });
  const Seq code = body_code(u);
  const Seq prologue{"ldc 0", "stl 0", "ldl 11", "stl 1", "ldl 1", "mint", "csub0"};
  ASSERT_GT(code.size(), prologue.size() + 1);
  EXPECT_EQ(Seq(code.begin(), code.begin() + long(prologue.size())), prologue);
  EXPECT_EQ(code[prologue.size()].rfind("cj ", 0), 0u);
  const Seq body{"ldl 0", "ldc 8", "csub0", "ldl 13", "wsub",   "ldnl 0", "ldl 4",
                 "add",   "ldl 0", "ldc 8", "csub0",  "ldl 12", "wsub",   "stnl 0"};
  EXPECT_EQ(Seq(code.begin() + 8, code.begin() + 8 + long(body.size())), body);
  EXPECT_EQ(count_of(code, "lend"), 8);
  // The test jumps over the loop's code: one iteration's bytes, its lend included.
  std::int64_t over = -1, iteration_bytes = 0;
  for (const auto& run : u.runs)
    for (const auto& in : run.code) {
      if (in.op == Op::cj) over = in.operand;
      if (run.times > 1) iteration_bytes += in.bytes();
    }
  EXPECT_EQ(over, iteration_bytes);
  // Without run-time checks the count is still tested for none, but not for a negative count.
  const Seq unchecked = body_code(compile_int(
      [](Int& a, auto&, auto&, auto&, auto&, auto&, auto&, Int& n, auto& x, auto& y) {
        for (std::size_t i : occam::seq<Int>(n)) x[i] = y[i] + a;
      },
      Target{true, false}));
  EXPECT_EQ(Seq(unchecked.begin(), unchecked.begin() + 5),
            (Seq{"ldc 0", "stl 0", "ldl 11", "stl 1", "ldl 1"}));
  EXPECT_EQ(unchecked[5].rfind("cj ", 0), 0u);
  EXPECT_EQ(count_of(unchecked, "csub0"), 0);
}

// A count of none (a - a, computed): the cj is taken and the loop, never run, has no code to jump
// over.
TEST(LoopBounds, AVariableCountOfNoneJumpsOverTheLoop) {
  const CodeUnit u =
      compile_int([](Int& a, auto&, auto&, auto&, auto&, auto&, auto&, auto&, auto& x, auto& y) {
        for (std::size_t i : occam::seq<Int>(a - a)) x[i] = y[i] + a;
      });
  const Seq code = body_code(u);
  EXPECT_EQ(count_of(code, "lend"), 0);
  int taken = 0;
  for (const auto& run : u.runs)
    for (const auto& in : run.code)
      if (in.op == Op::cj) {
        EXPECT_EQ(in.operand, 0);
        taken += int(in.param);
      }
  EXPECT_EQ(taken, 1);
}

// SEQ i = k FOR n - k (oc's elimination row update), k = f = 6 and n = h = 8: both computed,
// the count's expression evaluated into the control block (n first: sub is not commutative).
TEST(LoopBounds, AComputedFirstIndexAndCountAreEvaluated) {
  const Seq code = body_code(
      compile_int([](Int& a, auto&, auto&, auto&, auto&, Int& k, auto&, Int& n, auto& x, auto& y) {
        for (std::size_t i : occam::seq<Int>(k, n - k)) x[i] = y[i] + a;
      }));
  const Seq prologue{"ldl 9", "stl 0", "ldl 11", "ldl 9", "sub", "stl 1", "ldl 1", "mint", "csub0"};
  ASSERT_GT(code.size(), prologue.size());
  EXPECT_EQ(Seq(code.begin(), code.begin() + long(prologue.size())), prologue);
  EXPECT_EQ(count_of(code, "lend"), 2);           // i = 6, 7
  EXPECT_EQ(count_of(code, "csub0"), 1 + 2 * 2);  // the count, then x[i] and y[i] twice
}

TEST(LoopBounds, ANegativeCountIsAnError) {
  EXPECT_THROW(compile_int([](Int&, auto&, auto&, auto&, auto&, auto&, auto&, auto&, auto&, auto&) {
                 for (std::size_t i : occam::seq<Int>(Int(0) - Int(1))) (void)i;
               }),
               std::out_of_range);
}

}  // namespace
