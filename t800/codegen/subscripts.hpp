// How the generated code addresses each recorded array element: with a constant subscript, or
// subscripted by the index of the replicated SEQ it runs in (plus a constant). A recording only
// has concrete indices, so this is read off the iterations: an element a loop's consecutive
// iterations reach at the same place in their work with the same index is a constant subscript;
// with indices that move with the loop's index, `a[i + c]`. Elements read before a loop and used
// inside it keep their constant subscript.
#pragma once

#include <cstdint>
#include <vector>

#include "t800/codegen/recording.hpp"

namespace t800::codegen {

struct Subscript {
  bool by_loop = false;     // a[i + offset], i the index of the loop at `depth`
  int depth = 0;            // nesting depth of that loop (0 = outermost)
  std::int64_t offset = 0;  // by_loop: c; otherwise the constant subscript itself
};

// One entry per access of the recording.
std::vector<Subscript> classify_subscripts(const Recording& recording);

}  // namespace t800::codegen
