// A T800 assembler (text to bytes) and a one-instruction disassembler, so tests can build the
// programs the instruction-set simulator boots and the simulator can name what it failed on.
//
// Encodings are the instruction table's (t800/isa/opcode.hpp); the rules for prefixes and for
// relative jumps are those of "Transputer instruction set: a compiler writer's guide" (INMOS,
// 1988), cited below as CWG.
//
// Syntax, one statement per line:
//
//   [label:]... [statement] [-- comment | ; comment]
//
//   statement   direct function with an operand     ldc 1083 / j loop / ldc end - here
//               operation or fpu-entry operation    add / in / fpadd / fpuabs   (no operand)
//               opr with an operation code          opr #17C   (codes the table lacks)
//               constant                            name = expr   or   .equ name, expr
//               directive                           .byte e, ...   .word e, ...   .ascii "text"
//                                                   .align n [, fill]   .space n [, fill]
//
//   expr        numbers: 42, -7, #7F (INMOS hex), 0x7F, 'A' (escapes \n \t \r \0 \\ \' \");
//               names (labels, constants); `.` (the address of the current statement);
//               + - * and parentheses. `--` always starts a comment, so write `5 - -3`.
//
// Mnemonics and directives are case-insensitive; labels and constants are case-sensitive and
// may contain letters, digits, `_` and `.` (occam style: `end.loop`), not starting with a digit.
//
// Values are addresses or numbers. A label and `.` are addresses (the origin included);
// address + number and address - number are addresses, address - address is a number, and
// numbers combine freely; anything else (address + address, address * n, -address) is an error.
// `j`, `cj` and `call` given an address jump to it: the operand is the address minus the address
// of the next instruction, because the hardware adds the operand to Iptr once Iptr points past
// the instruction (CWG, "j" / "cj" / "call"). Given a number, they take it as the operand as
// written (`call 0`, as the INMOS primary bootstrap saves its registers). Every other operand is
// the value itself: `ldc label` loads the label's absolute address, `ldc end - here` a distance
// (for ldpi-relative addressing put `here:` after the ldpi).
//
// Operands are 32-bit: a value in -2^31 .. 2^32-1 is taken modulo 2^32 and encoded as the signed
// 32-bit number it is, which never needs more prefixes than the unsigned reading.
//
// Prefix sizing (CWG, "prefixing"): the length of an operand's pfix/nfix chain depends on label
// distances, which depend on lengths. Every instruction starts at its shortest length; each pass
// lays the program out, evaluates every operand and lengthens any instruction whose operand no
// longer fits; lengths never shrink, so the passes end (each instruction can grow only to the
// longest 32-bit chain). The result is always exact: an instruction left longer than its operand
// needs is filled out with leading `pfix 0` bytes (#20), which leave the operand register at
// zero and so change nothing. Because required lengths grow with distances, starting from the
// shortest lengths reaches the least consistent layout for jumps, calls and label differences;
// an instruction can end up a byte longer than necessary only when a value shrinks as the code
// grows: a `.align` whose padding shrinks because code before it grew, or an expression such as
// `ldc 300 - (b - a)`. (Letting lengths shrink again could oscillate for ever on such input.)
// The fill is why an explicit `pfix`/`nfix` statement should only precede an instruction whose
// operand fits its own byte: a fill byte between them would shift the explicit prefix up.
//
// `.align n` (n a power of two, relative to the absolute address) pads with #20 (`pfix 0`) bytes
// unless a fill byte is given, so padding that control falls into is harmless (a pfix 0 after a
// complete instruction leaves the operand register zero; a zero byte would be `j 0`, a
// descheduling point). `.space n` reserves n zero bytes (or the fill given). The counts of
// `.align` and `.space` must not depend on the layout (no labels or `.`), so sizing terminates.
#pragma once

#include <cstddef>
#include <cstdint>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "t800/isa/opcode.hpp"

namespace t800::assembly {

// The first error in the source: where (1-based line and column) and what would be valid.
// what() is "line:column: message", prefixed by the source name when one was given.
class AssemblyError : public std::runtime_error {
 public:
  AssemblyError(std::string source_name, int line, int column, std::string message);
  int line() const { return line_; }
  int column() const { return column_; }
  const std::string& message() const { return message_; }

 private:
  int line_, column_;
  std::string message_;
};

struct Options {
  std::uint32_t origin = 0;  // the address of the first byte (e.g. MemStart, #80000070)
  std::string source_name;   // for messages only ("primary.s")
};

// One source line in the listing: where it landed and what it produced.
struct ListingLine {
  int line = 0;
  std::uint32_t address = 0;
  std::vector<std::uint8_t> bytes;
  std::string source;
};

struct Program {
  std::uint32_t origin = 0;
  std::vector<std::uint8_t> bytes;
  std::map<std::string, std::uint32_t> labels;    // label -> absolute address
  std::map<std::string, std::int64_t> constants;  // `name = expr` -> value
  std::vector<ListingLine> listing;               // every source line, in order
  int sizing_passes = 0;                          // layout passes until the lengths were stable

  // "80000070  24 23 4B  ldc 1083" per line; long data continues on lines of its own.
  std::string listing_text() const;
};

// Throws AssemblyError.
Program assemble(std::string_view source, const Options& options = {});

// One instruction decoded, its pfix/nfix chain folded into the operand, and an fpu-entry pair
// (`ldc code; fpentry`) folded into the operation it selects.
struct Instruction {
  std::optional<isa::Op> op;  // none for an operation code the table lacks (mnemonic "opr")
  std::string mnemonic;       // "ldc", "fpuabs", "opr"; empty if incomplete
  bool has_operand = false;   // direct functions and opr
  std::int32_t operand = 0;   // the operand register's value at the function byte
  int length = 0;             // bytes, prefixes (and an fpu-entry pair's ldc) included
  bool complete = true;       // false: the bytes end inside a prefix chain
  std::optional<std::uint32_t> target;  // j, cj, call: the address jumped to
  std::string text;                     // "ldc 1083", "j -5 (to #0000000B)", "fpuabs"
};

// Decodes the instruction at bytes[offset]; base_address is the address of bytes[0] (for jump
// targets). Throws std::out_of_range if offset is not inside the bytes.
Instruction disassemble(const std::uint8_t* bytes, std::size_t size, std::size_t offset,
                        std::uint32_t base_address = 0);
Instruction disassemble(const std::vector<std::uint8_t>& bytes, std::size_t offset,
                        std::uint32_t base_address = 0);

}  // namespace t800::assembly
