#include "t800/iss/decoder.hpp"

#include <array>

#include "t800/processors/timing_stepper.hpp"

namespace t800::iss {

using isa::Encoding;
using isa::Op;

namespace {

constexpr int kFunctionPfix = 0x2, kFunctionNfix = 0x6, kFunctionOpr = 0xF, kFunctionLdc = 0x4;
constexpr int kCodes = 0x200;  // operation codes and fpentry selectors below this

struct CodeMaps {
  std::array<std::int16_t, kCodes> operation{}, fpu_entry{};
  std::array<Op, 16> direct{};
  CodeMaps() {
    operation.fill(-1);
    fpu_entry.fill(-1);
    for (int i = 0; i < isa::kOpCount; ++i) {
      const isa::OpInfo& info = isa::info(Op(i));
      if (info.encoding == Encoding::direct) direct[std::size_t(info.code)] = info.op;
      if (info.encoding == Encoding::operate) operation[std::size_t(info.code)] = std::int16_t(i);
      if (info.encoding == Encoding::fpu_entry) fpu_entry[std::size_t(info.code)] = std::int16_t(i);
    }
  }
};

const CodeMaps& maps() {
  static const CodeMaps m;
  return m;
}

std::optional<Op> lookup(const std::array<std::int16_t, kCodes>& map, std::int64_t code) {
  if (code < 0 || code >= kCodes || map[std::size_t(code)] < 0) return std::nullopt;
  return Op(map[std::size_t(code)]);
}

// One direct function with its prefixes: the function code, the operand built, the bytes taken.
struct Raw {
  int function;
  std::int32_t operand;
  int bytes;
};

Raw raw_at(const Memory& memory, Word iptr) {
  std::uint32_t operand = 0;
  int bytes = 0;
  for (;;) {
    const std::uint8_t b = memory.byte(iptr + Word(bytes++));
    const int function = b >> 4;
    operand |= b & 0xFu;
    if (function == kFunctionPfix) {
      operand <<= 4;
    } else if (function == kFunctionNfix) {
      operand = (~operand) << 4;
    } else {
      return {function, std::int32_t(operand), bytes};
    }
    if (bytes == kMaxInstructionBytes)  // a runaway prefix chain: pfix or nfix, undefined
      return {function, std::int32_t(operand), bytes};
  }
}

}  // namespace

std::optional<Op> operation_of(std::int64_t code) {
  return lookup(maps().operation, code);
}

std::optional<Op> fpu_entry_of(std::int64_t selector) {
  return lookup(maps().fpu_entry, selector);
}

Decoded decode(const Memory& memory, Word iptr) {
  const Raw raw = raw_at(memory, iptr);
  Decoded d;
  d.bytes = std::uint8_t(raw.bytes);
  d.operand = raw.operand;
  if (raw.function != kFunctionOpr) {
    d.op = maps().direct[std::size_t(raw.function)];
    d.defined = raw.function != kFunctionPfix && raw.function != kFunctionNfix;
    d.prefix_cycles = std::uint8_t(raw.bytes - 1);
    if (d.op == Op::ldc) {
      // `ldc selector; fpentry` is the FPU-entry operation the selector names.
      const Raw next = raw_at(memory, iptr + Word(raw.bytes));
      const auto entry = fpu_entry_of(raw.operand);
      if (entry && next.function == kFunctionOpr && operation_of(next.operand) == Op::fpentry &&
          raw.bytes + next.bytes <= kMaxInstructionBytes) {
        d.op = *entry;
        d.bytes = std::uint8_t(raw.bytes + next.bytes);
        d.prefix_cycles = std::uint8_t(prefix_cycles(*entry, 0));
        d.operand = 0;
      }
    }
    return d;
  }
  const auto op = operation_of(raw.operand);
  d.defined = op.has_value();
  d.op = op.value_or(Op::rev);
  d.prefix_cycles = std::uint8_t(raw.bytes - 1);
  return d;
}

DecodeCache::DecodeCache(Memory& memory) : memory_(memory), slots_(kSlots) {
  memory_.on_code_written([this](std::uint32_t line) { invalidate_line(line); });
}

void DecodeCache::clear() {
  for (Slot& s : slots_) s.valid = false;
}

const Decoded& DecodeCache::fill(Slot& s, Word iptr) {
  ++misses_;
  s.decoded = decode(memory_, iptr);
  s.iptr = iptr;
  s.valid = true;
  for (int k = 0; k < s.decoded.bytes; ++k) memory_.mark_code(memory_.offset(iptr + Word(k)));
  // A fused `ldc; fpentry` also depends on the bytes after it being what they were.
  return s.decoded;
}

void DecodeCache::invalidate_line(std::uint32_t line_offset) {
  // Any instruction with a byte in the line: it started at most kMaxInstructionBytes before it
  // (a fused `ldc; fpentry` included). The slots are indexed by address, so the line's
  // instructions (and those that run into it) sit in consecutive slots; their tags say whether
  // they are the line's.
  const Word line = kMostNeg + line_offset;
  constexpr std::uint32_t line_bytes = 1u << Memory::kLineShift;
  for (Word a = line - Word(kMaxInstructionBytes); a != line + line_bytes; ++a) {
    Slot& s = slots_[a & kMask];
    if (!s.valid) continue;
    const std::uint32_t start = memory_.offset(s.iptr);
    if (start + s.decoded.bytes > line_offset && start < line_offset + line_bytes) s.valid = false;
  }
}

}  // namespace t800::iss
