#include "t800/codegen/frame.hpp"

#include <algorithm>

namespace t800::codegen {

std::string loop_index_name(int depth) {
  static const char* names[] = {"i", "j", "k", "l", "m", "n"};
  return depth < 6 ? names[depth] : "i" + std::to_string(depth);
}

Frame::Frame(const Recording& recording) {
  int depth = 0;
  for (const Event& e : recording.events()) {
    if (e.kind == EventKind::loop_begin) loop_depth_ = std::max(loop_depth_, ++depth);
    if (e.kind == EventKind::loop_end) --depth;
  }
  int next = 2 * loop_depth_ + 2;  // control blocks, integer variable, constant table pointer
  for (const ArrayDecl& a : recording.arrays()) {
    array_base_.push_back(next);
    next += a.storage == ArrayStorage::workspace
                ? int(a.length) * element_words(a, recording.real64())
                : 1;
  }
  fixed_ = next;
}

int Frame::allocate_temporary(int words) {
  std::size_t slot = 0;
  for (;; ++slot) {  // the first run of `words` free words
    bool free = true;
    for (int w = 0; w < words && free; ++w)
      free = slot + std::size_t(w) >= temporary_used_.size() ||
             !temporary_used_[slot + std::size_t(w)];
    if (free) break;
  }
  if (temporary_used_.size() < slot + std::size_t(words))
    temporary_used_.resize(slot + std::size_t(words), false);
  for (int w = 0; w < words; ++w) temporary_used_[slot + std::size_t(w)] = true;
  return fixed_ + int(slot);
}

void Frame::release_temporary(int offset, int words) {
  for (int w = 0; w < words; ++w) {
    const int slot = offset - fixed_ + w;
    if (slot >= 0 && slot < int(temporary_used_.size())) temporary_used_[std::size_t(slot)] = false;
  }
}

}  // namespace t800::codegen
