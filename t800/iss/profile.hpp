// Where a processor's cycles go, instruction by instruction: each operation's count and cycles, and
// each 64-byte block of code's. The core keeps one while a profile is asked for (Core::set_profile:
// a branch per instruction otherwise); what the processor waited for is its node's to add
// (workloads/boot/iss_node.cpp). `t800sim boot --profile` writes it, tools/plot profile draws it.
#pragma once

#include <array>
#include <cstdint>
#include <unordered_map>
#include <utility>
#include <vector>

#include "t800/isa/opcode.hpp"
#include "t800/iss/machine_words.hpp"

namespace t800::iss {

struct Tally {
  std::int64_t instructions = 0;
  std::int64_t cycles = 0;  // from the instruction's issue to the next's: its waits included
};

class InstructionProfile {
 public:
  static constexpr Word kBlockBytes = 64;

  void record(isa::Op op, Word address, std::int64_t cycles) {
    add(ops_[std::size_t(op)], cycles);
    add(blocks_[address / kBlockBytes], cycles);
  }
  const Tally& of(isa::Op op) const { return ops_[std::size_t(op)]; }
  // The operations executed, most cycles first.
  std::vector<std::pair<isa::Op, Tally>> operations() const;
  // The `n` blocks of code with the most cycles, as (first address, tally), most cycles first.
  std::vector<std::pair<Word, Tally>> hottest_blocks(std::size_t n) const;

 private:
  static void add(Tally& t, std::int64_t cycles) {
    ++t.instructions;
    t.cycles += cycles;
  }
  std::array<Tally, isa::kOpCount> ops_{};
  std::unordered_map<Word, Tally> blocks_;  // by address / kBlockBytes
};

}  // namespace t800::iss
