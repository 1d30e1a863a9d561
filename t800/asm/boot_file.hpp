// Boot files: the byte stream a host sends down a link to a T800 that boots from link.
//
// At reset the chip waits for a byte on any link. A byte n >= 2 means n bytes of code follow;
// they are loaded at MemStart and run at low priority, Iptr = MemStart, Wptr the first word
// above the code, and C holding the address of the boot link's input channel (T800 datasheet;
// pahihu/t4 main.c and examples/bootload.asm; docs: /work/shared/reference/t800-iss.md). 0 and 1
// are poke and peek, so a first stage has 2 .. 255 bytes.
//
// A program longer than that is sent in two stages (two_stage): a small primary loader of ours
// (primary_loader_source(), 38 bytes, position-independent, T414-compatible) as the first stage,
// then the program's length as a 4-byte little-endian word, then the program. The primary reads the
// length and the program from the boot link into memory right after itself (program_address())
// and enters it the way the hardware enters a first stage:
//
//   Iptr = program_address(mem_start)
//   Wptr = program_address(mem_start) + length rounded up to a word (just above the program)
//   C    = the boot link's input channel, as at reset
//   B    = the program's length in bytes
//   A    = the address after the primary's gcall (of no use)
//   W[5] = Iptr, W[6] = the boot link's input channel, W[7] = the length (the primary's own
//          variables, left in the program's workspace; a program may overwrite them)
//
// so a program written to be booted directly runs unchanged through the two-stage loader, once
// it is assembled for its load address (program_address()) if it uses absolute addresses.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string_view>
#include <vector>

namespace t800::assembly {

constexpr std::uint32_t kMemStartT800 = 0x80000070;  // T800, T805
constexpr std::uint32_t kMemStartT414 = 0x80000048;

class BootFileError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

// [n][code] for code of 2 .. 255 bytes; throws BootFileError otherwise.
std::vector<std::uint8_t> single_stage(const std::vector<std::uint8_t>& code);

// The primary loader's assembler text (commented line by line) and its bytes.
std::string_view primary_loader_source();
const std::vector<std::uint8_t>& primary_loader();

// Where two_stage's program is loaded and entered on a processor whose MemStart is mem_start.
std::uint32_t program_address(std::uint32_t mem_start = kMemStartT800);

// [n][primary][length, 4 bytes little-endian][program] for a program of at least one byte;
// throws BootFileError for an empty one.
std::vector<std::uint8_t> two_stage(const std::vector<std::uint8_t>& program);

}  // namespace t800::assembly
