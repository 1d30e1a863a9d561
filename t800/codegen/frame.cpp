#include "t800/codegen/frame.hpp"

#include <algorithm>

namespace t800::codegen {

Frame::Frame(const Recording& recording) {
  int depth = 0;
  for (const Event& e : recording.events()) {
    if (e.kind == EventKind::loop_begin) loop_depth_ = std::max(loop_depth_, ++depth);
    if (e.kind == EventKind::loop_end) --depth;
  }
  int next = 2 * loop_depth_ + 2;  // control blocks, integer variable, constant table pointer
  const int words = recording.real64() ? 2 : 1;
  for (const ArrayDecl& a : recording.arrays()) {
    array_base_.push_back(next);
    next += a.storage == ArrayStorage::workspace ? int(a.length) * words : 1;
  }
  fixed_ = next;
}

int Frame::allocate_temporary() {
  auto free = std::find(temporary_used_.begin(), temporary_used_.end(), false);
  if (free == temporary_used_.end()) free = temporary_used_.insert(free, false);
  *free = true;
  return fixed_ + int(free - temporary_used_.begin());
}

void Frame::release_temporary(int offset) {
  const int slot = offset - fixed_;
  if (slot >= 0 && slot < int(temporary_used_.size())) temporary_used_[std::size_t(slot)] = false;
}

}  // namespace t800::codegen
