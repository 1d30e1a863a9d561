// The one-instruction disassembler: prefix chains folded into operands, fpu-entry pairs into the
// operation they select, jump targets, and bytes that end inside a chain.
#include <gtest/gtest.h>

#include "t800/asm/assembler.hpp"

namespace {

using t800::assembly::assemble;
using t800::assembly::disassemble;
using t800::isa::Op;
using Bytes = std::vector<std::uint8_t>;

TEST(Disassembler, FoldsPfixChains) {
  auto in = disassemble(Bytes{0x24, 0x23, 0x4B}, 0);
  EXPECT_EQ(in.op, Op::ldc);
  EXPECT_EQ(in.mnemonic, "ldc");
  EXPECT_TRUE(in.has_operand);
  EXPECT_EQ(in.operand, 1083);
  EXPECT_EQ(in.length, 3);
  EXPECT_TRUE(in.complete);
  EXPECT_EQ(in.text, "ldc 1083");
  EXPECT_FALSE(in.target);
}

TEST(Disassembler, FoldsNfixChains) {
  auto in = disassemble(Bytes{0x62, 0xBD}, 0);  // ajw -35
  EXPECT_EQ(in.op, Op::ajw);
  EXPECT_EQ(in.operand, -35);
  EXPECT_EQ(in.text, "ajw -35");
  // pfix 1, nfix 2, ldc 4: #FFFFFED4 = -300.
  EXPECT_EQ(disassemble(Bytes{0x21, 0x62, 0x44}, 0).operand, -300);
  // pfix 7, pfix F x5, nfix 8, ldc 8: #80000078, shown in hex.
  auto big = disassemble(Bytes{0x27, 0x2F, 0x2F, 0x2F, 0x2F, 0x2F, 0x68, 0x48}, 0);
  EXPECT_EQ(big.length, 8);
  EXPECT_EQ(std::uint32_t(big.operand), 0x80000078u);
  EXPECT_EQ(big.text, "ldc #80000078");
}

TEST(Disassembler, PfixZeroPaddingIsPartOfTheInstruction) {
  auto in = disassemble(Bytes{0x20, 0x20, 0x41}, 0);
  EXPECT_EQ(in.text, "ldc 1");
  EXPECT_EQ(in.length, 3);
}

TEST(Disassembler, StartsAtTheOffset) {
  const Bytes code{0xF5, 0x24, 0x23, 0x4B, 0x72};
  EXPECT_EQ(disassemble(code, 0).text, "add");
  EXPECT_EQ(disassemble(code, 1).text, "ldc 1083");
  EXPECT_EQ(disassemble(code, 4).text, "ldl 2");
  EXPECT_THROW(disassemble(code, 5), std::out_of_range);
}

TEST(Disassembler, JumpsShowTheirTarget) {
  // At #80000073: j -5, two bytes, so the target is #80000075 - 5 = #80000070.
  const Bytes code{0xF5, 0xF5, 0xF5, 0x60, 0x0B};
  auto in = disassemble(code, 3, 0x80000070);
  EXPECT_EQ(in.op, Op::j);
  EXPECT_EQ(in.operand, -5);
  EXPECT_EQ(*in.target, 0x80000070u);
  EXPECT_EQ(in.text, "j -5 (to #80000070)");
  auto cj = disassemble(Bytes{0x21, 0xA0}, 0, 0x100);  // cj 16 at #100, two bytes
  EXPECT_EQ(*cj.target, 0x112u);
  EXPECT_EQ(disassemble(Bytes{0x90}, 0).text, "call 0 (to #00000001)");
}

TEST(Disassembler, OperationsThroughOpr) {
  EXPECT_EQ(disassemble(Bytes{0xF5}, 0).text, "add");
  EXPECT_EQ(disassemble(Bytes{0x28, 0xF7}, 0).op, Op::fpadd);
  EXPECT_EQ(disassemble(Bytes{0x28, 0xF7}, 0).length, 2);
  EXPECT_EQ(disassemble(Bytes{0x21, 0x27, 0xFC}, 0).text, "lddevid");
  auto unknown = disassemble(Bytes{0x21, 0xF1}, 0);  // opr #11: no such operation
  EXPECT_FALSE(unknown.op);
  EXPECT_EQ(unknown.mnemonic, "opr");
  EXPECT_TRUE(unknown.has_operand);
  EXPECT_EQ(unknown.operand, 0x11);
  EXPECT_EQ(unknown.text, "opr #11");
}

TEST(Disassembler, FoldsFpuEntryPairs) {
  auto abs = disassemble(Bytes{0x4B, 0x2A, 0xFB}, 0);  // ldc #B; fpentry
  EXPECT_EQ(abs.op, Op::fpuabs);
  EXPECT_EQ(abs.text, "fpuabs");
  EXPECT_EQ(abs.length, 3);
  EXPECT_FALSE(abs.has_operand);
  auto div2 = disassemble(Bytes{0x21, 0x41, 0x2A, 0xFB}, 0);  // ldc #11; fpentry
  EXPECT_EQ(div2.op, Op::fpudivby2);
  EXPECT_EQ(div2.length, 4);
  EXPECT_EQ(disassemble(Bytes{0x2A, 0xFB}, 0).text, "fpentry");      // alone: A is whatever it is
  EXPECT_EQ(disassemble(Bytes{0x4B, 0xF5}, 0).text, "ldc 11");       // no fpentry after it
  EXPECT_EQ(disassemble(Bytes{0x40, 0x2A, 0xFB}, 0).text, "ldc 0");  // no fpu operation 0
  EXPECT_EQ(disassemble(Bytes{0x4B}, 0).text, "ldc 11");
}

TEST(Disassembler, BytesEndingInsideAPrefixChain) {
  auto in = disassemble(Bytes{0xF5, 0x24, 0x23}, 1);
  EXPECT_FALSE(in.complete);
  EXPECT_EQ(in.length, 2);
  EXPECT_TRUE(in.mnemonic.empty());
  EXPECT_NE(in.text.find("runs past the end"), std::string::npos);
}

TEST(Disassembler, RoundTripsEveryInstructionInTheTable) {
  for (int i = 0; i < t800::isa::kOpCount; ++i) {
    const auto op = static_cast<Op>(i);
    if (op == Op::pfix || op == Op::nfix) continue;  // folded into what follows
    const std::string mnemonic(t800::isa::mnemonic(op));
    const bool direct = t800::isa::info(op).encoding == t800::isa::Encoding::direct;
    const auto p = assemble(mnemonic + (direct ? " 1083" : ""));
    const auto in = disassemble(p.bytes, 0);
    EXPECT_EQ(in.op, op) << mnemonic;
    EXPECT_EQ(in.length, int(p.bytes.size())) << mnemonic;
    if (direct) {
      EXPECT_EQ(in.operand, 1083) << mnemonic;
    }
  }
}

}  // namespace
