#include "t800/asm/boot_file.hpp"

#include <algorithm>

#include <string>

#include "t800/asm/assembler.hpp"

namespace t800::assembly {

namespace {

constexpr std::size_t kMinFirstStage = 2, kMaxFirstStage = 255;  // 0, 1: poke, peek

// The primary loader. It has no absolute addresses, so its bytes serve any MemStart (T414 and
// T800 alike); it uses only T414 instructions. Stack effects per the compiler writer's guide:
// a load pushes (A to B, B to C), a store pops (B to A, C to B); `in` takes the count in A, the
// channel in B, the destination in C, and, like every instruction that can deschedule, leaves
// A, B, C undefined, which is why everything the loader needs later lives in memory.
//
// Workspace. At entry Wptr = P, the word after the loader, which is where the program goes. A
// process waiting in `in` keeps its Iptr and its destination in the words just below Wptr (CWG,
// "input message": W[-1], W[-3]), so the loader first moves its workspace five words up, leaving
// its own code intact below, and keeps the length and the channel at P+20 and P+24. Once the
// length L is known the workspace moves to Q = P + L rounded up to a word + 20: the five words
// below Q, which the second `in` uses, lie above the program it reads over P. The new words are at
// Q, Q+4, Q+8 with Q >= P+24, so the length at P+20 is never overwritten before it is copied; the
// channel at P+24 is carried on the stack through gajw. Before entering the program the loader
// steps Wptr back down to P + L rounded up, where the hardware puts it above a first stage.
constexpr std::string_view kPrimary =
    R"(-- t800sim primary loader: reads a 4-byte length, then that many bytes, from the boot link
-- into memory right after itself, then enters them as a hardware boot enters a first stage.
-- Entry: Iptr = MemStart, Wptr = P (the word after this code), C = boot link input channel.
        ajw   5          -- Wptr = P+20: the words a waiting `in` takes below it are not code
        stl   0          -- pop the undefined A: A = B, B = C (the channel)
        stl   0          -- pop the undefined B: A = the channel
        stl   1          -- W[1] (P+24) = channel
        ldlp  0          -- C for in: the length goes to W[0] (P+20)
        ldl   1          -- B for in: the channel
        ldc   4          -- A for in: 4 bytes
        in               -- W[0] = program length L, little-endian
        ldl   1          -- the channel, kept on the stack (in B or C) through gajw
        ldl   0          -- L
        adc   23         -- L + 3 (to round up) + 20 (the five words below the new Wptr)
        ldc   -4         -- a mask of whole words
        and              -- L rounded up to a word, + 20
        ldlp  -5         -- P
        bsub             -- A = Q = P + rounded L + 20; B = channel
        gajw             -- Wptr = Q; A = P+20 (the old Wptr); B = channel
        adc   -20        -- P, where the program goes and starts
        stl   0          -- W[0] (Q) = P
        stl   1          -- W[1] = channel
        ldl   0          -- P
        ldnl  5          -- L, from the old W[0] at P+20 (below every new word)
        stl   2          -- W[2] = L
        ldl   0          -- C for in: P
        ldl   1          -- B for in: the channel
        ldl   2          -- A for in: L bytes
        in               -- the program, at P .. P+L-1 (over the old workspace words)
        ldl   1          -- C at entry: the channel, as at reset
        ldl   2          -- B at entry: L
        ldl   0          -- A: the program's first byte
        ajw   -5         -- Wptr = P + rounded L, just above the program
        gcall            -- Iptr = P, A = the return address
)";

std::uint32_t round_up_to_word(std::uint32_t n) {
  return (n + 3u) & ~3u;
}

}  // namespace

std::vector<std::uint8_t> single_stage(const std::vector<std::uint8_t>& code) {
  if (code.size() < kMinFirstStage || code.size() > kMaxFirstStage)
    throw BootFileError(
        "a first boot stage has 2 .. 255 bytes (a first byte of 0 or 1 is a poke "
        "or a peek), not " +
        std::to_string(code.size()) + "; use two_stage for longer programs");
  std::vector<std::uint8_t> out(code.size() + 1);
  out[0] = std::uint8_t(code.size());
  std::copy(code.begin(), code.end(), out.begin() + 1);
  return out;
}

std::string_view primary_loader_source() {
  return kPrimary;
}

const std::vector<std::uint8_t>& primary_loader() {
  static const std::vector<std::uint8_t> bytes =
      assemble(kPrimary, Options{0, "primary loader"}).bytes;
  return bytes;
}

// The hardware puts Wptr on the first word above the first stage (t4 main.c rounds
// MemStart + n up to a word), and the primary loads the program there.
std::uint32_t program_address(std::uint32_t mem_start) {
  return round_up_to_word(mem_start + std::uint32_t(primary_loader().size()));
}

std::vector<std::uint8_t> two_stage(const std::vector<std::uint8_t>& program) {
  if (program.empty()) throw BootFileError("two_stage: the program is empty");
  if (program.size() > 0xFFFFFFFFu) throw BootFileError("two_stage: the program exceeds 4 GiB");
  std::vector<std::uint8_t> out = single_stage(primary_loader());
  const auto length = std::uint32_t(program.size());
  for (int b = 0; b < 4; ++b) out.push_back(std::uint8_t(length >> (8 * b)));  // little-endian
  out.insert(out.end(), program.begin(), program.end());
  return out;
}

}  // namespace t800::assembly
