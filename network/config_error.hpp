// An error in a configuration file or a command-line override, with where it is.
#pragma once

#include <stdexcept>
#include <string>

namespace network {

// line and column are 1-based; 0 means "the whole file" (or, for a flag, no position).
struct SourcePos {
  std::string file;  // a path, or a flag such as "--set workload.bytes=x"
  int line = 0;
  int column = 0;
};

// Formats as "file:line:column: error: message" (GCC style, so editors can jump to it), bounded by
// bounded_message (an override's flag or an echoed value may be a megabyte long).
class ConfigError : public std::runtime_error {
 public:
  ConfigError(SourcePos where, const std::string& message);
  const SourcePos& where() const { return where_; }
  const std::string& message() const { return message_; }

 private:
  SourcePos where_;
  std::string message_;
};

// `text` with every word (a run without spaces) longer than 300 bytes cut to its first 120 and last
// 60 bytes around "...[N bytes]...", and the whole cut to 4 KB: a message echoes what the user
// gave, which may be huge, and must stay readable.
std::string bounded_message(const std::string& text);

}  // namespace network
