// Every error the assembler reports: its line, its column (1-based, of the offending token) and
// that the message says what would be valid.
#include <gtest/gtest.h>

#include "t800/asm/assembler.hpp"

namespace {

using t800::assembly::assemble;
using t800::assembly::AssemblyError;
using t800::assembly::Options;

struct Expected {
  int line, column;
  std::string says;
};

Expected error_of(const std::string& source, Options options = {}) {
  try {
    assemble(source, options);
  } catch (const AssemblyError& e) {
    return Expected{e.line(), e.column(), e.message()};
  }
  return Expected{0, 0, "(no error)"};
}

#define EXPECT_ERROR(source, line_, column_, text)                                \
  do {                                                                            \
    Expected got = error_of(source);                                              \
    EXPECT_EQ(got.line, line_) << got.says;                                       \
    EXPECT_EQ(got.column, column_) << got.says;                                   \
    EXPECT_NE(got.says.find(text), std::string::npos) << "message: " << got.says; \
  } while (0)

TEST(Errors, UnknownMnemonicNamesTheNearest) {
  EXPECT_ERROR("  ldcc 4", 1, 3, "unknown instruction 'ldcc'; the nearest is 'ldc'");
  EXPECT_ERROR("add\n fpadd\n\tfpaddd", 3, 2, "the nearest is 'fpadd'");
  EXPECT_ERROR("sttimr", 1, 1, "the nearest is 'sttimer'");
}

TEST(Errors, ALabelWithoutItsColon) {
  EXPECT_ERROR("loop ldc 1", 1, 1, "'loop' is not an instruction; to label the line write 'loop:'");
}

TEST(Errors, UnknownDirectiveNamesTheNearest) {
  EXPECT_ERROR("x: .wrod 1", 1, 4, "unknown directive '.wrod'; the nearest is '.word'");
  EXPECT_ERROR(".asci \"a\"", 1, 1, "the nearest is '.ascii'");
}

TEST(Errors, OperationGivenAnOperand) {
  EXPECT_ERROR("ldc 1\n  fpadd 3", 2, 9, "'fpadd' is an operation and takes no operand; found '3'");
  EXPECT_ERROR("fpuabs x", 1, 8, "takes no operand");
}

TEST(Errors, DirectFunctionWithoutOperand) {
  EXPECT_ERROR("  ldc", 1, 3, "'ldc' needs an operand");
  EXPECT_ERROR("j  -- where to?", 1, 1, "'j' needs an operand");
}

TEST(Errors, UndefinedNameNamesTheNearest) {
  EXPECT_ERROR("somewhere: add\n  j nowhere", 2, 5,
               "undefined name 'nowhere'; the nearest defined is 'somewhere'");
  EXPECT_ERROR("ldc 1 + missing", 1, 9, "undefined name 'missing'; no labels or constants");
  EXPECT_ERROR("Loop: j loop", 1, 9, "the nearest defined is 'Loop'");  // names keep their case
}

TEST(Errors, OperandOutOfThirtyTwoBitRange) {
  EXPECT_ERROR("ldc #100000000", 1, 5, "operand 4294967296 is outside the 32-bit range");
  EXPECT_ERROR("ldc -2147483649", 1, 5, "(-2147483648 .. 4294967295)");
  EXPECT_ERROR("add\nldc (1 + #FFFFFFFF)", 2, 5, "operand 4294967296");
  EXPECT_ERROR("j #100000000", 1, 3, "operand 4294967296 is outside");
  EXPECT_ERROR("opr -2147483649", 1, 5, "is outside the 32-bit range");
}

TEST(Errors, JumpDistanceOutOfRange) {
  Expected got = error_of("j far\nfar = . + #100000000", Options{});
  EXPECT_EQ(got.line, 1);
  EXPECT_EQ(got.column, 3);
  EXPECT_NE(got.says.find("jump distance"), std::string::npos) << got.says;
}

TEST(Errors, GarbageAfterAnOperand) {
  EXPECT_ERROR("ldc 1 2", 1, 7, "unexpected '2' after the operand; a comment starts with -- or ;");
  EXPECT_ERROR("ldc 1, 2", 1, 6, "unexpected ','");
  EXPECT_ERROR(".ascii \"a\" x", 1, 12, "unexpected 'x' after the string");
  EXPECT_ERROR("N = 1 1", 1, 7, "after the value");
  EXPECT_ERROR(".byte 1 2", 1, 9, "after the values");
}

TEST(Errors, DuplicateLabel) {
  EXPECT_ERROR("x: add\n  x: sub", 2, 3, "'x' is already defined at line 1");
  EXPECT_ERROR("x = 1\nx: add", 2, 1, "'x' is already defined at line 1");
  EXPECT_ERROR("a: b: a: add", 1, 7, "'a' is already defined at line 1");
}

TEST(Errors, ByteAndWordValuesOutOfRange) {
  EXPECT_ERROR(".byte 1, 256", 1, 10, "'.byte' value 256 is outside a byte (-128 .. 255)");
  EXPECT_ERROR(".byte -129", 1, 7, "-129 is outside a byte");
  EXPECT_ERROR(".word #100000000", 1, 7, "'.word' value 4294967296 is outside the 32-bit range");
}

TEST(Errors, AlignAndSpaceCounts) {
  EXPECT_ERROR(".align 3", 1, 8, "'.align' needs a power of two from 1 to 65536, not 3");
  EXPECT_ERROR(".align 0", 1, 8, "not 0");
  EXPECT_ERROR(".space -1", 1, 8, "'.space' needs a count from 0 to");
  EXPECT_ERROR(".space end\nend:", 1, 8, "'.space' count must be known before layout");
  EXPECT_ERROR("N = end - .\n.align N\nend:", 2, 8, "'.align' count must be known before layout");
  EXPECT_ERROR(".align 4, 300", 1, 11, "'.align' fill 300 does not fit a byte");
  EXPECT_ERROR(".space 1, 2, 3", 1, 14, "takes a count and at most a fill byte");
}

TEST(Errors, AddressArithmetic) {
  EXPECT_ERROR("a: b: ldc a + b", 1, 13, "cannot add two addresses");
  EXPECT_ERROR("a: ldc 3 - a", 1, 10, "cannot subtract an address from a number");
  EXPECT_ERROR("a: ldc a * 2", 1, 10, "'*' needs two numbers");
  EXPECT_ERROR("a: ldc -a", 1, 8, "cannot negate an address");
  EXPECT_ERROR("ldc #7FFFFFFFFFFFFFFF * 2", 1, 23, "the value overflows 64 bits");
}

TEST(Errors, ConstantDefinedInTermsOfItself) {
  EXPECT_ERROR("a = b\nb = a", 1, 5, "constant 'b' is defined in terms of itself");
  EXPECT_ERROR("ldc n\nn = n + 1", 2, 5, "constant 'n' is defined in terms of itself");
}

TEST(Errors, MalformedExpressions) {
  EXPECT_ERROR("ldc (1 + 2", 1, 11, "expected ')' to close the '(' at column 5");
  EXPECT_ERROR("ldc 1 +", 1, 8, "expected a value (a number, a name, '.' or '('), found the end");
  EXPECT_ERROR("ldc * 2", 1, 5, "expected a value");
  EXPECT_ERROR("x: 5", 1, 4, "expected an instruction, a directive, 'label:' or 'name = value'");
  EXPECT_ERROR(".equ 5, 3", 1, 6, "'.equ' needs a name, then ',' and a value");
  EXPECT_ERROR(".ascii 5", 1, 8, "'.ascii' needs a string in double quotes");
}

TEST(Errors, MalformedTokens) {
  EXPECT_ERROR("ldc $5", 1, 5, "unexpected character '$'");
  EXPECT_ERROR("ldc 12ab", 1, 5, "malformed number '12ab'; write decimal (42), hex as #2A or 0x2A");
  EXPECT_ERROR("ldc #", 1, 5, "'#' must be followed by hex digits");
  EXPECT_ERROR("ldc 0xg", 1, 5, "'0x' must be followed by hex digits");
  EXPECT_ERROR("ldc #12G", 1, 5, "malformed number '#12G'");
  EXPECT_ERROR("ldc 99999999999999999999", 1, 5, "number too large");
  EXPECT_ERROR(".ascii \"abc", 1, 8, "the string has no closing \"");
  EXPECT_ERROR(".ascii \"a\\qb\"", 1, 10, "unknown escape '\\q'; valid are \\n");
  EXPECT_ERROR("ldc ''", 1, 5, "empty character literal");
  EXPECT_ERROR("ldc 'ab'", 1, 5, "a character literal holds one character");
  EXPECT_ERROR("ldc 'a", 1, 5, "a character literal holds one character");
}

TEST(Errors, ProgramPastTheTopOfTheAddressSpace) {
  Expected got = error_of("add\n.space 4", Options{0xFFFFFFFC, ""});
  EXPECT_EQ(got.line, 2);
  EXPECT_NE(got.says.find("passes the top of the 32-bit address space"), std::string::npos);
}

TEST(Errors, WhatNamesTheSourceLineAndColumn) {
  try {
    assemble("add\n  ldcc 4", Options{0, "boot.s"});
    FAIL() << "no error";
  } catch (const AssemblyError& e) {
    EXPECT_EQ(std::string(e.what()),
              "boot.s:2:3: unknown instruction 'ldcc'; the nearest is 'ldc'");
  }
  try {
    assemble("ldcc 4");
    FAIL() << "no error";
  } catch (const AssemblyError& e) {
    EXPECT_EQ(std::string(e.what()), "1:1: unknown instruction 'ldcc'; the nearest is 'ldc'");
  }
}

TEST(Errors, TheFirstErrorIsReported) {
  EXPECT_ERROR("add\nbogus1\nbogus2", 2, 1, "'bogus1'");
}

}  // namespace
