// INT expressions compiled onto the integer stack, against sequences derived by hand from the
// INMOS occam compiler's back end (occ21, concurrency/kroc tools/occ21/be: gen4.c tdop for the
// operators and their evaluation order, gen7.c trelop and tguard for comparisons and the IF's cj,
// code1k.c genshiftimmediate for constant shifts, tran1.c for the checked shift count and the
// unchecked product) and the compiler writer's guide's instruction definitions. Compiled with
// occam's default run-time checks unless a test says otherwise. Variables a..h are workspace
// words 2..9 (after the integer variable and the constant table's pointer), x and y INT arrays
// reached through pointers in words 10 and 11, of 8 elements each.
#include <gtest/gtest.h>

#include "tests/codegen/codegen_fixtures.hpp"
#include "workloads/occam/subscript.hpp"

namespace {

using codegen_test::body_code;
using codegen_test::compile_int;
using codegen_test::Int;  // t800sim::Int
using t800::codegen::CodeUnit;
using t800::codegen::Target;
using Seq = std::vector<std::string>;

TEST(GeneratedIntegerCode, ASumIsLoadedAddedAndStoredThroughThePointer) {
  const CodeUnit u = compile_int([](Int& a, Int& b, auto&, auto&, auto&, auto&, auto&, auto&,
                                    auto& x, auto&) { x[0] = a + b; });
  EXPECT_EQ(body_code(u), (Seq{"ldl 2", "ldl 3", "add", "ldl 10", "stnl 0"}));
}

TEST(GeneratedIntegerCode, AConstantOperandIsAdcOrEqc) {
  const CodeUnit minus = compile_int([](Int& a, auto&, auto&, auto&, auto&, auto&, auto&, auto&,
                                        auto& x, auto&) { x[1] = a - Int(5); });
  EXPECT_EQ(body_code(minus), (Seq{"ldl 2", "adc -5", "ldl 10", "stnl 1"}));
  const CodeUnit test =
      compile_int([](Int& a, auto&, Int& c, auto&, auto&, auto&, auto&, auto&, auto&, auto&) {
        if (a == Int(1)) c = Int(0);
      });
  EXPECT_EQ(body_code(test), (Seq{"ldl 2", "eqc 1", "cj 4", "ldc 0", "stl 4"}));
}

// tdop: the left operand first unless the right needs the whole stack; for a commutative
// operation the one loaded by a single instruction goes last (so no rev is ever needed there).
TEST(GeneratedIntegerCode, TheLeftOperandFirstButACommutativeOnesLoadLast) {
  const CodeUnit u = compile_int([](Int& a, Int& b, Int& c, auto&, auto&, auto&, auto&, auto&,
                                    auto& x, auto&) { x[0] = a - b * c; });
  EXPECT_EQ(body_code(u), (Seq{"ldl 2", "ldl 3", "ldl 4", "mul", "sub", "ldl 10", "stnl 0"}));
  const CodeUnit commutative = compile_int([](Int& a, Int& b, Int& c, auto&, auto&, auto&, auto&,
                                              auto&, auto& x, auto&) { x[0] = a + b * c; });
  EXPECT_EQ(body_code(commutative),
            (Seq{"ldl 3", "ldl 4", "mul", "ldl 2", "add", "ldl 10", "stnl 0"}));
  // The right operand needing all three registers goes first, then rev.
  const CodeUnit deep = compile_int([](Int& a, Int& b, Int& c, Int& d, Int& e, auto&, auto&, auto&,
                                       auto& x, auto&) { x[0] = a - (b * c - d * e); });
  EXPECT_EQ(body_code(deep), (Seq{"ldl 3", "ldl 4", "mul", "ldl 5", "ldl 6", "mul", "sub", "ldl 2",
                                  "rev", "sub", "ldl 10", "stnl 0"}));
}

// trelop: a > b is gt with a in B, a < b is b > a; >= and <= are those negated (eqc 0); = is
// diff then eqc 0, <> the diff alone; cj jumps when the condition is false.
TEST(GeneratedIntegerCode, ComparisonsAreGtAndDiffAndTheIfIsCj) {
  const CodeUnit u =
      compile_int([](Int& a, Int& b, Int& c, auto&, auto&, auto&, auto&, auto&, auto&, auto&) {
        if (a < b) c = a;   // 1 < 2: true
        if (a == b) c = b;  // false
      });
  EXPECT_EQ(body_code(u), (Seq{"ldl 3", "ldl 2", "gt", "cj 4", "ldl 2", "stl 4", "ldl 2", "ldl 3",
                               "diff", "eqc 0", "cj 4"}));
  int taken = 0;
  for (const auto& run : u.runs)
    for (const auto& in : run.code)
      if (in.op == t800::isa::Op::cj) taken += int(in.param);
  EXPECT_EQ(taken, 1);  // the second IF's condition was false: its cj jumps
  const CodeUnit negated =
      compile_int([](Int& a, Int& b, auto&, auto&, auto&, auto&, auto&, auto&, auto&, auto&) {
        if (a >= b) {
        }
        if (a <= b) {
        }
        if (a != b) {
        }
        if (a != Int(0)) {
        }
      });
  EXPECT_EQ(body_code(negated),
            (Seq{"ldl 3", "ldl 2", "gt", "eqc 0", "cj 4", "ldl 2", "ldl 3", "gt", "eqc 0", "cj 4",
                 "ldl 2", "ldl 3", "diff", "cj 4", "ldl 2", "cj 4"}));
}

// genshiftimmediate and tdop's special cases: << 1 is dup; bsub, << 2 bcnt, << 3 ldc 0; wsubdb,
// >> k ldc k; shr; a * 2 is dup; add; a constant factor, not loaded from memory, goes before the
// variable (tdop's tie-break: the operand loaded from memory last).
TEST(GeneratedIntegerCode, ConstantShiftsAndDoublingHaveTheirOwnShapes) {
  const CodeUnit u =
      compile_int([](Int& a, auto&, auto&, auto&, auto&, auto&, auto&, auto&, auto& x, auto&) {
        x[0] = a << Int(1);
        x[1] = a << Int(2);
        x[2] = a << Int(3);
        x[3] = a >> Int(3);
        x[4] = a * Int(2);
        x[5] = Int(5) * a;
      });
  EXPECT_EQ(body_code(u),
            (Seq{"ldl 2",  "dup",    "bsub",   "ldl 10", "stnl 0", "ldl 2",  "bcnt",   "ldl 10",
                 "stnl 1", "ldl 2",  "ldc 0",  "wsubdb", "ldl 10", "stnl 2", "ldl 2",  "ldc 3",
                 "shr",    "ldl 10", "stnl 3", "ldl 2",  "dup",    "add",    "ldl 10", "stnl 4",
                 "ldc 5",  "ldl 2",  "mul",    "ldl 10", "stnl 5"}));
}

// Without run-time checks a product is prod, whose time is the highest set bit of A (b + 4).
TEST(GeneratedIntegerCode, AnUncheckedProductIsProdTimedByItsOperand) {
  const CodeUnit u = compile_int([](Int& a, Int&, Int&, Int&, Int&, Int& f, auto&, auto&, auto& x,
                                    auto&) { x[0] = a * f; },  // f = 6: bit 2
                                 Target{true, false});
  EXPECT_EQ(body_code(u), (Seq{"ldl 2", "ldl 7", "prod", "ldl 10", "stnl 0"}));
  for (const auto& run : u.runs)
    for (const auto& in : run.code)
      if (in.op == t800::isa::Op::prod) EXPECT_EQ(in.param, 2);
}

// A shift's time depends on the places shifted: the count as the run had it is its parameter.
TEST(GeneratedIntegerCode, AShiftCarriesItsCountAsTheRunHadIt) {
  const CodeUnit u = compile_int([](Int& a, auto&, auto&, auto&, auto&, auto&, auto&, Int& h,
                                    auto& x, auto&) { x[0] = a << h; });  // h = 8
  // A computed count is checked against 0..32 (tran1.c: CSUB0 (n, 33)).
  EXPECT_EQ(body_code(u), (Seq{"ldl 2", "ldl 9", "ldc 33", "csub0", "shl", "ldl 10", "stnl 0"}));
  for (const auto& run : u.runs)
    for (const auto& in : run.code)
      if (in.op == t800::isa::Op::shl) EXPECT_EQ(in.param, 8);
}

// bind2.c mapdop: two operands that each need all three registers (a product less a product):
// the right one goes to a temporary (word 12, the first after the arrays' pointers), the left is
// computed, the temporary loaded, no rev.
TEST(GeneratedIntegerCode, BothOperandsThreeDeepSpillTheRightOne) {
  const CodeUnit u = compile_int([](Int& a, Int& b, Int& c, Int& d, Int& e, Int& f, Int& g, Int& h,
                                    auto& x, auto&) { x[0] = (a * b - c * d) - (e * f - g * h); });
  EXPECT_EQ(body_code(u), (Seq{"ldl 6", "ldl 7", "mul", "ldl 8", "ldl 9", "mul", "sub", "stl 12",
                               "ldl 2", "ldl 3", "mul", "ldl 4", "ldl 5", "mul", "sub", "ldl 12",
                               "sub", "ldl 10", "stnl 0"}));
}

// A subscript the kernel computes (occam::at): evaluated onto the integer stack, checked against
// the array's bound (ldc 8; csub0, CWG "range checking") and scaled onto the array's base by wsub
// (CWG: x[i] is i; the base; wsub); the element then loaded or stored by ldnl 0 / stnl 0.
TEST(GeneratedIntegerCode, AComputedSubscriptIsEvaluatedCheckedAndScaledByWsub) {
  const CodeUnit load = compile_int([](Int& a, auto&, auto&, auto&, auto&, auto&, auto&, auto&,
                                       auto& x, auto& y) { x[0] = occam::at(y, a); });
  EXPECT_EQ(body_code(load),
            (Seq{"ldl 2", "ldc 8", "csub0", "ldl 11", "wsub", "ldnl 0", "ldl 10", "stnl 0"}));
  const CodeUnit unchecked =
      compile_int([](Int& a, Int& b, auto&, auto&, auto&, auto&, auto&, auto&, auto& x,
                     auto& y) { x[0] = occam::at(y, a + b); },
                  Target{true, false, true});
  EXPECT_EQ(body_code(unchecked),
            (Seq{"ldl 2", "ldl 3", "add", "ldl 11", "wsub", "ldnl 0", "ldl 10", "stnl 0"}));
  // The value first, then the element's address onto it (stnl stores B at A).
  const CodeUnit store = compile_int([](Int& a, Int& b, auto&, auto&, auto&, auto&, auto&, auto&,
                                        auto& x, auto&) { occam::at(x, a) = b; });
  EXPECT_EQ(body_code(store),
            (Seq{"ldl 3", "ldl 2", "ldc 8", "csub0", "ldl 10", "wsub", "stnl 0"}));
  // A subscript read from an array: y[x[a]], the inner element's address computed first.
  const CodeUnit nested =
      compile_int([](Int& a, Int& b, auto&, auto&, auto&, auto&, auto&, auto&, auto& x, auto& y) {
        x[1] = a;  // x[1] := 1, so x[a] is 1
        b = occam::at(y, occam::at(x, a));
      });
  EXPECT_EQ(body_code(nested),
            (Seq{"ldl 2", "ldl 10", "stnl 1", "ldl 2", "ldc 8", "csub0", "ldl 10", "wsub", "ldnl 0",
                 "ldc 8", "csub0", "ldl 11", "wsub", "ldnl 0", "stl 3"}));
}

// An element's address that needs the whole stack goes first when it is stored into: the value
// onto it and rev (stnl stores B at A); a value that needs the whole stack too waits in a
// workspace word. Rules derived from the stack's depth (occ21's own choice for this shape was not
// checked).
TEST(GeneratedIntegerCode, AStoreThroughADeepSubscriptComputesTheAddressFirst) {
  const CodeUnit u = compile_int([](Int& a, Int& b, Int& c, Int& d, auto&, auto&, auto&, auto&,
                                    auto& x, auto&) { occam::at(x, d * b - c * b) = a; });
  const Seq address{"ldl 5", "ldl 3", "mul",   "ldl 4",  "ldl 3", "mul",
                    "sub",   "ldc 8", "csub0", "ldl 10", "wsub"};
  Seq expected = address;
  for (const char* s : {"ldl 2", "rev", "stnl 0"}) expected.push_back(s);
  EXPECT_EQ(body_code(u), expected);
  const CodeUnit both =
      compile_int([](Int& a, Int& b, Int& c, Int& d, auto&, auto&, auto&, auto&, auto& x, auto&) {
        occam::at(x, d * b - c * b) = a * b - c * a;  // 2 - 3
      });
  const Seq code = body_code(both);
  ASSERT_EQ(code.size(), 7u + 1u + address.size() + 3u);
  EXPECT_EQ(Seq(code.begin(), code.begin() + 7),
            (Seq{"ldl 2", "ldl 3", "mul", "ldl 4", "ldl 2", "mul", "sub"}));
  const std::string hold = code[7];
  ASSERT_EQ(hold.rfind("stl ", 0), 0u) << hold;
  EXPECT_GE(std::stoi(hold.substr(4)), 12) << "a word of its own, past the variables";
  EXPECT_EQ(Seq(code.begin() + 8, code.end() - 3), address);
  EXPECT_EQ(Seq(code.end() - 3, code.end()), (Seq{"ldl " + hold.substr(4), "rev", "stnl 0"}));
}

// A subscript that is a constant is the element itself: no code computes it.
TEST(GeneratedIntegerCode, AConstantSubscriptIsTheElement) {
  const CodeUnit u = compile_int([](Int& a, auto&, auto&, auto&, auto&, auto&, auto&, auto&,
                                    auto& x, auto& y) { x[0] = occam::at(y, Int(5)) + a; });
  EXPECT_EQ(body_code(u), (Seq{"ldl 11", "ldnl 5", "ldl 2", "add", "ldl 10", "stnl 0"}));
}

// The loop's index as an Int (for (Int i : seq(n))) is the loop's index in the code: `ldl i`, the
// same in every iteration, so the iterations compile to one body, as occam's SEQ i = 0 FOR n does.
// at(x, i) is then the element the loop-indexed subscript x[i] is, in the same code.
TEST(GeneratedIntegerCode, TheLoopsIndexAsAnIntIsTheSameCodeInEveryIteration) {
  const CodeUnit by_int =
      compile_int([](Int& a, auto&, auto&, auto&, auto&, auto&, auto&, auto&, auto& x, auto& y) {
        for (Int i : occam::seq<Int>(8)) occam::at(x, i) = occam::at(y, i) + a;
      });
  const CodeUnit by_index =
      compile_int([](Int& a, auto&, auto&, auto&, auto&, auto&, auto&, auto&, auto& x, auto& y) {
        for (std::size_t i : occam::seq<Int>(8)) x[i] = y[i] + a;
      });
  EXPECT_EQ(body_code(by_int), body_code(by_index));
  EXPECT_EQ(by_int.code_bytes, by_index.code_bytes);
  const auto strided = [](int n) {
    return compile_int([n](Int&, Int& b, auto&, auto&, auto&, auto&, auto&, auto&, auto& x, auto&) {
      for (Int i : occam::seq<Int>(std::size_t(n))) occam::at(x, i * Int(2)) = b + i;
    });
  };
  // In memory once whatever the count: ldc 3 and ldc 4 are one byte each.
  EXPECT_EQ(strided(3).code_bytes, strided(4).code_bytes);
  // SEQ i = 0 FOR 2: ldc 0; stl 0; ldc 2; stl 1 (the control block in words 0 and 1, so the
  // variables from word 4 and x's pointer in word 12); then x[i * 2] := b + i; ldlp 0; ldc; lend.
  const Seq code = body_code(strided(2));
  ASSERT_EQ(code.size(), 4u + 2u * (11u + 3u));
  const Seq body{"ldl 5", "ldl 0", "add",    "ldl 0", "dup",   "add",
                 "ldc 8", "csub0", "ldl 12", "wsub",  "stnl 0"};
  EXPECT_EQ(Seq(code.begin() + 4, code.begin() + 15), body);
  EXPECT_EQ(Seq(code.begin() + 18, code.begin() + 29), body);
  EXPECT_EQ(code.back(), "lend");
}

// A declared variable is a workspace word whatever the loop: in a SEQ of one iteration, where no
// second iteration shows its subscript constant, it is still ldl/stl, never subscripted by the
// loop's index (issue 25's `ur :=` compiled as `ldl 0; ldc 1; csub0; ldlp 12; wsub`).
TEST(GeneratedIntegerCode, AVariableInASeqOfOneIterationIsAWorkspaceWord) {
  const CodeUnit u =
      compile_int([](Int& a, auto&, Int& c, auto&, auto&, auto&, auto&, auto&, auto&, auto& y) {
        for (std::size_t i : occam::seq<Int>(1)) c = a + y[i];
      });
  // The control block in words 0 and 1, a in word 4, c in word 6, y's pointer in word 13; the
  // commutative add loads a (one instruction) last; y[i], the bare index of a known SEQ, is not
  // range-checked.
  const Seq code = body_code(u);
  ASSERT_GE(code.size(), 11u);
  EXPECT_EQ(Seq(code.begin() + 4, code.begin() + 11),
            (Seq{"ldl 0", "ldl 13", "wsub", "ldnl 0", "ldl 4", "add", "stl 6"}));
}

}  // namespace
