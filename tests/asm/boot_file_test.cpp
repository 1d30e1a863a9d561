// The boot-file writers' byte layout, the primary loader's bytes (encoded by hand from the
// instruction table), and the primary run on a small model of the dozen instructions it uses,
// until the project's instruction-set simulator can run it.
#include <gtest/gtest.h>

#include <map>

#include "t800/asm/assembler.hpp"
#include "t800/asm/boot_file.hpp"

namespace {

using namespace t800::assembly;
using Bytes = std::vector<std::uint8_t>;

TEST(BootFile, SingleStageIsTheLengthThenTheCode) {
  EXPECT_EQ(single_stage(Bytes{0xF5, 0xF5}), (Bytes{2, 0xF5, 0xF5}));
  const Bytes longest(255, 0x20);
  const Bytes file = single_stage(longest);
  ASSERT_EQ(file.size(), 256u);
  EXPECT_EQ(file[0], 255);
  EXPECT_EQ(Bytes(file.begin() + 1, file.end()), longest);
}

TEST(BootFile, SingleStageRefusesWhatTheChipWouldNotTakeAsCode) {
  EXPECT_THROW(single_stage(Bytes{}), BootFileError);        // 0 would be a poke
  EXPECT_THROW(single_stage(Bytes{0xF5}), BootFileError);    // 1 would be a peek
  EXPECT_THROW(single_stage(Bytes(256, 0)), BootFileError);  // does not fit the length byte
  try {
    single_stage(Bytes(300, 0));
  } catch (const BootFileError& e) {
    EXPECT_NE(std::string(e.what()).find("two_stage"), std::string::npos);
  }
}

TEST(BootFile, PrimaryLoaderBytes) {
  // ajw 5; stl 0, stl 0, stl 1, ldlp 0, ldl 1, ldc 4, in; ldl 1, ldl 0, adc 23 (pfix 1, adc 7),
  // ldc -4 (nfix 0, ldc C), and (opr #46), ldlp -5 (nfix 0, ldlp B), bsub, gajw (opr #3C),
  // adc -20 (nfix 1, adc C); stl 0, stl 1, ldl 0, ldnl 5, stl 2; ldl 0, ldl 1, ldl 2, in; ldl 1,
  // ldl 2, ldl 0, ajw -5 (nfix 0, ajw B), gcall.
  const Bytes expected{0xB5, 0xD0, 0xD0, 0xD1, 0x10, 0x71, 0x44, 0xF7, 0x71, 0x70, 0x21, 0x87, 0x60,
                       0x4C, 0x24, 0xF6, 0x60, 0x1B, 0xF2, 0x23, 0xFC, 0x61, 0x8C, 0xD0, 0xD1, 0x70,
                       0x35, 0xD2, 0x70, 0x71, 0x72, 0xF7, 0x71, 0x72, 0x70, 0x60, 0xBB, 0xF6};
  EXPECT_EQ(primary_loader(), expected);
  EXPECT_EQ(assemble(primary_loader_source()).bytes, expected);
  // Position-independent: the same bytes at any origin.
  EXPECT_EQ(assemble(primary_loader_source(), Options{kMemStartT800, ""}).bytes, expected);
}

TEST(BootFile, ProgramAddressIsTheWordAfterThePrimary) {
  EXPECT_EQ(program_address(kMemStartT800), 0x80000098u);  // #80000070 + 38, rounded up
  EXPECT_EQ(program_address(kMemStartT414), 0x80000070u);  // #80000048 + 38, rounded up
  EXPECT_EQ(program_address(), 0x80000098u);
}

TEST(BootFile, TwoStageLayout) {
  Bytes program(300);
  for (std::size_t i = 0; i < program.size(); ++i) program[i] = std::uint8_t(i * 7);
  const Bytes file = two_stage(program);
  const Bytes& primary = primary_loader();
  ASSERT_EQ(file.size(), 1 + primary.size() + 4 + program.size());
  EXPECT_EQ(file[0], primary.size());
  EXPECT_EQ(Bytes(file.begin() + 1, file.begin() + 1 + long(primary.size())), primary);
  const auto length = file.begin() + 1 + long(primary.size());
  EXPECT_EQ(Bytes(length, length + 4), (Bytes{0x2C, 0x01, 0x00, 0x00}));  // 300, little-endian
  EXPECT_EQ(Bytes(length + 4, file.end()), program);
  EXPECT_THROW(two_stage(Bytes{}), BootFileError);
}

// --- A model of the primary's instructions, from the compiler writer's guide's descriptions, to
// run the loader against a boot stream. Registers the guide leaves undefined (at entry, and after
// `in`, which can deschedule) are filled with junk, so the loader cannot rely on them.
class Model {
 public:
  static constexpr std::uint32_t kBootLinkIn = 0x80000010;  // Link0In
  static constexpr std::uint32_t kJunk = 0xDEADBEEF;

  explicit Model(Bytes stream) : stream_(std::move(stream)) {}

  // The chip's reset-and-boot-from-link: the length byte, the code at MemStart, Wptr on the
  // first word above it, C the channel.
  void boot(std::uint32_t mem_start) {
    const std::uint32_t n = next_byte();
    for (std::uint32_t i = 0; i < n; ++i) memory_[mem_start + i] = next_byte();
    iptr = mem_start;
    wptr = (mem_start + n + 3) & ~3u;
    a = kJunk, b = kJunk + 1, c = kBootLinkIn;
  }

