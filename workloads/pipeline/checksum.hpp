// The checksum the elimination pipeline's recovery sends with every row (README "Faults"): the sum,
// modulo 2^32, of the message's words -- its header and its REALs' bit patterns -- as occam
// computes `sum := sum PLUS w` over the row RETYPED as words; and that loop's code, for its cost on
// the processor that computes it.
#pragma once

#include <cstdint>
#include <cstring>
#include <vector>

#include "t800/isa/instruction.hpp"

namespace workloads {

template <class Value>
void add_words(std::uint32_t& sum, const Value& v) {
  static_assert(sizeof(Value) % 4 == 0, "REAL32 or REAL64");
  std::uint32_t words[sizeof(Value) / 4];
  std::memcpy(words, &v, sizeof(Value));
  for (std::uint32_t w : words) sum += w;
}

// `header` is the message's header word; `values` its REALs (Counted or plain).
template <class Reals>
std::uint32_t checksum(std::uint32_t header, const Reals& values) {
  std::uint32_t sum = header;
  for (const auto& v : values) add_words(sum, v.value());
  return sum;
}

// SEQ i = 0 FOR words: sum := sum PLUS row[i], compiled as occam does (a counted loop, lend).
inline t800::isa::Sequence checksum_code(std::int64_t words) {
  using t800::isa::Op;
  const t800::isa::MemoryRef ws{t800::isa::Region::workspace, -1};
  t800::isa::Sequence code;
  for (std::int64_t i = 0; i < words; ++i)
    for (const t800::isa::Instruction& in :
         t800::isa::Sequence{{Op::ldl, 1, 0, false, ws, "row"},
                             {Op::ldl, 2, 0, false, ws, "i"},
                             {Op::wsub, 0, 0, false, {}, "row[i]"},
                             {Op::ldnl, 0, 0, false, {}, "row[i]"},
                             {Op::ldl, 3, 0, false, ws, "sum"},
                             {Op::sum, 0, 0, false, {}, "PLUS"},
                             {Op::stl, 3, 0, false, ws, "sum"},
                             {Op::ldlp, 2, 0, false, ws, "loop"},
                             {Op::ldc, 8, 0, false, {}, "loop"},
                             {Op::lend, 0, i + 1 < words, false, ws, "loop"}})
      code.push_back(in);
  return code;
}

}  // namespace workloads
