#include "network/config_error.hpp"

#include <utility>

namespace network {

namespace {

// GCC style ("file:line:column: error: message") so editors and IDEs can jump to the spot.
std::string format(const SourcePos& where, const std::string& message) {
  std::string text = where.file;
  if (where.line > 0) {
    text += ':' + std::to_string(where.line);
    if (where.column > 0) text += ':' + std::to_string(where.column);
  }
  return text + ": error: " + message;
}

}  // namespace

ConfigError::ConfigError(SourcePos where, const std::string& message)
    : std::runtime_error(format(where, message)), where_(std::move(where)), message_(message) {}

}  // namespace network
