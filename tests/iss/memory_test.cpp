// Memory::copy is `move`: bytes copied one at a time in address order (CWG, "move"), so a copy to
// a higher address over its own source repeats the source's first bytes, and a copy past the
// installed memory wraps with the addresses. The expected bytes below follow from that rule by
// hand.
#include <gtest/gtest.h>

#include <vector>

#include "t800/iss/memory.hpp"

namespace {

using t800::iss::AddressPolicy;
using t800::iss::kMostNeg;
using t800::iss::Memory;
using t800::iss::Word;

constexpr std::int64_t kMemoryBytes = 1 << 16;

void fill_counting(Memory& m, Word at, int count) {
  for (int k = 0; k < count; ++k) m.set_byte(at + Word(k), std::uint8_t(k + 1));
}
std::vector<int> bytes_at(const Memory& m, Word at, int count) {
  std::vector<int> out;
  for (int k = 0; k < count; ++k) out.push_back(m.byte(at + Word(k)));
  return out;
}

TEST(MemoryCopy, ToALowerAddressOverItsSourceMovesTheBytesDown) {
  Memory m(4096, kMemoryBytes, AddressPolicy::wrap);
  const Word at = kMostNeg + 0x2000;
  fill_counting(m, at + 2, 6);  // 1..6 at +2..+7
  m.copy(at, at + 2, 6);
  EXPECT_EQ(bytes_at(m, at, 8), (std::vector<int>{1, 2, 3, 4, 5, 6, 5, 6}));
}

TEST(MemoryCopy, ToAHigherAddressOverItsSourceRepeatsTheFirstBytes) {
  Memory m(4096, kMemoryBytes, AddressPolicy::wrap);
  const Word at = kMostNeg + 0x2000;
  fill_counting(m, at, 3);  // 1 2 3
  m.copy(at + 2, at, 6);
  // Byte k goes to +2+k after bytes 0..k-1 have: 1 2 1 2 1 2 1 2.
  EXPECT_EQ(bytes_at(m, at, 8), (std::vector<int>{1, 2, 1, 2, 1, 2, 1, 2}));
}

TEST(MemoryCopy, PastTheInstalledMemoryWrapsWithTheAddresses) {
  Memory m(4096, kMemoryBytes, AddressPolicy::wrap);
  const Word end = kMostNeg + Word(kMemoryBytes);
  fill_counting(m, kMostNeg + 0x100, 8);
  m.copy(end - 4, kMostNeg + 0x100, 8);
  EXPECT_EQ(bytes_at(m, end - 4, 4), (std::vector<int>{1, 2, 3, 4}));
  EXPECT_EQ(bytes_at(m, kMostNeg, 4), (std::vector<int>{5, 6, 7, 8}));
}

TEST(MemoryCopy, PastTheInstalledMemoryIsAFaultUnderStrictAddressing) {
  Memory m(4096, kMemoryBytes, AddressPolicy::strict);
  const Word end = kMostNeg + Word(kMemoryBytes);
  EXPECT_THROW(m.copy(end - 4, kMostNeg + 0x100, 8), t800::iss::MemoryFault);
}

TEST(MemoryCopy, OverCodeTellsTheDecoderOfEveryCodeLineItWrites) {
  Memory m(4096, kMemoryBytes, AddressPolicy::wrap);
  std::vector<std::uint32_t> told;
  m.on_code_written([&](std::uint32_t line) { told.push_back(line); });
  m.mark_code(0x3000);  // lines at 0x3000 and 0x3020 hold code, 0x3010 does not
  m.mark_code(0x3020);
  m.mark_code(0x3040);                                // beyond the copy
  m.copy(kMostNeg + 0x3008, kMostNeg + 0x100, 0x20);  // writes 0x3008..0x3027
  EXPECT_EQ(told, (std::vector<std::uint32_t>{0x3000, 0x3020}));
}

// The undo log (Memory::start_undo_log) is what lets a core go back to a checkpoint: every way of
// writing keeps what it overwrote, and undo() puts it all back, telling the decoder of code lines
// it restores.
TEST(MemoryUndo, EveryKindOfWriteIsUndoneToTheBytesBefore) {
  Memory m(4096, kMemoryBytes, AddressPolicy::wrap);
  fill_counting(m, kMostNeg + 0x0F00, 0x300);  // on chip and off (the on-chip RAM is 4 KB)
  const std::vector<int> before = bytes_at(m, kMostNeg + 0x0F00, 0x300);
  std::vector<std::uint32_t> told;
  m.on_code_written([&](std::uint32_t line) { told.push_back(line); });
  m.mark_code(0x1100);
  m.start_undo_log();
  m.set_word(kMostNeg + 0x0F10, 0xDEADBEEF);
  bool external = false;
  m.set_word(kMostNeg + 0x1002, 0x01020304, external);  // unaligned: the word at 0x1000
  m.set_word(kMostNeg + 0x1004, 0x05060708, external);
  m.set_byte(kMostNeg + 0x0F21, 0xAA);
  m.copy(kMostNeg + 0x1040, kMostNeg + 0x0F00, 0x81);  // plain, an odd length
  m.copy(kMostNeg + 0x0F81, kMostNeg + 0x0F80, 0x10);  // forward over its source: byte by byte
  const std::uint8_t in[5] = {9, 9, 9, 9, 9};
  m.write(kMostNeg + 0x10FE, in, 5);          // into the code line at 0x1100
  m.mark_code(0x1100);                        // decoded again after it, as a run executing it would
  m.set_word(kMostNeg + 0x0F10, 0x11111111);  // the same word again
  EXPECT_NE(bytes_at(m, kMostNeg + 0x0F00, 0x300), before);
  told.clear();
  m.undo();
  EXPECT_EQ(bytes_at(m, kMostNeg + 0x0F00, 0x300), before);
  EXPECT_EQ(told, (std::vector<std::uint32_t>{0x1100}));
  // Undone, the log is off: a write now stands.
  m.set_byte(kMostNeg + 0x0F00, 0x55);
  m.undo();
  EXPECT_EQ(m.byte(kMostNeg + 0x0F00), 0x55);
}

TEST(MemoryUndo, ADroppedLogLeavesTheWritesInPlace) {
  Memory m(4096, kMemoryBytes, AddressPolicy::wrap);
  m.start_undo_log();
  m.set_word(kMostNeg + 0x2000, 7);
  m.drop_undo_log();
  m.undo();
  EXPECT_EQ(m.word(kMostNeg + 0x2000), 7u);
}

}  // namespace
