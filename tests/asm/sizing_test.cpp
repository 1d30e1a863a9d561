// Prefix sizing: jumps over distances that need 0, 1 and 2 prefix bytes, backward (nfix) jumps,
// jumps whose own growth pushes them over a boundary, a growth that pushes another jump over a
// 16-byte boundary, and the one case sizes-only-grow leaves a byte longer than needed. Expected
// bytes worked out by hand: j's function code is 0, so a one-byte `j n` is the byte n.
#include <gtest/gtest.h>

#include <random>

#include "t800/asm/assembler.hpp"

namespace {

using t800::assembly::assemble;
using t800::assembly::disassemble;
using Bytes = std::vector<std::uint8_t>;

Bytes head(const Bytes& b, std::size_t n) {
  return Bytes(b.begin(), b.begin() + long(n));
}

TEST(Sizing, ForwardJumpWithoutPrefix) {
  auto p = assemble("j end\n.space 15\nend:");
  EXPECT_EQ(head(p.bytes, 1), (Bytes{0x0F}));  // 16 - 1
  EXPECT_EQ(p.labels.at("end"), 16u);
}

TEST(Sizing, ForwardJumpWithOnePrefix) {
  // At one byte the distance is 16, which needs pfix 1; at two bytes it is still 16 (the target
  // moves with the jump).
  auto p = assemble("j end\n.space 16\nend:");
  EXPECT_EQ(head(p.bytes, 2), (Bytes{0x21, 0x00}));
  EXPECT_EQ(p.labels.at("end"), 18u);
  EXPECT_EQ(p.sizing_passes, 2);
  auto q = assemble("j end\n.space 255\nend:");
  EXPECT_EQ(head(q.bytes, 2), (Bytes{0x2F, 0x0F}));  // the longest one-prefix distance
}

TEST(Sizing, ForwardJumpWithTwoPrefixes) {
  auto p = assemble("j end\n.space 256\nend:");
  EXPECT_EQ(head(p.bytes, 3), (Bytes{0x21, 0x20, 0x00}));  // pfix 1, pfix 0, j 0: 256
  EXPECT_EQ(p.labels.at("end"), 259u);
}

TEST(Sizing, BackwardJumpsUseNfix) {
  // A jump to itself: -1 at one byte needs nfix, -2 at two bytes: nfix 0, j E.
  EXPECT_EQ(assemble("top: j top").bytes, (Bytes{0x60, 0x0E}));
  // Back over 254 bytes: at two bytes the distance is -256 = nfix F, j 0, which fits.
  auto p = assemble("top: .space 254\nj top");
  EXPECT_EQ(Bytes(p.bytes.begin() + 254, p.bytes.end()), (Bytes{0x6F, 0x00}));
  EXPECT_EQ(p.sizing_passes, 2);
}

TEST(Sizing, BackwardJumpPushedOverByItsOwnPrefix) {
  // Back over 255 bytes: at one byte -256 needs one prefix; at two bytes -257 needs two
  // (~(-257) = 256); at three bytes -258 = #FFFFFEFE: pfix 1, nfix 0, j E. Three passes.
  auto p = assemble("top: .space 255\nj top");
  EXPECT_EQ(Bytes(p.bytes.begin() + 255, p.bytes.end()), (Bytes{0x21, 0x60, 0x0E}));
  EXPECT_EQ(p.sizing_passes, 3);
}

TEST(Sizing, GrowingOneJumpPushesAnotherOverASixteenByteBoundary) {
  // Pass 1: the first jump's distance is 15 (fits), the second's 16 (grows). Pass 2: the grown
  // second jump makes the first's distance 16 (grows). Pass 3: both 16, stable.
  auto p = assemble(
      "    j a\n"
      "    .space 14\n"
      "    j b\n"
      "a:  .space 16\n"
      "b:\n");
  Bytes expected{0x21, 0x00};
  expected.resize(16, 0);
  expected.insert(expected.end(), {0x21, 0x00});
  expected.resize(34, 0);
  EXPECT_EQ(p.bytes, expected);
  EXPECT_EQ(p.labels.at("a"), 18u);
  EXPECT_EQ(p.labels.at("b"), 34u);
  EXPECT_EQ(p.sizing_passes, 3);
}

TEST(Sizing, AlignThatShrinksLeavesAJumpOneByteLongFilledWithPfixZero) {
  // At one byte the jump's target is 17 (padding 2 to 16, then a byte): distance 16, so it
  // grows. At two bytes the padding shrinks to 1 and the distance is 15, which would fit one
  // byte, but lengths never shrink: it stays two bytes, pfix 0, j 15, still exact.
  auto p = assemble(
      "     j end\n"
      "     .space 13\n"
      "     .align 16\n"
      "     .byte 7\n"
      "end:\n");
  Bytes expected{0x20, 0x0F};
  expected.resize(15, 0);
  expected.insert(expected.end(), {0x20, 0x07});
  EXPECT_EQ(p.bytes, expected);
  auto j = disassemble(p.bytes, 0);
  EXPECT_EQ(j.length, 2);
  EXPECT_EQ(j.operand, 15);
  EXPECT_EQ(*j.target, p.labels.at("end"));
}

TEST(Sizing, ACascadeOfGrowthsOnePerPass) {
  // J0 .. J5; Ji jumps to the label just after J(i+1), over 14 bytes and J(i+1): 15 while
  // J(i+1) is one byte, 16 once it has grown. J5 jumps over 16 bytes and grows in pass 1, J4 in
  // pass 2, ..., J0 in pass 6; pass 7 finds them stable, every one pfix 1, j 0.
  const int n = 5;
  std::string source = "j a0\n.space 14\n";
  for (int i = 1; i <= n; ++i)
    source += "j a" + std::to_string(i) + "\na" + std::to_string(i - 1) + ": .space " +
              (i < n ? "14" : "16") + "\n";
  source += "a" + std::to_string(n) + ":\n";
  auto p = assemble(source);
  Bytes expected;
  for (int i = 0; i <= n; ++i) {
    expected.insert(expected.end(), {0x21, 0x00});
    expected.resize(expected.size() + (i < n ? 14 : 16), 0);
  }
  EXPECT_EQ(p.bytes, expected);
  EXPECT_EQ(p.sizing_passes, n + 2);
}

// Random programs of jumps, conditional jumps and label differences, checked through the
// disassembler: every operand reaches its label and, with no .align, no instruction is longer
// than its operand needs (the least consistent layout).
TEST(Sizing, RandomProgramsAreExactAndMinimal) {
  std::mt19937 random(1988);
  for (int trial = 0; trial < 200; ++trial) {
    const int labels = 1 + int(random() % 6);
    std::vector<std::string> lines;
    std::vector<int> targets;  // per line: the label index jumped to, or -1
    const int count = 5 + int(random() % 20);
    std::vector<int> label_line(static_cast<std::size_t>(labels));
    for (int& l : label_line) l = int(random() % std::uint32_t(count));
    for (int i = 0; i < count; ++i) {
      std::string line;
      for (int l = 0; l < labels; ++l)
        if (label_line[std::size_t(l)] == i) line += "L" + std::to_string(l) + ": ";
      int kind = int(random() % 4);
      int target = int(random() % std::uint32_t(labels));
      if (kind == 0) {
        line += ".space " + std::to_string(random() % 300);
        target = -1;
      } else if (kind == 1) {
        line += (random() % 2 ? "j L" : "cj L") + std::to_string(target);
      } else if (kind == 2) {
        line += "call L" + std::to_string(target);
      } else {
        line += "ldc L" + std::to_string(target) + " - .";
      }
      lines.push_back(line);
      targets.push_back(target);
    }
    std::string source;
    for (const auto& l : lines) source += l + "\n";
    auto p = assemble(source);
    ASSERT_EQ(p.listing.size(), lines.size());
    for (std::size_t i = 0; i < lines.size(); ++i) {
      const auto& row = p.listing[i];
      if (targets[i] < 0) continue;
      const std::uint32_t label = p.labels.at("L" + std::to_string(targets[i]));
      auto in = disassemble(row.bytes, 0, row.address);
      ASSERT_TRUE(in.complete) << source;
      ASSERT_EQ(in.length, int(row.bytes.size())) << source;
      if (in.mnemonic == "ldc")
        EXPECT_EQ(std::int64_t(in.operand), std::int64_t(label) - row.address) << source;
      else
        EXPECT_EQ(*in.target, label) << source;
      EXPECT_EQ(in.length, 1 + t800::isa::prefix_bytes(in.operand)) << source;
    }
  }
}

}  // namespace
