// The code generator against sequences derived by hand from the occam compiler's rules (the
// compiler writer's guide's expression evaluation, and code the INMOS compiler emitted for the
// same constructs). Variables a..h are workspace words 2..9 (after the integer variable and the
// constant table's pointer), x and y arrays reached through pointers in words 10 and 11.
#include <gtest/gtest.h>

#include "tests/codegen/codegen_fixtures.hpp"

namespace {

using namespace codegen_test;
using Seq = std::vector<std::string>;

// Rule: an operand comes from memory by fpldnlsn; a product with a memory operand is one
// load-and-multiply; the value is stored after its address is formed.
TEST(GeneratedCode, ProductOfTwoVariablesUsesLoadAndMultiply) {
  const CodeUnit u = compile([](C& a, C& b, auto&...) {}, Target{true, false});
  (void)u;
  const CodeUnit v =
      compile([](C& a, C& b, C&, C&, C&, C&, C&, C&, auto& x, auto&) { x[0] = a * b; });
  EXPECT_EQ(body_code(v),
            (Seq{"ldlp 2", "fpldnlsn", "ldlp 3", "fpldnlmulsn", "ldl 10", "fpstnlsn"}));
}

// Rule: subtraction has no load-and-operate form: the right operand is loaded, then fpsub; a
// constant subscript is an ldnlp from the array's base.
TEST(GeneratedCode, DifferenceLoadsBothOperands) {
  const CodeUnit v =
      compile([](C& a, C& b, C&, C&, C&, C&, C&, C&, auto& x, auto&) { x[1] = a - b; });
  EXPECT_EQ(body_code(v), (Seq{"ldlp 2", "fpldnlsn", "ldlp 3", "fpldnlsn", "fpsub", "ldl 10",
                               "ldnlp 1", "fpstnlsn"}));
}

// Rule: for a non-commutative operation the left operand goes first while the right one fits in
// the registers left; a complex left operand is computed, then the right one loaded.
TEST(GeneratedCode, NonCommutativeOperandsKeepTheirOrder) {
  const CodeUnit left_simple =
      compile([](C&, C& b, C& c, C& d, C&, C&, C&, C&, auto& x, auto&) { x[0] = b - c * d; });
  EXPECT_EQ(fpu_code(left_simple),
            (Seq{"fpldnlsn", "fpldnlsn", "fpldnlmulsn", "fpsub", "fpstnlsn"}));
  const CodeUnit left_complex =
      compile([](C&, C& b, C& c, C& d, C&, C&, C&, C&, auto& x, auto&) { x[0] = c * d - b; });
  EXPECT_EQ(fpu_code(left_complex),
            (Seq{"fpldnlsn", "fpldnlmulsn", "fpldnlsn", "fpsub", "fpstnlsn"}));
  EXPECT_EQ(count(body_code(left_simple), "fprev"), 0);
  EXPECT_EQ(count(body_code(left_complex), "fprev"), 0);
}

// The INMOS compiler's shapes for unary minus (0.0 - x), a square (fpdup) and a halving (the FPU's
// divide by two).
TEST(GeneratedCode, NegationSquareAndHalving) {
  EXPECT_EQ(fpu_code(compile([](C& a, C&, C&, C&, C&, C&, C&, C&, auto& x, auto&) { x[0] = -a; })),
            (Seq{"fpldzerosn", "fpldnlsn", "fpsub", "fpstnlsn"}));
  EXPECT_EQ(
      fpu_code(compile([](C& a, C&, C&, C&, C&, C&, C&, C&, auto& x, auto&) { x[0] = a * a; })),
      (Seq{"fpldnlsn", "fpdup", "fpmul", "fpstnlsn"}));
  EXPECT_EQ(
      fpu_code(compile([](C& a, C&, C&, C&, C&, C&, C&, C&, auto& x, auto&) { x[0] = a / C(2); })),
      (Seq{"fpldnlsn", "fpudivby2", "fpstnlsn"}));
}

// A sign change is folded into the operation that consumes it: a + (-b) is a - b.
TEST(GeneratedCode, SignChangesFoldIntoAdditions) {
  const CodeUnit v =
      compile([](C& a, C& b, C&, C&, C&, C&, C&, C&, auto& x, auto&) { x[0] = a + -b; });
  EXPECT_EQ(fpu_code(v), (Seq{"fpldnlsn", "fpldnlsn", "fpsub", "fpstnlsn"}));
}

// Sethi-Ullman: each sum is a load and a load-and-add, which pushes its operand before adding
// (CWG), so (a+b)*(c+d) needs three registers for a moment: c + d is added above a + b.
TEST(GeneratedCode, TwoSumsMultipliedNeedThreeRegisters) {
  const CodeUnit v = compile(
      [](C& a, C& b, C& c, C& d, C&, C&, C&, C&, auto& x, auto&) { x[0] = (a + b) * (c + d); });
  EXPECT_EQ(fpu_code(v),
            (Seq{"fpldnlsn", "fpldnladdsn", "fpldnlsn", "fpldnladdsn", "fpmul", "fpstnlsn"}));
  EXPECT_EQ(deepest_fp_stack(v), 3);
}

// A tree needing four registers: the stack never holds more than three, and exactly one
// intermediate is spilled to the workspace. Each sum a + b needs two (fpldnladd pushes b before it
// adds, CWG), so (a + b) * (c + d) needs three: the second sum's operand goes above c and a + b.
TEST(GeneratedCode, SpillsOnlyWhenTheStackIsFull) {
  const CodeUnit v = compile([](C& a, C& b, C& c, C& d, C& e, C& f, C& g, C& h, auto& x, auto&) {
    x[0] = ((a + b) * (c + d)) * ((e + f) * (g + h));
  });
  EXPECT_EQ(deepest_fp_stack(v), 3);
  EXPECT_EQ(count(body_code(v), "fpstnlsn"), 2);  // the spill and the result
  // With one sum less on the right it fits: nothing is spilled.
  const CodeUnit w = compile([](C& a, C& b, C& c, C& d, C& e, C& f, C&, C&, auto& x, auto&) {
    x[0] = ((a + b) * (c + d)) * (e + f);
  });
  EXPECT_EQ(deepest_fp_stack(w), 3);
  EXPECT_EQ(count(body_code(w), "fpstnlsn"), 1);
}

// A value used twice is a local variable: computed once, stored, loaded where used.
TEST(GeneratedCode, SharedValuesAreLocalVariables) {
  const CodeUnit v = compile([](C& a, C& b, C& c, C& d, C&, C&, C&, C&, auto& x, auto&) {
    const C t = a * b;
    x[0] = t + c;
    x[1] = t + d;
  });
  const Seq fpu = fpu_code(v);
  EXPECT_EQ(count(fpu, "fpldnlmulsn"), 1);
  EXPECT_EQ(count(fpu, "fpstnlsn"), 3);  // t, x[0], x[1]
}

// SEQ i: the two-word control block, the loop-indexed subscript (ldl i; wsub, or the indexed
// load fpldnlsni for an element loaded alone, as oc has it), lend each
// iteration; the checked compilation adds an FPU error check before each store, and no bound
// check: the compiler proves a known SEQ's bare index in range (tests/codegen/loop_bounds_test).
TEST(GeneratedCode, ReplicatedSeqCompilesToALoop) {
  auto kernel = [](C& a, C&, C&, C&, C&, C&, C&, C&, auto& x, auto& y) {
    for (std::size_t i : occam::seq<C>(8)) x[i] = y[i] + a;
  };
  const CodeUnit fast = compile(kernel, Target{true, false});
  const Seq code = body_code(fast);
  EXPECT_EQ(count(code, "lend"), 8);
  EXPECT_EQ(count(code, "wsub"), 8);       // x[i] :=
  EXPECT_EQ(count(code, "fpldnlsni"), 8);  // y[i], loaded first: a + y[i] adds a from memory
  EXPECT_EQ(count(code, "csub0"), 0);
  EXPECT_EQ(count(code, "fpchkerror"), 0);
  EXPECT_EQ(count(code, "fpldnladdsn"), 8);
  const CodeUnit checked = compile(kernel, Target{true, true});
  const Seq checked_code = body_code(checked);
  EXPECT_EQ(count(checked_code, "csub0"), 0);
  EXPECT_EQ(count(checked_code, "fpchkerror"), 8);
  // The loop's body is in memory once: the checked one is longer by its checks only.
  EXPECT_LT(fast.code_bytes, checked.code_bytes);
  EXPECT_LT(fast.code_bytes, 60);
}

// A T414 has no FPU: every operation is a call of the library's REAL32OP.
TEST(GeneratedCode, WithoutAnFpuArithmeticIsALibraryCall) {
  const CodeUnit v =
      compile([](C& a, C& b, C& c, C&, C&, C&, C&, C&, auto& x, auto&) { x[0] = a * b + c; },
              Target{false, false});
  for (const auto& run : v.runs)
    for (const auto& in : run.code)
      EXPECT_NE(std::string(t800::isa::mnemonic(in.op)).rfind("fp", 0), 0u)
          << t800::isa::mnemonic(in.op);
  EXPECT_EQ(count(body_code(v), "call 1024"), 2);
  ASSERT_EQ(v.routines.size(), 1u);
  EXPECT_EQ(v.routines.front()->name, "REAL32OP");
}

}  // namespace
