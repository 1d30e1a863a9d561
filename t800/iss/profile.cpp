#include "t800/iss/profile.hpp"

#include <algorithm>

namespace t800::iss {

namespace {
template <class Key>
void most_cycles_first(std::vector<std::pair<Key, Tally>>& v) {
  std::sort(v.begin(), v.end(), [](const auto& a, const auto& b) {
    return a.second.cycles != b.second.cycles ? a.second.cycles > b.second.cycles
                                              : a.first < b.first;
  });
}
}  // namespace

std::vector<std::pair<isa::Op, Tally>> InstructionProfile::operations() const {
  std::vector<std::pair<isa::Op, Tally>> v;
  for (int op = 0; op < isa::kOpCount; ++op)
    if (ops_[std::size_t(op)].instructions) v.emplace_back(isa::Op(op), ops_[std::size_t(op)]);
  most_cycles_first(v);
  return v;
}

std::vector<std::pair<Word, Tally>> InstructionProfile::hottest_blocks(std::size_t n) const {
  std::vector<std::pair<Word, Tally>> v;
  v.reserve(blocks_.size());
  for (const auto& [block, tally] : blocks_) v.emplace_back(block * kBlockBytes, tally);
  most_cycles_first(v);
  if (v.size() > n) v.resize(n);
  return v;
}

}  // namespace t800::iss
