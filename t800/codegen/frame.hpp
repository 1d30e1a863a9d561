// The workspace frame of a generated PROC: which word holds what. Low offsets are the cheapest to
// reach (ldl/stl/ldlp take no prefix byte below 16), so the words used on every iteration come
// first: the loop control blocks (index, count) by nesting depth, an integer variable for
// integer statements, the pointer to the constant table, the arrays' base pointers (or the arrays
// themselves when they live in the workspace), then temporaries. Temporaries whose lifetimes do not
// overlap share a word, as the compiler overlays the workspace of scopes that do not overlap.
#pragma once

#include <string>
#include <vector>

#include "t800/codegen/recording.hpp"

namespace t800::codegen {

// A loop's index as listings name it: i, j, k, ... by nesting depth.
std::string loop_index_name(int depth);

class Frame {
 public:
  explicit Frame(const Recording& recording);

  int loop_index(int depth) const { return 2 * depth; }  // the count is the word after
  int integer_variable() const { return 2 * loop_depth_; }
  int constant_table() const { return 2 * loop_depth_ + 1; }  // pointer to the REAL constants
  int array_base(int array) const { return array_base_[std::size_t(array)]; }

  // A temporary of `words` consecutive words (2 for a REAL64).
  int allocate_temporary(int words = 1);
  void release_temporary(int offset, int words = 1);

  // The frame's size in words, the call linkage (Iptr and the three saved registers) included.
  int words() const { return fixed_ + int(temporary_used_.size()) + kLinkage; }

 private:
  static constexpr int kLinkage = 4;
  int loop_depth_ = 0;
  int fixed_ = 0;
  std::vector<int> array_base_;
  std::vector<bool> temporary_used_;
};

}  // namespace t800::codegen
