// What the fuzz targets of the instruction-set simulator's inputs feed it, shared with the test
// that replays the committed corpus (tests/fuzz): machine code, SP request bodies, assembler text.
// One input in, and a verdict, or a Finding (fuzz/harness.hpp) for anything that is a bug.
//
// - run_machine_code (fuzz_decoder): the bytes after the first, loaded at MemStart as a booted
//   program, run on an ISS Core with strict and then with wrap addressing, for at most
//   kMaxInstructions instructions and kMaxCycles cycles. The first byte picks the processor (T800,
//   T805, T414), the installed memory (power of two or not) and whether the links are connected. A
//   halt with a report (undefined operation, wild access under strict, HaltOnError, break, ...) is
//   a refusal; idle, a limit or time running out is acceptance. An exception out of the Core, a
//   halt without a reason, a run past its budget is a Finding; so is a crash or a hang, which the
//   fuzzer itself catches (the sanitizers, -timeout).
// - serve_sp_requests (fuzz_sp_server): the input as framed SP packets (2-byte little-endian
// length,
//   body), up to kMaxRequests of them, or, first byte odd, the rest as one body; each body to
//   SpServer::handle on a fresh temporary root holding a few files, SP.SYSTEM disallowed. handle
//   must not throw, its reply must be a padded body of 6..510 bytes, SP.SYSTEM must never reach the
//   host, and nothing beside the root may change (a sibling directory and its file are checked).
// - assemble_source (fuzz_assembler): the input as assembler source. Assembled (then every
//   instruction of the result disassembled) or refused with an AssemblyError naming a line and
//   column inside the text; any other exception is a Finding.
#pragma once

#include <cstddef>
#include <cstdint>

#include "fuzz/harness.hpp"

namespace fuzz {

inline constexpr std::int64_t kMaxInstructions = 20000;
inline constexpr std::int64_t kMaxCycles = 2'000'000;
inline constexpr int kMaxRequests = 32;

Verdict run_machine_code(const std::uint8_t* data, std::size_t size);
Verdict serve_sp_requests(const std::uint8_t* data, std::size_t size);
Verdict assemble_source(const std::uint8_t* data, std::size_t size);

}  // namespace fuzz