  // Runs until Iptr reaches `stop`; false if that takes too long or an unmodelled byte is met.
  bool run_until(std::uint32_t stop) {
    for (int steps = 0; steps < 1000; ++steps) {
      if (iptr == stop) return true;
      if (!step()) return false;
    }
    return false;
  }

  std::uint8_t byte(std::uint32_t address) const { return memory_.at(address); }
  std::uint32_t word(std::uint32_t address) const {
    std::uint32_t w = 0;
    for (int i = 3; i >= 0; --i) w = w << 8 | byte(address + std::uint32_t(i));
    return w;
  }
  std::size_t unread() const { return stream_.size() - read_; }

  std::uint32_t iptr = 0, wptr = 0, a = 0, b = 0, c = 0, o = 0;

 private:
  std::uint8_t next_byte() { return read_ < stream_.size() ? stream_[read_++] : 0; }
  void store(std::uint32_t address, std::uint32_t w) {
    for (int i = 0; i < 4; ++i) memory_[address + std::uint32_t(i)] = std::uint8_t(w >> (8 * i));
  }
  void push(std::uint32_t v) { c = b, b = a, a = v; }
  std::uint32_t pop() {
    std::uint32_t v = a;
    a = b, b = c, c = kJunk + 2;
    return v;
  }

  bool step() {
    const std::uint8_t instruction = byte(iptr++);
    const std::uint32_t operand = o | (instruction & 0xFu);
    o = 0;
    switch (instruction >> 4) {
      case 0x1:
        push(wptr + 4 * operand);
        return true;  // ldlp
      case 0x2:
        o = operand << 4;
        return true;  // pfix
      case 0x3:
        a = word(a + 4 * operand);
        return true;  // ldnl
      case 0x4:
        push(operand);
        return true;  // ldc
      case 0x6:
        o = ~operand << 4;
        return true;  // nfix
      case 0x7:
        push(word(wptr + 4 * operand));
        return true;  // ldl
      case 0x8:
        a += operand;
        return true;  // adc
      case 0xB:
        wptr += 4 * operand;
        return true;  // ajw
      case 0xD:
        store(wptr + 4 * operand, pop());
        return true;  // stl
      case 0xF:
        return operate(operand);
    }
    return false;
  }

  bool operate(std::uint32_t code) {
    switch (code) {
      case 0x02: {  // bsub: A + B
        std::uint32_t x = pop();
        a += x;
        return true;
      }
      case 0x06:  // gcall: exchange A and Iptr
        std::swap(a, iptr);
        return true;
      case 0x07: {  // in: A bytes from channel B to C; the stack is undefined afterwards
        if (b != kBootLinkIn) return false;
        // The process waits: its Iptr goes to W[-1] and the destination to W[-3] (CWG, "input
        // message"), and the link's words W[-2] may change too.
        store(wptr - 4, iptr);
        store(wptr - 8, kJunk + 4);
        store(wptr - 12, c);
        for (std::uint32_t i = 0; i < a; ++i) memory_[c + i] = next_byte();
        a = b = c = kJunk + 3;
        return true;
      }
      case 0x3C:  // gajw: exchange A and Wptr
        std::swap(a, wptr);
        return true;
      case 0x46: {  // and
        std::uint32_t x = pop();
        a &= x;
        return true;
      }
    }
    return false;
  }

  Bytes stream_;
  std::size_t read_ = 0;
  std::map<std::uint32_t, std::uint8_t> memory_;
};

void expect_loads_and_enters(std::size_t length, std::uint32_t mem_start) {
  Bytes program(length);
  for (std::size_t i = 0; i < length; ++i) program[i] = std::uint8_t(0x5A ^ i);
  Model model(two_stage(program));
  model.boot(mem_start);
  const std::uint32_t p = program_address(mem_start);
  ASSERT_TRUE(model.run_until(p)) << "length " << length << ", stopped at Iptr " << model.iptr;
  for (std::size_t i = 0; i < length; ++i)
    ASSERT_EQ(model.byte(p + std::uint32_t(i)), program[i])
        << "length " << length << ", byte " << i;
  EXPECT_EQ(model.unread(), 0u);
  EXPECT_EQ(model.wptr, p + ((std::uint32_t(length) + 3) & ~3u)) << "length " << length;
  EXPECT_EQ(model.c, Model::kBootLinkIn) << "length " << length;
  EXPECT_EQ(model.b, length);
  EXPECT_EQ(model.word(model.wptr + 20), p);
  EXPECT_EQ(model.word(model.wptr + 24), Model::kBootLinkIn);
  EXPECT_EQ(model.word(model.wptr + 28), length);
}

TEST(BootFile, PrimaryLoadsAndEntersTheProgramOnAModel) {
  // 1 .. 13 cover the new workspace overlapping the old one (a length of 1 .. 4 puts the new
  // W[0] on the old channel word at P+24, 5 .. 8 the new W[0] just above it).
  for (std::size_t length = 1; length <= 13; ++length)
    expect_loads_and_enters(length, kMemStartT800);
  expect_loads_and_enters(300, kMemStartT800);
  expect_loads_and_enters(1000, kMemStartT414);
}

TEST(BootFile, AProgramAssembledForItsLoadAddress) {
  // A program that finds its own data by absolute address, assembled at program_address().
  const auto program =
      assemble("ldc data\nldnl 0\n.align 4\ndata: .word 42", Options{program_address(), ""});
  EXPECT_EQ(program.labels.at("data") % 4, 0u);
  const Bytes file = two_stage(program.bytes);
  EXPECT_EQ(Bytes(file.end() - long(program.bytes.size()), file.end()), program.bytes);
}

}  // namespace
