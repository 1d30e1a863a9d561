#include "network/config_error.hpp"

#include <utility>

#include <fmt/format.h>

namespace network {

namespace {

// One line, whatever it echoes: a newline, a NUL (which would end what()) or another control
// character in a value or a file name is written as an escape.
std::string one_line(const std::string& text) {
  std::string out;
  for (char c : text) {
    const auto u = static_cast<unsigned char>(c);
    if (c == '\n')
      out += "\\n";
    else if (c == '\t')
      out += "\\t";
    else if (u < 0x20 || u == 0x7f)
      out += fmt::format("\\x{:02x}", u);
    else
      out += c;
  }
  return out;
}

// GCC style ("file:line:column: error: message") so editors and IDEs can jump to the spot.
std::string format(const SourcePos& where, const std::string& raw_message) {
  const std::string message = one_line(raw_message);
  if (where.file.empty()) return bounded_message("error: " + message);
  std::string text = one_line(where.file);
  if (where.line > 0) {
    text += ':' + std::to_string(where.line);
    if (where.column > 0) text += ':' + std::to_string(where.column);
  }
  return bounded_message(text + ": error: " + message);
}

constexpr std::size_t kLongWord = 300, kKeepHead = 120, kKeepTail = 60, kMaxMessage = 4096;

bool utf8_continuation(char c) {
  return (static_cast<unsigned char>(c) & 0xC0) == 0x80;
}

// Moves a cut point back so that it does not split a UTF-8 character.
std::size_t char_boundary(const std::string& text, std::size_t at) {
  while (at > 0 && at < text.size() && utf8_continuation(text[at])) --at;
  return at;
}

std::string shortened_word(const std::string& word) {
  const std::size_t head = char_boundary(word, kKeepHead);
  const std::size_t tail = char_boundary(word, word.size() - kKeepTail);
  return word.substr(0, head) + "...[" + std::to_string(word.size()) + " bytes]..." +
         word.substr(tail);
}

}  // namespace

std::string bounded_message(const std::string& text) {
  std::string out;
  std::size_t start = 0;
  while (start < text.size()) {
    std::size_t end = text.find_first_of(" \n", start);
    if (end == std::string::npos) end = text.size();
    const std::string word = text.substr(start, end - start);
    out += word.size() > kLongWord ? shortened_word(word) : word;
    if (end < text.size()) out += text[end];
    start = end + 1;
  }
  if (out.size() > kMaxMessage)
    out = out.substr(0, char_boundary(out, kMaxMessage)) + "...[message cut at " +
          std::to_string(kMaxMessage) + " bytes]";
  return out;
}

ConfigError::ConfigError(SourcePos where, const std::string& message)
    : std::runtime_error(format(where, message)), where_(std::move(where)), message_(message) {}

}  // namespace network
