#include "network/toml_limits.hpp"

#include <optional>
#include <vector>

namespace network {

namespace {

// A lexical pass that knows just enough TOML to tell keys, headers, values, strings, comments and
// brackets apart. It measures, and refuses only what toml++ must not see (the header says what);
// other malformed text is the parser's to report.
class LimitScanner {
 public:
  LimitScanner(std::string_view text, const std::string& name, bool positions)
      : text_(text), name_(name), positions_(positions) {}

  void scan() {
    if (text_.size() > TomlLimits::kMaxBytes)
      fail({}, "the text is " + std::to_string(text_.size()) + " bytes; at most " +
                   std::to_string(TomlLimits::kMaxBytes) + " are read");
    check_utf8();
    bool key_next = true;  // at the start of a line outside brackets, or after '{' or ','
    while (i_ < text_.size()) {
      if (key_next) {
        key_or_header();
        key_next = false;
        continue;
      }
      const char c = text_[i_];
      if ((c == '"' || c == '\'') && value_start_) {
        string();
        value_start_ = false;
      } else if (c == '#') {
        comment();
      } else if (c == '\n') {
        advance();
        key_next = open_.empty();
      } else if (c == ' ' || c == '\t' || c == '\r') {
        advance();
      } else if (c == '[' || c == '{') {  // an array's first value starts here if the array does
        const Position at = here();
        advance();
        open_.push_back(c);
        if (open_.size() > TomlLimits::kMaxNesting)
          fail(at, "arrays and inline tables nested more than " +
                       std::to_string(TomlLimits::kMaxNesting) + " deep");
        key_next = c == '{';
      } else if (c == ']' || c == '}') {
        value_start_ = false;
        advance();
        if (!open_.empty()) open_.pop_back();
      } else if (c == ',') {
        value_start_ = true;
        advance();
        key_next = !open_.empty() && open_.back() == '{';
      } else if (static_cast<unsigned char>(c) >= 0x80) {
        fail_non_ascii(here());
      } else {  // a bare value (or garbage): toml++ reads on to a space, ',', ']', ...
        value_start_ = false;
        advance();
      }
    }
  }

 private:
  struct Position {
    int line = 0, column = 0;
  };

  Position here() const { return {line_, column_}; }

  // Length of the UTF-8 sequence at `at`, or 0 when it is not one (a stray continuation byte, a
  // truncated or overlong sequence, a surrogate, beyond U+10FFFF).
  std::size_t utf8_length(std::size_t at) const {
    const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text_[at + k]); };
    const unsigned char b = byte(0);
    if (b < 0x80) return 1;
    const std::size_t n = b >= 0xF0 ? 4 : b >= 0xE0 ? 3 : b >= 0xC2 ? 2 : 0;
    if (n == 0 || b > 0xF4 || at + n > text_.size()) return 0;
    for (std::size_t k = 1; k < n; ++k)
      if ((byte(k) & 0xC0) != 0x80) return 0;
    if ((b == 0xE0 && byte(1) < 0xA0) || (b == 0xED && byte(1) >= 0xA0) ||  // overlong, surrogate
        (b == 0xF0 && byte(1) < 0x90) || (b == 0xF4 && byte(1) >= 0x90))    // overlong, > U+10FFFF
      return 0;
    return n;
  }

  // The whole text first, with the position of the first bad byte.
  void check_utf8() const {
    int line = 1, column = 1;
    for (std::size_t at = 0; at < text_.size();) {
      const std::size_t n = utf8_length(at);
      if (n == 0) fail({line, column}, "invalid UTF-8 (TOML files are UTF-8 text)");
      if (text_[at] == '\n') {
        ++line;
        column = 1;
      } else {
        ++column;
      }
      at += n;
    }
  }

  [[noreturn]] void fail_non_ascii(Position at) const {
    fail(at,
         "a non-ASCII character outside a string or comment; TOML allows them only in strings, "
         "quoted keys and comments");
  }

  [[noreturn]] void fail(Position at, const std::string& message) const {
    if (!positions_ || at.line == 0) throw ConfigError({name_, 0, 0}, message);
    throw ConfigError({name_, at.line, at.column}, message);
  }

  void advance() {
    if (text_[i_] == '\n') {
      ++line_;
      column_ = 1;
    } else {
      ++column_;
    }
    ++i_;
  }

  bool at(std::string_view s) const { return text_.substr(i_, s.size()) == s; }

  void skip_blanks() {
    while (i_ < text_.size() && (text_[i_] == ' ' || text_[i_] == '\t' || text_[i_] == '\r'))
      advance();
  }

  void comment() {
    while (i_ < text_.size() && text_[i_] != '\n') advance();
  }

