// The assembler's statements and directives, with bytes worked out by hand from the compiler
// writer's guide's prefixing rule (pfix n: O = (O | n) << 4; nfix n: O = ~(O | n) << 4; the
// function byte sees O | n) and the codes of the instruction table (t800/isa/opcode.cpp).
#include <gtest/gtest.h>

#include "t800/asm/assembler.hpp"

namespace {

using t800::assembly::assemble;
using t800::assembly::Options;
using Bytes = std::vector<std::uint8_t>;

Bytes bytes_of(const std::string& source, std::uint32_t origin = 0) {
  return assemble(source, Options{origin, ""}).bytes;
}

TEST(Assembler, DirectFunctionsTakeTheirOperandThroughPrefixes) {
  EXPECT_EQ(bytes_of("ldc 1083"), (Bytes{0x24, 0x23, 0x4B}));  // pfix 4, pfix 3, ldc B
  EXPECT_EQ(bytes_of("ldc 15"), (Bytes{0x4F}));
  EXPECT_EQ(bytes_of("ldc 16"), (Bytes{0x21, 0x40}));
  EXPECT_EQ(bytes_of("ldl 2"), (Bytes{0x72}));
  EXPECT_EQ(bytes_of("stl 3"), (Bytes{0xD3}));
  EXPECT_EQ(bytes_of("ajw -35"), (Bytes{0x62, 0xBD}));  // ~(-35) = 34, nfix 2, ajw D
  EXPECT_EQ(bytes_of("ldc -1"), (Bytes{0x60, 0x4F}));
  EXPECT_EQ(bytes_of("eqc 0"), (Bytes{0xC0}));
  EXPECT_EQ(bytes_of("pfix 0"), (Bytes{0x20}));
  EXPECT_EQ(bytes_of("ldnlp -4"), (Bytes{0x60, 0x5C}));
}

TEST(Assembler, OperationsAndFpuEntryOperationsTakeNoOperand) {
  EXPECT_EQ(bytes_of("add"), (Bytes{0xF5}));
  EXPECT_EQ(bytes_of("in"), (Bytes{0xF7}));
  EXPECT_EQ(bytes_of("ldpi"), (Bytes{0x21, 0xFB}));
  EXPECT_EQ(bytes_of("fpadd"), (Bytes{0x28, 0xF7}));
  EXPECT_EQ(bytes_of("fpuabs"), (Bytes{0x4B, 0x2A, 0xFB}));           // ldc #B; fpentry
  EXPECT_EQ(bytes_of("fpudivby2"), (Bytes{0x21, 0x41, 0x2A, 0xFB}));  // ldc #11; fpentry
  EXPECT_EQ(bytes_of("lddevid"), (Bytes{0x21, 0x27, 0xFC}));          // opr #17C
  EXPECT_EQ(bytes_of("not\nxor\nand\nor"), (Bytes{0x23, 0xF2, 0x23, 0xF3, 0x24, 0xF6, 0x24, 0xFB}));
}

TEST(Assembler, OprTakesAnOperationCode) {
  EXPECT_EQ(bytes_of("opr 5"), (Bytes{0xF5}));
  EXPECT_EQ(bytes_of("opr #17C"), (Bytes{0x21, 0x27, 0xFC}));
}

TEST(Assembler, MnemonicsAndDirectivesIgnoreCase) {
  EXPECT_EQ(bytes_of("LDC 1\nAdd\nFPUABS\n.BYTE 9"), (Bytes{0x41, 0xF5, 0x4B, 0x2A, 0xFB, 9}));
}

TEST(Assembler, NumbersInEveryNotation) {
  EXPECT_EQ(bytes_of(".byte 10, #7F, 0x7f, #a, 'A', '\\n', '\\0', '\\\\', '\\'', -1, -128"),
            (Bytes{10, 0x7F, 0x7F, 0x0A, 0x41, 0x0A, 0x00, 0x5C, 0x27, 0xFF, 0x80}));
}

TEST(Assembler, ExpressionsFollowArithmeticPrecedence) {
  EXPECT_EQ(bytes_of("ldc 2 + 3 * 4"), (Bytes{0x4E}));          // 14
  EXPECT_EQ(bytes_of("ldc (2 + 3) * 4"), (Bytes{0x21, 0x44}));  // 20
  EXPECT_EQ(bytes_of("ldc -(3)"), (Bytes{0x60, 0x4D}));         // -3: nfix 0, ldc D
  EXPECT_EQ(bytes_of("ldc 10 - 2 - 3"), (Bytes{0x45}));         // left to right
  EXPECT_EQ(bytes_of("ldc 5 - -3"), (Bytes{0x48}));
  EXPECT_EQ(bytes_of("ldc +7"), (Bytes{0x47}));
  EXPECT_EQ(bytes_of("ldc 5--3 is a comment"), (Bytes{0x45}));  // `--` starts occam's comments
}

TEST(Assembler, ThirtyTwoBitOperandsAreTakenModuloTwoToTheThirtyTwo) {
  // #FFFFFFFF is -1 as the 32-bit operand register holds it: the short nfix form.
  EXPECT_EQ(bytes_of("ldc #FFFFFFFF"), (Bytes{0x60, 0x4F}));
  EXPECT_EQ(bytes_of("ldc -2147483648"), bytes_of("ldc #80000000"));
  // MinInt: ~#80000000 = #7FFFFFFF, so nfix of #7FFFFFF (pfix 7, pfix F x5, nfix F), ldc 0.
  EXPECT_EQ(bytes_of("ldc #80000000"), (Bytes{0x27, 0x2F, 0x2F, 0x2F, 0x2F, 0x2F, 0x6F, 0x40}));
}

TEST(Assembler, CommentsBlankLinesAndLabels) {
  auto p = assemble(
      "-- occam comment\n"
      "; semicolon comment\n"
      "\n"
      "start: first: ldc 1  ; two labels\n"
      "   mid:\n"
      "        add        -- trailing\n"
      "end:\n");
  EXPECT_EQ(p.bytes, (Bytes{0x41, 0xF5}));
  EXPECT_EQ(p.labels.at("start"), 0u);
  EXPECT_EQ(p.labels.at("first"), 0u);
  EXPECT_EQ(p.labels.at("mid"), 1u);
  EXPECT_EQ(p.labels.at("end"), 2u);
  EXPECT_EQ(p.listing.size(), 7u);
}

TEST(Assembler, LabelsMayHaveOccamDotsAndAreCaseSensitive) {
  auto p = assemble("end.loop: ldc 1\nEnd.Loop: ldc 2\n j end.loop");
  EXPECT_EQ(p.labels.at("end.loop"), 0u);
  EXPECT_EQ(p.labels.at("End.Loop"), 1u);
  EXPECT_EQ(p.bytes, (Bytes{0x41, 0x42, 0x60, 0x0C}));  // j at 2, next 4: -4
}

TEST(Assembler, ByteDirective) {
  EXPECT_EQ(bytes_of(".byte 0, 255, -128, 'z', 3 * 4"), (Bytes{0, 0xFF, 0x80, 'z', 12}));
}

TEST(Assembler, WordDirectiveIsLittleEndian) {
  EXPECT_EQ(bytes_of(".word 1, -1, #12345678, #80000070"),
            (Bytes{1, 0, 0, 0, 0xFF, 0xFF, 0xFF, 0xFF, 0x78, 0x56, 0x34, 0x12, 0x70, 0, 0, 0x80}));
}

TEST(Assembler, AsciiDirectiveWithEscapes) {
  EXPECT_EQ(bytes_of(R"(.ascii "a\n\0\\\"\t'-- ;")"),
            (Bytes{'a', '\n', 0, '\\', '"', '\t', '\'', '-', '-', ' ', ';'}));
  EXPECT_EQ(bytes_of(R"(.ascii "")"), Bytes{});
}

TEST(Assembler, AlignPadsWithPfixZeroUnlessGivenAFill) {
  EXPECT_EQ(bytes_of("add\n.align 4\nadd"), (Bytes{0xF5, 0x20, 0x20, 0x20, 0xF5}));
  EXPECT_EQ(bytes_of("add\n.align 8, 0\n.byte 1"), (Bytes{0xF5, 0, 0, 0, 0, 0, 0, 0, 1}));
  EXPECT_EQ(bytes_of(".word 1\n.align 4\n.byte 2"), (Bytes{1, 0, 0, 0, 2}));  // already aligned
  EXPECT_EQ(bytes_of("add\n.align 1\nadd"), (Bytes{0xF5, 0xF5}));
}

TEST(Assembler, AlignIsRelativeToTheAbsoluteAddress) {
  // Origin 2: the byte at offset 0 is address 2, so two bytes reach address 4.
  EXPECT_EQ(bytes_of("add\n.align 4, #FF\nadd", 2), (Bytes{0xF5, 0xFF, 0xF5}));
}

TEST(Assembler, SpaceReservesZeroBytesOrAFill) {
  EXPECT_EQ(bytes_of(".space 3"), (Bytes{0, 0, 0}));
  EXPECT_EQ(bytes_of(".space 2, #AA"), (Bytes{0xAA, 0xAA}));
  EXPECT_EQ(bytes_of(".space 0\nadd"), (Bytes{0xF5}));
}

TEST(Assembler, ConstantsByAssignmentAndEqu) {
  auto p = assemble(
      "N = 5\n"
      ".equ M, N * 2 + 1\n"
      "ldc M\n"
      "ldc LATER\n"
      "LATER = M + N\n"
      ".space N - 3\n");
  EXPECT_EQ(p.bytes, (Bytes{0x4B, 0x21, 0x40, 0, 0}));
  EXPECT_EQ(p.constants.at("N"), 5);
  EXPECT_EQ(p.constants.at("M"), 11);
  EXPECT_EQ(p.constants.at("LATER"), 16);
  EXPECT_TRUE(p.labels.empty());
}

TEST(Assembler, ConstantsMayBeLabelDifferencesAndAddresses) {
  auto p = assemble(
      "start: ldc size\n"
      "       .space 20\n"
      "end:\n"
      "size = end - start\n"
      "here = .\n");
  // size = 22 once ldc has grown to pfix 1, ldc 6.
  EXPECT_EQ(p.bytes[0], 0x21);
  EXPECT_EQ(p.bytes[1], 0x46);
  EXPECT_EQ(p.constants.at("size"), 22);
  EXPECT_EQ(p.constants.at("here"), 22);
}

TEST(Assembler, LdcOfALabelIsItsAbsoluteAddress) {
  // data = #80000070 + 8 = #80000078, signed -2147483528: ~v = #7FFFFF87, so nfix #7FFFFF8 after
  // pfix 7, pfix F x5, then ldc 8; 8 bytes, which is where data lies.
  auto p = assemble("ldc data\ndata: .word data", Options{0x80000070, ""});
  EXPECT_EQ(p.bytes, (Bytes{0x27, 0x2F, 0x2F, 0x2F, 0x2F, 0x2F, 0x68, 0x48, 0x78, 0, 0, 0x80}));
  EXPECT_EQ(p.labels.at("data"), 0x80000078u);
  EXPECT_EQ(p.origin, 0x80000070u);
}

TEST(Assembler, DotIsTheAddressOfTheCurrentStatement) {
  EXPECT_EQ(bytes_of("add\nldc . + 2", 0x10), (Bytes{0xF5, 0x21, 0x43}));  // #11 + 2 = #13
  EXPECT_EQ(bytes_of("j ."), (Bytes{0x60, 0x0E}));                         // j -2: back to itself
  EXPECT_EQ(bytes_of("add\n.word ., . + 1"), (Bytes{0xF5, 1, 0, 0, 0, 2, 0, 0, 0}));
}

TEST(Assembler, LdpiRelativeAddressing) {
  // ldc msg - here; ldpi; here: ... msg: the distance from the ldpi's successor, 3.
  auto p = assemble(
      "      ldc msg - here\n"
      "      ldpi\n"
      "here: .space 3\n"
      "msg:  .byte 1\n");
  EXPECT_EQ(p.bytes, (Bytes{0x43, 0x21, 0xFB, 0, 0, 0, 1}));
}

TEST(Assembler, LdcOfLabelDifferences) {
  auto p = assemble(
      "start: ldc end - start\n"
      "       ldc start - end\n"
      "       .space 294\n"
      "end:\n");
  // 300 = #12C: pfix 1, pfix 2, ldc C. -300 = #FFFFFED4: ~ = #12B, nfix #12 (pfix 1, nfix 2),
  // ldc 4.
  EXPECT_EQ((Bytes(p.bytes.begin(), p.bytes.begin() + 6)),
            (Bytes{0x21, 0x22, 0x4C, 0x21, 0x62, 0x44}));
  EXPECT_EQ(p.labels.at("end"), 300u);
}

TEST(Assembler, JumpsGivenANumberTakeItAsTheOperand) {
  EXPECT_EQ(bytes_of("call 0"), (Bytes{0x90}));  // as the INMOS primary saves its registers
  EXPECT_EQ(bytes_of("j 0"), (Bytes{0x00}));
  EXPECT_EQ(bytes_of("cj -1"), (Bytes{0x60, 0xAF}));
}

TEST(Assembler, ConditionalJumpAndCallAreRelative) {
  auto p = assemble(
      "      cj skip\n"   // 0: next 1, skip at 3: 2
      "      call sub\n"  // 1: next 2, sub at 4: 2
      "      add\n"       // 2
      "skip: add\n"       // 3
      "sub:  ret\n");     // 4: opr #20 = pfix 2, opr 0
  EXPECT_EQ(p.bytes, (Bytes{0xA2, 0x92, 0xF5, 0xF5, 0x22, 0xF0}));
}

TEST(Assembler, ListingShowsAddressBytesAndSource) {
  auto p =
      assemble("start: ldc 1083   -- big\n\n  .ascii \"0123456789\"\n", Options{0x80000070, ""});
  EXPECT_EQ(p.listing_text(),
            "80000070  24 23 4B                 start: ldc 1083   -- big\n"
            "80000073\n"
            "80000073  30 31 32 33 34 35 36 37    .ascii \"0123456789\"\n"
            "8000007B  38 39\n");
  ASSERT_EQ(p.listing.size(), 3u);
  EXPECT_EQ(p.listing[0].line, 1);
  EXPECT_EQ(p.listing[0].address, 0x80000070u);
  EXPECT_EQ(p.listing[0].bytes, (Bytes{0x24, 0x23, 0x4B}));
  EXPECT_EQ(p.listing[2].source, "  .ascii \"0123456789\"");
}

TEST(Assembler, EmptySourceIsAnEmptyProgram) {
  auto p = assemble("");
  EXPECT_TRUE(p.bytes.empty());
  EXPECT_EQ(p.sizing_passes, 1);
}

TEST(Assembler, WindowsLineEndingsAreAccepted) {
  EXPECT_EQ(bytes_of("ldc 1\r\nadd\r\n"), (Bytes{0x41, 0xF5}));
}

}  // namespace
