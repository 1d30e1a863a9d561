// Listing notes are the only thing Target::notes changes: compiled without them (as a processor's
// timing compiles), a unit has the same runs, instructions, operands, memory references and sizes
// as with them, and no notes.
#include <gtest/gtest.h>

#include "tests/codegen/codegen_fixtures.hpp"

namespace {

using namespace codegen_test;

void expect_same_code(const CodeUnit& annotated, const CodeUnit& bare) {
  EXPECT_EQ(annotated.code_bytes, bare.code_bytes);
  EXPECT_EQ(annotated.constant_bytes, bare.constant_bytes);
  EXPECT_EQ(annotated.workspace_words, bare.workspace_words);
  EXPECT_EQ(annotated.routines, bare.routines);
  ASSERT_EQ(annotated.runs.size(), bare.runs.size());
  int notes = 0;
  for (std::size_t r = 0; r < bare.runs.size(); ++r) {
    const auto& a = annotated.runs[r];
    const auto& b = bare.runs[r];
    EXPECT_EQ(a.label, b.label);
    EXPECT_EQ(a.times, b.times);
    EXPECT_EQ(a.library, b.library);
    ASSERT_EQ(a.code.size(), b.code.size());
    for (std::size_t i = 0; i < b.code.size(); ++i) {
      const auto& x = a.code[i];
      const auto& y = b.code[i];
      EXPECT_EQ(t800::isa::assembly(x), t800::isa::assembly(y));
      EXPECT_EQ(x.param, y.param);
      EXPECT_EQ(x.real64, y.real64);
      EXPECT_TRUE(x.data == y.data);
      EXPECT_EQ(y.note, "");
      notes += !x.note.empty();
    }
  }
  EXPECT_GT(notes, 0);  // the annotated unit does carry notes
}

TEST(ListingNotes, ChangeNothingButTheNotes) {
  auto kernel = [](C& a, C& b, C& c, C& d, C&, C&, C&, C&, auto& x, auto& y) {
    for (std::size_t i : occam::seq<C>(8)) x[i] = y[i] * a + C(2.5);
    x[0] = (a - b) / (c + d * C(3.0));
    x[1] = x[0] * x[0] - y[2];
  };
  for (bool fpu : {true, false})
    for (bool checked : {true, false}) {
      SCOPED_TRACE(testing::Message() << "fpu " << fpu << ", checked " << checked);
      expect_same_code(compile(kernel, Target{fpu, checked, true}),
                       compile(kernel, Target{fpu, checked, false}));
    }
}

}  // namespace