  // Blank lines and comments, then a table header or a (dotted) key.
  void key_or_header() {
    while (i_ < text_.size()) {
      skip_blanks();
      if (i_ < text_.size() && text_[i_] == '#') comment();
      if (i_ < text_.size() && text_[i_] == '\n' && open_.empty()) {
        advance();
        continue;
      }
      break;
    }
    if (i_ >= text_.size()) return;
    if (open_.empty() && text_[i_] == '[') {
      advance();
      if (i_ < text_.size() && text_[i_] == '[') advance();
      key("a table header");
      skip_blanks();
      for (int n = 0; n < 2 && i_ < text_.size() && text_[i_] == ']'; ++n) advance();
      return;
    }
    key("a key");
    skip_blanks();
    if (i_ < text_.size() && text_[i_] == '=') {
      advance();
      value_start_ = true;
    }
  }

  static bool bare_key_char(char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' ||
           c == '-';
  }

  // Counts the parts of a dotted key (bare or quoted); stops at anything else.
  void key(const char* what) {
    const Position start = here();
    std::size_t parts = 0;
    for (;;) {
      skip_blanks();
      if (i_ >= text_.size()) break;
      const std::size_t before = i_;
      if (text_[i_] == '"' || text_[i_] == '\'')
        string();
      else
        while (i_ < text_.size() && bare_key_char(text_[i_])) advance();
      if (i_ == before) break;
      if (++parts > TomlLimits::kMaxKeyParts)
        fail(start, std::string(what) + " with more than " +
                        std::to_string(TomlLimits::kMaxKeyParts) + " dotted parts");
      skip_blanks();
      if (i_ >= text_.size() || text_[i_] != '.') break;
      advance();
    }
  }

  // A basic or literal string, single- or multi-line; measures its length. toml++ tests the
  // character after a backslash, and the characters after a line-ending backslash, for whitespace:
  // they must be ASCII. So must everything in a string that does not end (the parser reads on as a
  // bare value).
  void string() {
    const Position start = here();
    const char quote = text_[i_];
    const std::string triple(3, quote);
    const bool multi_line = at(triple);
    for (std::size_t n = 0; n < (multi_line ? 3u : 1u); ++n) advance();
    const std::size_t first = i_;
    std::optional<Position> non_ascii;
    while (i_ < text_.size()) {
      if (multi_line ? at(triple) : text_[i_] == quote) break;
      if (!multi_line && text_[i_] == '\n') break;  // unterminated: the parser says so
      if (quote == '"' && text_[i_] == '\\' && i_ + 1 < text_.size()) {
        advance();
        escaped_character(multi_line);
      }
      if (!non_ascii && static_cast<unsigned char>(text_[i_]) >= 0x80) non_ascii = here();
      advance();
      if (i_ - first > TomlLimits::kMaxStringBytes)
        fail(start,
             "a string longer than " + std::to_string(TomlLimits::kMaxStringBytes) + " bytes");
    }
    const bool ended = i_ < text_.size() && text_[i_] != '\n';
    if (!ended && non_ascii)
      fail(*non_ascii,
           "a non-ASCII character in a string that does not end (the parser would read "
           "on as a bare value, where TOML allows only ASCII)");
    if (ended)
      for (std::size_t n = 0; n < (multi_line ? 3u : 1u) && i_ < text_.size(); ++n) advance();
  }

  // At the character after a backslash in a basic string.
  void escaped_character(bool multi_line) {
    if (i_ >= text_.size()) return;
    if (static_cast<unsigned char>(text_[i_]) >= 0x80)
      fail(here(), "a backslash before a non-ASCII character; escapes are \\n, \\t, \\uXXXX, ...");
    if (!multi_line) return;
    std::size_t j =
        i_;  // a line-ending backslash: blanks, a newline, then all whitespace is skipped
    while (j < text_.size() && (text_[j] == ' ' || text_[j] == '\t' || text_[j] == '\r')) ++j;
    if (j >= text_.size() || text_[j] != '\n') return;
    while (j < text_.size() && std::string_view(" \t\r\n").find(text_[j]) != std::string_view::npos)
      ++j;
    if (j < text_.size() && static_cast<unsigned char>(text_[j]) >= 0x80) {
      while (i_ < j) advance();
      fail(here(),
           "a non-ASCII character first after a line-ending backslash in a multi-line string; "
           "toml++ cannot read it there: end the line without the backslash");
    }
  }

  std::string_view text_;
  const std::string& name_;
  bool positions_;
  std::size_t i_ = 0;
  int line_ = 1, column_ = 1;
  std::vector<char> open_;  // '[' and '{' not yet closed
  // A quote opens a string only where a value starts: after a key's '=', an array's '[' or a ','.
  // Inside a bare value toml++ reads quotes and all up to a space, ',', ']' ..., testing each
  // character for a space (hence non-ASCII characters there are errors).
  bool value_start_ = false;
};

}  // namespace

void check_toml_limits(std::string_view text, const std::string& name, bool positions) {
  LimitScanner(text, name, positions).scan();
}

}  // namespace network
