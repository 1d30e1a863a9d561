// Bounds a TOML text must keep before it is parsed. toml++ parses dotted keys and table headers
// recursively, one stack frame per part, so a key nested some 50,000 levels deep overflows the
// stack (SIGSEGV, no message); bounding depth and size before parsing turns every such input into
// an error with a position. Used by every reader of TOML: topology, scene, calibration, robot and
// paper files, and the --set overrides.
//
// The same pass keeps from toml++ (3.3) what it handles badly, found by fuzzing (fuzz/): invalid
// UTF-8 (thrown from a function that may not throw: std::terminate) and non-ASCII characters outside
// strings and comments (its whitespace test reaches an unreachable point for some, U+039A for one:
// undefined behaviour). TOML allows neither there, so both are errors with their position.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

#include "network/config_error.hpp"

namespace network {

// The shipped files use at most 3 key parts, 2 levels of arrays and strings of a few hundred bytes;
// the limits leave room for far larger hand-written or generated files (a 1024-processor topology
// with every link spelled out is about 100 KB).
struct TomlLimits {
  static constexpr std::size_t kMaxBytes = 4 << 20;  // the whole text
  static constexpr std::size_t kMaxKeyParts = 32;    // a.b.c = 1 has 3, [a.b] 2
  static constexpr std::size_t kMaxNesting = 32;     // arrays and inline tables inside each other
  static constexpr std::size_t kMaxStringBytes = 64 << 10;  // one string (or quoted key)
};

// Throws ConfigError at the first place `text` passes a limit, naming the limit and what is
// allowed. `name` names the text: a file (errors give line:column in it) or, with `positions`
// false, a flag (one line the user typed, named whole). Never throws for malformed TOML: that is
// the parser's to report.
void check_toml_limits(std::string_view text, const std::string& name, bool positions = true);

}  // namespace network
