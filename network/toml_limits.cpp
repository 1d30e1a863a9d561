#include "network/toml_limits.hpp"

#include <vector>

namespace network {

namespace {

// A lexical pass that knows just enough TOML to tell keys, headers, strings, comments and brackets
// apart; everything else is skipped. It never rejects malformed text: it only measures.
class LimitScanner {
 public:
  LimitScanner(std::string_view text, const std::string& name, bool positions)
      : text_(text), name_(name), positions_(positions) {}

  void scan() {
    if (text_.size() > TomlLimits::kMaxBytes)
      fail({}, "the text is " + std::to_string(text_.size()) + " bytes; at most " +
                   std::to_string(TomlLimits::kMaxBytes) + " are read");
    bool key_next = true;  // at the start of a line outside brackets, or after '{' or ','
    while (i_ < text_.size()) {
      if (key_next) {
        key_or_header();
        key_next = false;
        continue;
      }
      const char c = text_[i_];
      if (c == '"' || c == '\'') {
        string();
      } else if (c == '#') {
        comment();
      } else if (c == '\n') {
        advance();
        key_next = open_.empty();
      } else if (c == '[' || c == '{') {
        const Position at = here();
        advance();
        open_.push_back(c);
        if (open_.size() > TomlLimits::kMaxNesting)
          fail(at, "arrays and inline tables nested more than " +
                       std::to_string(TomlLimits::kMaxNesting) + " deep");
        key_next = c == '{';
      } else if (c == ']' || c == '}') {
        advance();
        if (!open_.empty()) open_.pop_back();
      } else if (c == ',') {
        advance();
        key_next = !open_.empty() && open_.back() == '{';
      } else {
        advance();
      }
    }
  }

 private:
  struct Position {
    int line = 0, column = 0;
  };

  Position here() const { return {line_, column_}; }

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

  // A basic or literal string, single- or multi-line; measures its length.
  void string() {
    const Position start = here();
    const char quote = text_[i_];
    const std::string triple(3, quote);
    const bool multi_line = at(triple);
    for (std::size_t n = 0; n < (multi_line ? 3u : 1u); ++n) advance();
    const std::size_t first = i_;
    while (i_ < text_.size()) {
      if (multi_line ? at(triple) : text_[i_] == quote) break;
      if (!multi_line && text_[i_] == '\n') break;  // unterminated: the parser says so
      if (quote == '"' && text_[i_] == '\\' && i_ + 1 < text_.size()) advance();
      advance();
      if (i_ - first > TomlLimits::kMaxStringBytes)
        fail(start,
             "a string longer than " + std::to_string(TomlLimits::kMaxStringBytes) + " bytes");
    }
    if (i_ < text_.size() && text_[i_] != '\n')
      for (std::size_t n = 0; n < (multi_line ? 3u : 1u) && i_ < text_.size(); ++n) advance();
  }

  std::string_view text_;
  const std::string& name_;
  bool positions_;
  std::size_t i_ = 0;
  int line_ = 1, column_ = 1;
  std::vector<char> open_;  // '[' and '{' not yet closed
};

}  // namespace

void check_toml_limits(std::string_view text, const std::string& name, bool positions) {
  LimitScanner(text, name, positions).scan();
}

}  // namespace network
