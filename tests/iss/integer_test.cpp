// Integer instructions at their edges, run on the ISS: every expected value is worked out by hand
// from the compiler writer's guide's definition of the instruction (two's complement words, the
// Error flag for the checked operations).
#include <gtest/gtest.h>

#include "tests/iss/iss_fixtures.hpp"

namespace {

using iss_test::TestMachine;
using iss_test::Word;
using t800::iss::StopReason;

using iss_test::Stack;
// Runs `body` (which leaves its results on the stack: A, B, C) and returns A, B, C and Error.
Stack run(const std::string& body) {
  return iss_test::run_stack(body);
}

TEST(IssInteger, AddSubtractMultiplyCheckOverflow) {
  EXPECT_EQ(run("ldc 7\nldc 5\nadd").a, 12u);
  EXPECT_FALSE(run("ldc 7\nldc 5\nadd").error);
  // MaxInt + 1 overflows; sum and diff never set Error.
  const Stack over = run("ldc #7FFFFFFF\nldc 1\nadd");
  EXPECT_EQ(over.a, 0x80000000u);
  EXPECT_TRUE(over.error);
  EXPECT_FALSE(run("ldc #7FFFFFFF\nldc 1\nsum").error);
  EXPECT_EQ(run("ldc 5\nldc 7\nsub").a, Word(-2));  // B - A
  EXPECT_TRUE(run("mint\nldc 1\nsub").error);
  EXPECT_EQ(run("mint\nldc 1\ndiff").a, 0x7FFFFFFFu);
  EXPECT_EQ(run("ldc -6\nldc 7\nmul").a, Word(-42));
  EXPECT_TRUE(run("ldc #10000\nldc #10000\nmul").error);  // 2^32
  EXPECT_FALSE(run("ldc #10000\nldc #10000\nprod").error);
  EXPECT_EQ(run("ldc #10001\nldc #10001\nprod").a, 0x00020001u);  // 2^32 + 2^17 + 1, mod 2^32
  EXPECT_TRUE(run("ldc #7FFFFFFF\nadc 1").error);
}

TEST(IssInteger, DivideAndRemainderTruncateTowardZero) {
  EXPECT_EQ(run("ldc -7\nldc 2\ndiv").a, Word(-3));
  EXPECT_EQ(run("ldc -7\nldc 2\nrem").a, Word(-1));
  EXPECT_EQ(run("ldc 7\nldc -2\nrem").a, 1u);
  EXPECT_TRUE(run("ldc 7\nldc 0\ndiv").error);
  EXPECT_TRUE(run("ldc 7\nldc 0\nrem").error);
  EXPECT_TRUE(run("mint\nldc -1\ndiv").error);  // -MinInt does not fit
  const Stack r = run("mint\nldc -1\nrem");
  EXPECT_EQ(r.a, 0u);
  EXPECT_FALSE(r.error);
}

TEST(IssInteger, ComparisonsAndLogic) {
  EXPECT_EQ(run("ldc -1\nldc 1\ngt").a, 0u);  // B > A, signed: -1 > 1 is false
  EXPECT_EQ(run("ldc 1\nldc -1\ngt").a, 1u);
  EXPECT_EQ(run("ldc 5\neqc 5").a, 1u);
  EXPECT_EQ(run("ldc #F0\nldc #3C\nand").a, 0x30u);
  EXPECT_EQ(run("ldc #F0\nldc #3C\nor").a, 0xFCu);
  EXPECT_EQ(run("ldc #F0\nldc #3C\nxor").a, 0xCCu);
  EXPECT_EQ(run("ldc 0\nnot").a, 0xFFFFFFFFu);
  EXPECT_EQ(run("mint").a, 0x80000000u);
}

TEST(IssInteger, ShiftsOfAWordOrMoreGiveZero) {
  EXPECT_EQ(run("ldc 1\nldc 31\nshl").a, 0x80000000u);
  EXPECT_EQ(run("ldc 1\nldc 32\nshl").a, 0u);
  EXPECT_EQ(run("ldc -1\nldc 40\nshr").a, 0u);
  EXPECT_EQ(run("ldc -1\nldc 28\nshr").a, 0xFu);  // logical
}

TEST(IssInteger, LongArithmetic) {
  // lsum: B + A + carry(C): #FFFFFFFF + 1 + 1 = 1 carry 1.
  Stack s = run("ldc 1\nldc -1\nldc 1\nlsum");
  EXPECT_EQ(s.a, 1u);
  EXPECT_EQ(s.b, 1u);
  // ldiff: 0 - 1 - 0 = #FFFFFFFF borrow 1.
  s = run("ldc 0\nldc 0\nldc 1\nldiff");
  EXPECT_EQ(s.a, 0xFFFFFFFFu);
  EXPECT_EQ(s.b, 1u);
  // lmul: #FFFFFFFF * #FFFFFFFF + #FFFFFFFF = #FFFFFFFF_00000000.
  s = run("ldc -1\nldc -1\nldc -1\nlmul");
  EXPECT_EQ(s.a, 0u);
  EXPECT_EQ(s.b, 0xFFFFFFFFu);
  // ldiv: C:B = 1:0 (2^32) / 3 = 1431655765 rem 1.
  s = run("ldc 1\nldc 0\nldc 3\nldiv");
  EXPECT_EQ(s.a, 1431655765u);
  EXPECT_EQ(s.b, 1u);
  EXPECT_TRUE(run("ldc 3\nldc 0\nldc 3\nldiv").error);  // quotient overflows a word
  // lshl: C:B = 0:#80000001 << 1 = 1:#00000002.
  s = run("ldc 0\nldc #80000001\nldc 1\nlshl");
  EXPECT_EQ(s.a, 2u);
  EXPECT_EQ(s.b, 1u);
  s = run("ldc 1\nldc 0\nldc 33\nlshr");  // 2^32 >> 33 = 0
  EXPECT_EQ(s.a, 0u);
  s = run("ldc 1\nldc 0\nldc 32\nlshr");
  EXPECT_EQ(s.a, 1u);
  // norm: B:A = 0:1 needs 63 places; zero gives 64.
  s = run("ldc 0\nldc 1\nnorm");  // B = 0 high, A = 1 low
  EXPECT_EQ(s.c, 63u);
  EXPECT_EQ(s.b, 0x80000000u);
  EXPECT_EQ(s.a, 0u);
  EXPECT_EQ(run("ldc 0\nldc 0\nnorm").c, 64u);
}

TEST(IssInteger, ChecksAndConversions) {
  EXPECT_TRUE(run("ldc 5\nldc 5\ncsub0").error);  // B >= A
  EXPECT_FALSE(run("ldc 4\nldc 5\ncsub0").error);
  EXPECT_TRUE(run("ldc -1\nldc 5\ncsub0").error);  // unsigned: #FFFFFFFF >= 5
  EXPECT_TRUE(run("ldc 0\nldc 5\nccnt1").error);
  EXPECT_TRUE(run("ldc 6\nldc 5\nccnt1").error);
  EXPECT_FALSE(run("ldc 5\nldc 5\nccnt1").error);
  EXPECT_EQ(run("ldc #FF\nldc #80\nxword").a, Word(-1));  // byte #FF as INT
  EXPECT_EQ(run("ldc #7F\nldc #80\nxword").a, 0x7Fu);
  EXPECT_TRUE(run("ldc 128\nldc #80\ncword").error);  // 128 is not a BYTE-sized INT
  EXPECT_FALSE(run("ldc -128\nldc #80\ncword").error);
  const Stack x = run("ldc -5\nxdble");
  EXPECT_EQ(x.b, 0xFFFFFFFFu);
  EXPECT_EQ(x.a, Word(-5));
  EXPECT_TRUE(run("ldc 1\nldc 0\ncsngl").error);  // B:A = 1:0 is not a single word (B high)
  EXPECT_FALSE(run("ldc -1\nldc -3\ncsngl").error);
}

TEST(IssInteger, T800BitOperations) {
  EXPECT_EQ(run("ldc 10\nldc #F0F0\nbitcnt").a, 18u);  // 8 bits set + 10
  EXPECT_EQ(run("ldc 1\nbitrevword").a, 0x80000000u);
  EXPECT_EQ(run("ldc #B\nldc 4\nbitrevnbits").a, 0xDu);  // 1011 reversed in 4 bits: 1101
  // crcbyte / crcword: the CRC register R with the data's bits shifted in below it, reduced by
  // the generator G (x^32 implied): R' = (R x^n + D) mod G over GF(2), n = 8 or 32. Expected
  // values by polynomial division (long division over GF(2), worked independently of the ISS's
  // bit loop) with G = #04C11DB7 (CRC-32's).
  EXPECT_EQ(run("ldc #04C11DB7\nldc #80000000\nldc #A5000000\ncrcbyte").a, 0x690CE04Bu);
  EXPECT_EQ(run("ldc #04C11DB7\nldc #12345678\nldc #DEADBEEF\ncrcword").a, 0xC623E9BFu);
}

TEST(IssInteger, IndexingAndWords) {
  EXPECT_EQ(run("ldc 3\nldc 100\nwsub").a, 112u);
  EXPECT_EQ(run("ldc 3\nldc 100\nwsubdb").a, 124u);
  EXPECT_EQ(run("ldc 3\nldc 100\nbsub").a, 103u);
  EXPECT_EQ(run("ldc 5\nbcnt").a, 20u);
  const Stack w = run("ldc 7\nwcnt");
  EXPECT_EQ(w.a, 1u);
  EXPECT_EQ(w.b, 3u);
}

TEST(IssInteger, BytesAndBlockMoves) {
  TestMachine m;
  const auto p = m.boot(R"(
        ajw 16
        ldc src
        ldc dst
        ldc 5
        move              -- C source, B destination, A bytes
        ldc #AB
        ldc dst
        adc 5
        sb
        ldc src
        adc 1
        lb
        stopp
        .align 4
src:    .byte 1, 2, 3, 4, 5, 6, 7, 8
dst:    .word 0, 0
)");
  EXPECT_EQ(m.run(), StopReason::idle);
  EXPECT_EQ(m.word(p.labels.at("dst")), 0x04030201u);
  EXPECT_EQ(m.word(p.labels.at("dst") + 4), 0x0000AB05u);
  EXPECT_EQ(m.core.registers().a, 2u);
}

TEST(IssInteger, TwoDimensionalMoveCopiesRowsWithStrides) {
  TestMachine m;
  const auto p = m.boot(R"(
        ajw 16
        ldc 4             -- C: source stride
        ldc 8             -- B: destination stride
        ldc 2             -- A: rows
        move2dinit
        ldc src
        ldc dst
        ldc 2             -- width in bytes
        move2dnonzero     -- only the non-zero bytes
        stopp
        .align 4
src:    .byte 1, 0, 9, 9, 3, 4, 9, 9
dst:    .byte 7, 7, 7, 7, 7, 7, 7, 7, 7, 7, 7, 7
)");
  EXPECT_EQ(m.run(), StopReason::idle);
  const Word d = p.labels.at("dst");
  EXPECT_EQ(m.word(d), 0x07070701u);      // row 0: 1, (0 skipped: 7)
  EXPECT_EQ(m.word(d + 8), 0x07070403u);  // row 1 at stride 8: 3, 4
}

// A prefix chain may be as long as the code likes (CWG, "prefixing": each pfix shifts the operand
// register four places; INMOS loaders pad with pfix 0): 26 pfix 0 bytes and then `ldc 5` load 5,
// and the chain costs a cycle a byte as any prefix does. A chain that never ends (memory full of
// pfix bytes) halts the processor instead of decoding for ever.
TEST(IssInteger, ALongPrefixChainIsOneInstruction) {
  std::string pad;
  for (int k = 0; k < 26; ++k) pad += k ? ", #20" : "#20";
  EXPECT_EQ(run(".byte " + pad + ", #45").a, 5u);
  // pfix 1 after the zeros, then ldc 2: #12, whatever zeros came before.
  EXPECT_EQ(run(".byte " + pad + ", #21, #42").a, 0x12u);
  // nfix 0 then ldc 0: ~0 << 4 = -16, after any number of zeros.
  EXPECT_EQ(run(".byte " + pad + ", #60, #40").a, Word(-16));
  const auto cycles = [](const std::string& code) {
    TestMachine m;
    m.boot("ajw 16\n" + code + "\nstopp\n");
    m.run();
    return m.core.cycle();
  };
  EXPECT_EQ(cycles(".byte " + pad + ", #45") - cycles(".byte #45"), 26);
  TestMachine m;
  std::string runaway;
  for (int k = 0; k < 300; ++k) runaway += k ? ", #20" : "#20";
  m.boot("ajw 16\n.byte " + runaway + "\n");
  EXPECT_EQ(m.run(), StopReason::halted);
  ASSERT_TRUE(m.core.halt_report());
  EXPECT_NE(m.core.halt_report()->reason.find("a prefix chain of 255 bytes or more"),
            std::string::npos)
      << m.core.halt_report()->reason;
}

}  // namespace
