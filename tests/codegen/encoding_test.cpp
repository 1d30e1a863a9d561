// Instruction encodings against the compiler writer's guide's prefixing rule and bytes the INMOS
// occam compiler (D7205A toolset) emitted for the same instructions.
#include <gtest/gtest.h>

#include "t800/isa/opcode.hpp"

namespace {

using t800::isa::encode;
using t800::isa::Op;
using Bytes = std::vector<std::uint8_t>;

TEST(Encoding, PrefixBytesFollowTheOperandsBits) {
  EXPECT_EQ(t800::isa::prefix_bytes(0), 0);
  EXPECT_EQ(t800::isa::prefix_bytes(15), 0);
  EXPECT_EQ(t800::isa::prefix_bytes(16), 1);
  EXPECT_EQ(t800::isa::prefix_bytes(255), 1);
  EXPECT_EQ(t800::isa::prefix_bytes(256), 2);
  EXPECT_EQ(t800::isa::prefix_bytes(-1), 1);   // nfix 0
  EXPECT_EQ(t800::isa::prefix_bytes(-16), 1);  // nfix 0
  EXPECT_EQ(t800::isa::prefix_bytes(-17), 1);  // nfix 1
}

TEST(Encoding, MatchesTheInmosCompilersBytes) {
  EXPECT_EQ(encode(Op::ldc, 1083), (Bytes{0x24, 0x23, 0x4B}));
  EXPECT_EQ(encode(Op::ldc, 20000), (Bytes{0x24, 0x2E, 0x22, 0x40}));
  EXPECT_EQ(encode(Op::ajw, -35), (Bytes{0x62, 0xBD}));
  EXPECT_EQ(encode(Op::fpadd), (Bytes{0x28, 0xF7}));
  EXPECT_EQ(encode(Op::fpldnladdsn), (Bytes{0x2A, 0xFA}));
  EXPECT_EQ(encode(Op::lend), (Bytes{0x22, 0xF1}));
  EXPECT_EQ(encode(Op::csub0), (Bytes{0x21, 0xF3}));
  EXPECT_EQ(encode(Op::fpuabs), (Bytes{0x4B, 0x2A, 0xFB}));
  EXPECT_EQ(encode(Op::fpudivby2), (Bytes{0x21, 0x41, 0x2A, 0xFB}));
  EXPECT_EQ(encode(Op::add), (Bytes{0xF5}));
  for (Op op : {Op::ldc, Op::fpadd, Op::fpuabs, Op::fpudivby2, Op::lend})
    EXPECT_EQ(int(encode(op, op == Op::ldc ? 1083 : 0).size()),
              t800::isa::encoded_bytes(op, op == Op::ldc ? 1083 : 0));
}

}  // namespace
