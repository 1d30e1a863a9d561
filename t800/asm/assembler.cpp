#include "t800/asm/assembler.hpp"

#include <algorithm>
#include <array>
#include <cstdio>
#include <memory>
#include <set>
#include <utility>

namespace t800::assembly {

AssemblyError::AssemblyError(std::string source_name, int line, int column, std::string message)
    : std::runtime_error((source_name.empty() ? "" : source_name + ":") + std::to_string(line) +
                         ":" + std::to_string(column) + ": " + message),
      line_(line),
      column_(column),
      message_(std::move(message)) {}

namespace {

// The range a 32-bit operand or word may be written in: signed or unsigned, taken modulo 2^32.
constexpr std::int64_t kMin32 = -(std::int64_t(1) << 31);
constexpr std::int64_t kMax32 = (std::int64_t(1) << 32) - 1;
constexpr std::int64_t kAddressSpace = std::int64_t(1) << 32;
constexpr std::uint8_t kPfixZero = 0x20;  // pfix 0: leaves a zero operand register zero
constexpr std::int64_t kMaxAlign = 65536, kMaxSpace = 1 << 24;

// Errors inside the assembler carry line and column; assemble() adds the source name.
struct Failure {
  int line, column;
  std::string message;
};

[[noreturn]] void fail(int line, int column, std::string message) {
  throw Failure{line, column, std::move(message)};
}

std::string range_text() {
  return "the 32-bit range (" + std::to_string(kMin32) + " .. " + std::to_string(kMax32) + ")";
}

std::int32_t as_int32(std::int64_t value) {
  return static_cast<std::int32_t>(static_cast<std::uint32_t>(value));
}

std::string lower(std::string_view text) {
  std::string out(text);
  for (char& c : out) c = char(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

std::string hex(std::uint32_t value, int digits) {
  char buffer[16];
  std::snprintf(buffer, sizeof buffer, "#%0*X", digits, value);
  return buffer;
}

// ---------------------------------------------------------------------------------------------
// Suggestions: the known word nearest (in edit distance) to an unknown one.

std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      std::size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

template <typename Words>
std::string nearest(std::string_view word, const Words& known) {
  std::string best;
  std::size_t best_distance = SIZE_MAX;
  for (const auto& candidate : known) {
    std::size_t d = edit_distance(word, candidate);
    if (d < best_distance) best_distance = d, best = std::string(candidate);
  }
  return best;
}

const std::vector<std::string>& instruction_names() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> out{"opr"};
    for (int i = 0; i < isa::kOpCount; ++i)
      out.emplace_back(isa::mnemonic(static_cast<isa::Op>(i)));
    return out;
  }();
  return names;
}

const std::vector<std::string> kDirectives{".byte", ".word", ".ascii", ".align", ".space", ".equ"};

// ---------------------------------------------------------------------------------------------
// Lexing: one line into tokens, stopping at a comment (`--`, occam's, or `;`).

enum class Tok {
  name,       // label, constant or mnemonic
  directive,  // .byte
  number,     // 42, #2A, 0x2A, '*'
  string,     // "text", escapes resolved
  dot,        // . (the current address)
  plus,
  minus,
  star,
  lparen,
  rparen,
  comma,
  colon,
  equals,
  end,  // end of line or start of a comment
};

struct Token {
  Tok kind = Tok::end;
  std::string text;  // as written (for messages); a string's resolved bytes
  std::int64_t value = 0;
  int column = 0;
};

std::string describe(const Token& t) {
  if (t.kind == Tok::end) return "the end of the line";
  if (t.kind == Tok::string) return "a string";
  return "'" + t.text + "'";
}

bool is_name_start(char c) {
  return std::isalpha(static_cast<unsigned char>(c)) || c == '_';
}
bool is_name_char(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '.';
}

class Lexer {
 public:
  Lexer(std::string_view text, int line) : s_(text), line_(line) {}

  std::vector<Token> tokens() {
    std::vector<Token> out;
    for (;;) {
      while (i_ < s_.size() && (s_[i_] == ' ' || s_[i_] == '\t' || s_[i_] == '\r')) ++i_;
      if (i_ >= s_.size() || s_[i_] == ';' || s_.substr(i_, 2) == "--") {
        out.push_back(Token{Tok::end, "", 0, column()});
        return out;
      }
      out.push_back(next());
    }
  }

 private:
  int column() const { return int(i_) + 1; }
  char at(std::size_t k) const { return k < s_.size() ? s_[k] : '\0'; }

  Token next() {
    const std::size_t start = i_;
    const char c = s_[i_];
    if (is_name_start(c)) return word(Tok::name, start);
    if (c == '.' && std::isalpha(static_cast<unsigned char>(at(i_ + 1)))) {
      ++i_;
      return word(Tok::directive, start);
    }
    if (std::isdigit(static_cast<unsigned char>(c))) return number(start);
    if (c == '#') return hex_number(start, 1);
    if (c == '\'') return character(start);
    if (c == '"') return string(start);
    static const std::string_view kSingles = ".+-*(),:=";
    static const Tok kKinds[] = {Tok::dot,    Tok::plus,  Tok::minus, Tok::star,  Tok::lparen,
                                 Tok::rparen, Tok::comma, Tok::colon, Tok::equals};
    if (std::size_t k = kSingles.find(c); k != std::string_view::npos) {
      ++i_;
      return Token{kKinds[k], std::string(1, c), 0, int(start) + 1};
    }
    fail(line_, column(), std::string("unexpected character '") + c + "'");
  }

  Token word(Tok kind, std::size_t start) {
    while (i_ < s_.size() &&
           (kind == Tok::name ? is_name_char(s_[i_]) : is_name_char(s_[i_]) && s_[i_] != '.'))
      ++i_;
    return Token{kind, std::string(s_.substr(start, i_ - start)), 0, int(start) + 1};
  }

  // Digits in `base`, accumulated with a bound well inside 64 bits (the 32-bit checks come later).
  std::int64_t digits(std::size_t start, int base) {
    std::int64_t value = 0;
    const std::size_t first = i_;
    for (; i_ < s_.size() && std::isxdigit(static_cast<unsigned char>(s_[i_])); ++i_) {
      int d = std::isdigit(static_cast<unsigned char>(s_[i_]))
                  ? s_[i_] - '0'
                  : std::tolower(static_cast<unsigned char>(s_[i_])) - 'a' + 10;
      if (d >= base) break;
      if (value > (INT64_MAX - d) / base)
        fail(line_, int(start) + 1, "number too large: '" + rest_of_number(start) + "'");
      value = value * base + d;
    }
    if (i_ == first) return -1;
    return value;
  }

  std::string rest_of_number(std::size_t start) {
    std::size_t end = start;
    while (end < s_.size() && (is_name_char(s_[end]) || s_[end] == '#')) ++end;
    return std::string(s_.substr(start, end - start));
  }

  Token finish_number(std::size_t start, std::int64_t value) {
    if (value < 0 || (i_ < s_.size() && is_name_char(s_[i_])))
      fail(line_, int(start) + 1,
           "malformed number '" + rest_of_number(start) +
               "'; write decimal (42), hex as #2A or 0x2A, or a character as '*'");
    return Token{Tok::number, std::string(s_.substr(start, i_ - start)), value, int(start) + 1};
  }

  Token number(std::size_t start) {
    if (s_[i_] == '0' && (at(i_ + 1) == 'x' || at(i_ + 1) == 'X')) return hex_number(start, 2);
    return finish_number(start, digits(start, 10));
  }

  Token hex_number(std::size_t start, std::size_t prefix) {
    i_ += prefix;
    std::int64_t value = digits(start, 16);
    if (value < 0)
      fail(line_, int(start) + 1,
           "'" + std::string(s_.substr(start, prefix)) + "' must be followed by hex digits (#7F)");
    return finish_number(start, value);
  }

  // One possibly escaped character inside quotes.
  std::uint8_t quoted_char(char quote, std::size_t start) {
    if (i_ >= s_.size())
      fail(line_, int(start) + 1,
           std::string(quote == '"' ? "the string" : "the character") + " has no closing " + quote);
    char c = s_[i_++];
    if (c != '\\') return std::uint8_t(c);
    const char e = at(i_++);
    switch (e) {
      case 'n':
        return '\n';
      case 't':
        return '\t';
      case 'r':
        return '\r';
      case '0':
        return '\0';
      case '\\':
        return '\\';
      case '\'':
        return '\'';
      case '"':
        return '"';
    }
    fail(line_, int(i_) - 1,
         std::string("unknown escape '\\") + e + "'; valid are \\n \\t \\r \\0 \\\\ \\' \\\"");
  }

  Token character(std::size_t start) {
    ++i_;
    if (at(i_) == '\'') fail(line_, int(start) + 1, "empty character literal ''");
    std::uint8_t c = quoted_char('\'', start);
    if (at(i_) != '\'')
      fail(line_, int(start) + 1, "a character literal holds one character and ends with '");
    ++i_;
    return Token{Tok::number, std::string(s_.substr(start, i_ - start)), c, int(start) + 1};
  }

  Token string(std::size_t start) {
    ++i_;
    std::string bytes;
    while (i_ >= s_.size() || s_[i_] != '"') bytes.push_back(char(quoted_char('"', start)));
    ++i_;
    return Token{Tok::string, bytes, 0, int(start) + 1};
  }

  std::string_view s_;
  int line_;
  std::size_t i_ = 0;
};

// ---------------------------------------------------------------------------------------------
// Expressions.

struct Expr {
  enum Kind { number, symbol, dot, negate, add, subtract, multiply } kind = number;
  std::int64_t value = 0;
  std::string name;
  int column = 0;  // of the token (an operator's for + - *)
  int start = 0;   // of the expression's first token, for messages about the whole value
  std::unique_ptr<Expr> left, right;
};
using ExprPtr = std::unique_ptr<Expr>;

// Recursive descent over one line's tokens: expr = term {(+|-) term}, term = unary {* unary},
// unary = [-|+] unary | primary.
class Parser {
 public:
  Parser(const std::vector<Token>& tokens, int line) : t_(tokens), line_(line) {}

  const Token& peek(std::size_t ahead = 0) const { return t_[std::min(i_ + ahead, t_.size() - 1)]; }
  Token take() { return t_[std::min(i_++, t_.size() - 1)]; }
  bool accept(Tok kind) {
    if (peek().kind != kind) return false;
    ++i_;
    return true;
  }
  int line() const { return line_; }

  ExprPtr expression() {
    ExprPtr e = term();
    while (peek().kind == Tok::plus || peek().kind == Tok::minus) {
      Token op = take();
      e = binary(op.kind == Tok::plus ? Expr::add : Expr::subtract, std::move(e), term(), op);
    }
    return e;
  }

 private:
  ExprPtr term() {
    ExprPtr e = unary();
    while (peek().kind == Tok::star) {
      Token op = take();
      e = binary(Expr::multiply, std::move(e), unary(), op);
    }
    return e;
  }

  ExprPtr unary() {
    if (peek().kind == Tok::plus) {
      int start = take().column;
      ExprPtr e = unary();
      e->start = start;
      return e;
    }
    if (peek().kind == Tok::minus) {
      auto e = std::make_unique<Expr>();
      e->kind = Expr::negate;
      e->column = e->start = take().column;
      e->left = unary();
      return e;
    }
    return primary();
  }

  ExprPtr primary() {
    const Token t = take();
    auto e = std::make_unique<Expr>();
    e->column = e->start = t.column;
    switch (t.kind) {
      case Tok::number:
        e->value = t.value;
        return e;
      case Tok::name:
        e->kind = Expr::symbol;
        e->name = t.text;
        return e;
      case Tok::dot:
        e->kind = Expr::dot;
        return e;
      case Tok::lparen: {
        ExprPtr inner = expression();
        if (!accept(Tok::rparen))
          fail(line_, peek().column,
               "expected ')' to close the '(' at column " + std::to_string(t.column) + ", found " +
                   describe(peek()));
        inner->start = t.column;
        return inner;
      }
      default:
        fail(line_, t.column,
             "expected a value (a number, a name, '.' or '('), found " + describe(t));
    }
  }

  static ExprPtr binary(Expr::Kind kind, ExprPtr left, ExprPtr right, const Token& op) {
    auto e = std::make_unique<Expr>();
    e->kind = kind;
    e->column = op.column;
    e->start = left->start;
    e->left = std::move(left);
    e->right = std::move(right);
    return e;
  }

  const std::vector<Token>& t_;
  int line_;
  std::size_t i_ = 0;
};

// ---------------------------------------------------------------------------------------------
// Statements: every source line is one (possibly empty) statement.

enum class Kind { none, instruction, opr, constant, byte, word, ascii, align, space };

struct Label {
  std::string name;
  int column;
};

struct Statement {
  int line = 0;
  int column = 0;  // of the mnemonic or directive
  std::string source;
  std::vector<Label> labels;
  Kind kind = Kind::none;
  isa::Op op = isa::Op::j;         // Kind::instruction
  std::string name;                // Kind::constant
  std::vector<ExprPtr> args;       // operand, values, count and fill
  std::vector<std::uint8_t> text;  // Kind::ascii
  // Known before layout (Kind::align, Kind::space):
  std::int64_t count = 0;
  std::uint8_t fill = 0;

  bool variable_length() const {
    return kind == Kind::opr ||
           (kind == Kind::instruction && isa::info(op).encoding == isa::Encoding::direct);
  }
  bool relative() const {
    return kind == Kind::instruction &&
           (op == isa::Op::j || op == isa::Op::cj || op == isa::Op::call);
  }
};

void expect_end(Parser& p, const char* after) {
  if (p.peek().kind != Tok::end)
    fail(
        p.line(), p.peek().column,
        "unexpected " + describe(p.peek()) + " after " + after + "; a comment starts with -- or ;");
}

std::vector<ExprPtr> expression_list(Parser& p) {
  std::vector<ExprPtr> out;
  do out.push_back(p.expression());
  while (p.accept(Tok::comma));
  return out;
}

void parse_instruction(Parser& p, const Token& word, Statement& s) {
  const std::string name = lower(word.text);
  s.column = word.column;
  if (name == "opr") {
    s.kind = Kind::opr;
  } else if (std::optional<isa::Op> op = isa::parse_op(name)) {
    s.kind = Kind::instruction;
    s.op = *op;
  } else if (p.peek().kind == Tok::name && isa::parse_op(lower(p.peek().text))) {
    fail(p.line(), word.column,
         "'" + word.text + "' is not an instruction; to label the line write '" + word.text + ":'");
  } else {
    fail(p.line(), word.column,
         "unknown instruction '" + word.text + "'; the nearest is '" +
             nearest(name, instruction_names()) + "'");
  }
  const bool direct = s.kind == Kind::opr || isa::info(s.op).encoding == isa::Encoding::direct;
  if (!direct) {
    if (p.peek().kind != Tok::end)
      fail(p.line(), p.peek().column,
           "'" + name + "' is an operation and takes no operand; found " + describe(p.peek()));
    return;
  }
  if (p.peek().kind == Tok::end)
    fail(p.line(), word.column,
         "'" + name + "' needs an operand (a number, a label or an expression)");
  s.args.push_back(p.expression());
  expect_end(p, "the operand");
}

void parse_directive(Parser& p, const Token& word, Statement& s) {
  const std::string name = lower(word.text);
  s.column = word.column;
  if (name == ".byte" || name == ".word") {
    s.kind = name == ".byte" ? Kind::byte : Kind::word;
    s.args = expression_list(p);
    expect_end(p, "the values");
  } else if (name == ".ascii") {
    if (p.peek().kind != Tok::string)
      fail(p.line(), p.peek().column,
           "'.ascii' needs a string in double quotes, found " + describe(p.peek()));
    const Token text = p.take();
    s.kind = Kind::ascii;
    s.text.assign(text.text.begin(), text.text.end());
    expect_end(p, "the string");
  } else if (name == ".align" || name == ".space") {
    s.kind = name == ".align" ? Kind::align : Kind::space;
    s.args = expression_list(p);
    if (s.args.size() > 2)
      fail(p.line(), s.args[2]->start, "'" + name + "' takes a count and at most a fill byte");
    expect_end(p, "the count");
  } else if (name == ".equ") {
    if (p.peek().kind != Tok::name || p.peek(1).kind != Tok::comma)
      fail(p.line(), p.peek().column, "'.equ' needs a name, then ',' and a value");
    s.kind = Kind::constant;
    s.name = p.take().text;
    p.take();
    s.args.push_back(p.expression());
    expect_end(p, "the value");
  } else {
    fail(p.line(), word.column,
         "unknown directive '" + word.text + "'; the nearest is '" + nearest(name, kDirectives) +
             "'");
  }
}

Statement parse_line(std::string_view text, int line) {
  Statement s;
  s.line = line;
  s.source = std::string(text);
  const std::vector<Token> tokens = Lexer(text, line).tokens();
  Parser p(tokens, line);
  while (p.peek().kind == Tok::name && p.peek(1).kind == Tok::colon) {
    const Token name = p.take();
    p.take();
    s.labels.push_back(Label{name.text, name.column});
  }
  const Token first = p.peek();
  if (first.kind == Tok::end) return s;
  p.take();
  if (first.kind == Tok::name && p.peek().kind == Tok::equals) {
    p.take();
    s.kind = Kind::constant;
    s.column = first.column;
    s.name = first.text;
    s.args.push_back(p.expression());
    expect_end(p, "the value");
  } else if (first.kind == Tok::name) {
    parse_instruction(p, first, s);
  } else if (first.kind == Tok::directive) {
    parse_directive(p, first, s);
  } else {
    fail(line, first.column,
         "expected an instruction, a directive, 'label:' or 'name = value', found " +
             describe(first));
  }
  return s;
}

std::vector<Statement> parse(std::string_view source) {
  std::vector<Statement> out;
  std::size_t begin = 0;
  for (int line = 1; begin <= source.size(); ++line) {
    std::size_t end = source.find('\n', begin);
    if (end == std::string_view::npos) end = source.size();
    if (end == source.size() && begin == end && line > 1) break;  // the final newline
    out.push_back(parse_line(source.substr(begin, end - begin), line));
    begin = end + 1;
  }
  return out;
}

// ---------------------------------------------------------------------------------------------
// Names: labels (the address of their statement) and constants (a value defined by expression).

struct Definition {
  std::size_t statement;
  bool label;
  int line, column;
};
using Names = std::map<std::string, Definition>;

Names collect_names(const std::vector<Statement>& statements) {
  Names names;
  auto define = [&](const std::string& name, std::size_t index, bool label, int column) {
    const int line = statements[index].line;
    auto [it, fresh] = names.emplace(name, Definition{index, label, line, column});
    if (!fresh)
      fail(line, column,
           "'" + name + "' is already defined at line " + std::to_string(it->second.line) +
               "; a label or constant can be defined once");
  };
  for (std::size_t i = 0; i < statements.size(); ++i) {
    for (const Label& l : statements[i].labels) define(l.name, i, true, l.column);
    if (statements[i].kind == Kind::constant)
      define(statements[i].name, i, false, statements[i].column);
  }
  return names;
}

// ---------------------------------------------------------------------------------------------
// Evaluation. A value is an address or a number, and knows whether it depends on the layout.

struct Value {
  std::int64_t v = 0;
  bool address = false;
  bool layout = false;  // derived from a label or `.`
};

// Where every statement lies in one pass: absolute addresses (origin included) and lengths.
struct Layout {
  std::vector<std::int64_t> address;
  std::vector<std::int64_t> length;
};

class Evaluator {
 public:
  // Without a layout, labels and `.` evaluate to 0 marked `layout` (used for counts that must
  // be known before layout).
  Evaluator(const std::vector<Statement>& statements, const Names& names, const Layout* layout)
      : statements_(statements), names_(names), layout_(layout) {}

  Value eval(const Expr& e, std::size_t statement) {
    const int line = statements_[statement].line;
    switch (e.kind) {
      case Expr::number:
        return Value{e.value, false, false};
      case Expr::dot:
        return Value{layout_ ? layout_->address[statement] : 0, true, true};
      case Expr::symbol:
        return symbol(e, line);
      case Expr::negate: {
        Value a = eval(*e.left, statement);
        if (a.address) fail(line, e.column, "cannot negate an address");
        return Value{checked(line, e, 0, a.v, Expr::subtract), false, a.layout};
      }
      default:
        return binary(e, eval(*e.left, statement), eval(*e.right, statement), line);
    }
  }

 private:
  Value binary(const Expr& e, Value a, Value b, int line) {
    bool address = false;
    if (e.kind == Expr::add) {
      if (a.address && b.address)
        fail(line, e.column,
             "cannot add two addresses; address - address gives a number, address + number an "
             "address");
      address = a.address || b.address;
    } else if (e.kind == Expr::subtract) {
      if (!a.address && b.address)
        fail(line, e.column,
             "cannot subtract an address from a number; only address - address or address - "
             "number");
      address = a.address && !b.address;
    } else if (a.address || b.address) {
      fail(line, e.column, "'*' needs two numbers, not addresses (a difference of labels is one)");
    }
    return Value{checked(line, e, a.v, b.v, e.kind), address, a.layout || b.layout};
  }

  static std::int64_t checked(int line, const Expr& e, std::int64_t a, std::int64_t b,
                              Expr::Kind kind) {
    std::int64_t r = 0;
    bool overflow = kind == Expr::add        ? __builtin_add_overflow(a, b, &r)
                    : kind == Expr::subtract ? __builtin_sub_overflow(a, b, &r)
                                             : __builtin_mul_overflow(a, b, &r);
    if (overflow)
      fail(line, e.column, "the value overflows 64 bits; " + range_text() + " is valid");
    return r;
  }

  Value symbol(const Expr& e, int line) {
    auto it = names_.find(e.name);
    if (it == names_.end()) {
      std::vector<std::string> known;
      for (const auto& [name, def] : names_) known.push_back(name);
      fail(line, e.column,
           "undefined name '" + e.name + "'" +
               (known.empty() ? std::string("; no labels or constants are defined")
                              : "; the nearest defined is '" + nearest(e.name, known) + "'"));
    }
    const Definition& d = it->second;
    if (d.label) return Value{layout_ ? layout_->address[d.statement] : 0, true, true};
    if (auto c = cache_.find(e.name); c != cache_.end()) return c->second;
    if (!evaluating_.insert(e.name).second)
      fail(line, e.column, "constant '" + e.name + "' is defined in terms of itself");
    Value v = eval(*statements_[d.statement].args[0], d.statement);
    evaluating_.erase(e.name);
    return cache_[e.name] = v;
  }

  const std::vector<Statement>& statements_;
  const Names& names_;
  const Layout* layout_;
  std::map<std::string, Value> cache_;
  std::set<std::string> evaluating_;
};

// The counts and fills of .align and .space, which must not depend on the layout: a count that
// shrank as code grew could keep the sizing passes from settling.
void fix_counts(std::vector<Statement>& statements, const Names& names) {
  Evaluator before_layout(statements, names, nullptr);
  for (std::size_t i = 0; i < statements.size(); ++i) {
    Statement& s = statements[i];
    if (s.kind != Kind::align && s.kind != Kind::space) continue;
    const std::string name = s.kind == Kind::align ? "'.align'" : "'.space'";
    auto known = [&](const Expr& e, const char* what) {
      Value v = before_layout.eval(e, i);
      if (v.layout)
        fail(s.line, e.start,
             name + " " + what +
                 " must be known before layout: numbers and constants, not labels "
                 "or '.'");
      return v.v;
    };
    s.count = known(*s.args[0], "count");
    if (s.kind == Kind::align && (s.count < 1 || s.count > kMaxAlign || (s.count & (s.count - 1))))
      fail(s.line, s.args[0]->start,
           "'.align' needs a power of two from 1 to " + std::to_string(kMaxAlign) + ", not " +
               std::to_string(s.count));
    if (s.kind == Kind::space && (s.count < 0 || s.count > kMaxSpace))
      fail(s.line, s.args[0]->start,
           "'.space' needs a count from 0 to " + std::to_string(kMaxSpace) + ", not " +
               std::to_string(s.count));
    s.fill = s.kind == Kind::align ? kPfixZero : 0;
    if (s.args.size() == 2) {
      std::int64_t fill = known(*s.args[1], "fill");
      if (fill < -128 || fill > 255)
        fail(s.line, s.args[1]->start,
             name + " fill " + std::to_string(fill) + " does not fit a byte (-128 .. 255)");
      s.fill = std::uint8_t(fill);
    }
  }
}

// ---------------------------------------------------------------------------------------------
// Layout and prefix sizing.

// A statement's fixed length (0 for those without bytes); variable-length ones are in `lengths`.
std::int64_t fixed_length(const Statement& s) {
  switch (s.kind) {
    case Kind::instruction:
      return isa::encoded_bytes(s.op);
    case Kind::byte:
      return std::int64_t(s.args.size());
    case Kind::word:
      return 4 * std::int64_t(s.args.size());
    case Kind::ascii:
      return std::int64_t(s.text.size());
    case Kind::space:
      return s.count;
    default:
      return 0;
  }
}

Layout lay_out(const std::vector<Statement>& statements, const std::vector<std::int64_t>& lengths,
               std::uint32_t origin) {
  Layout layout;
  std::int64_t address = origin;
  for (std::size_t i = 0; i < statements.size(); ++i) {
    const Statement& s = statements[i];
    std::int64_t length = s.variable_length() ? lengths[i] : fixed_length(s);
    if (s.kind == Kind::align) length = (s.count - address % s.count) % s.count;
    layout.address.push_back(address);
    layout.length.push_back(length);
    address += length;
  }
  return layout;
}

// The operand an instruction encodes: jumps to an address are relative to the next instruction
// (CWG: the operand is added to Iptr, which already points past the instruction).
std::int64_t operand_of(const Statement& s, const Value& v, std::int64_t address,
                        std::int64_t length) {
  return s.relative() && v.address ? v.v - (address + length) : v.v;
}

// Passes until no instruction needs to grow; returns the lengths and the number of passes.
std::pair<std::vector<std::int64_t>, int> size_instructions(
    const std::vector<Statement>& statements, const Names& names, std::uint32_t origin) {
  std::vector<std::int64_t> lengths(statements.size(), 1);
  // Each pass that changes anything lengthens an instruction by at least a byte, and none grows
  // past the longest 32-bit chain (8 bytes): a bound the passes cannot exceed.
  const std::size_t bound = 8 * statements.size() + 2;
  for (std::size_t pass = 1; pass <= bound; ++pass) {
    const Layout layout = lay_out(statements, lengths, origin);
    Evaluator evaluator(statements, names, &layout);
    bool grew = false;
    for (std::size_t i = 0; i < statements.size(); ++i) {
      const Statement& s = statements[i];
      if (!s.variable_length()) continue;
      const std::int64_t operand =
          operand_of(s, evaluator.eval(*s.args[0], i), layout.address[i], layout.length[i]);
      // An operand out of range is reported when the bytes are made; it does not grow anything.
      if (operand < kMin32 || operand > kMax32) continue;
      const std::int64_t needed = 1 + isa::prefix_bytes(as_int32(operand));
      if (needed > lengths[i]) lengths[i] = needed, grew = true;
    }
    if (!grew) return {lengths, int(pass)};
  }
  throw std::logic_error("assembler: prefix sizing did not settle");
}

// ---------------------------------------------------------------------------------------------
// Bytes.

// `opr code`: the same pfix/nfix chain as any direct function, then function F (CWG, "opr").
std::vector<std::uint8_t> encode_opr(std::int32_t code) {
  std::vector<std::uint8_t> out = isa::encode(isa::Op::ldc, code);
  out.back() = std::uint8_t(0xF0 | (out.back() & 0x0F));
  return out;
}

std::int64_t in_range(std::int64_t value, std::int64_t low, std::int64_t high, int line, int column,
                      const std::string& what) {
  if (value < low || value > high)
    fail(line, column,
         what + " " + std::to_string(value) + " is outside " +
             (high == 255 ? "a byte (-128 .. 255)" : range_text()));
  return value;
}

std::vector<std::uint8_t> instruction_bytes(const Statement& s, Evaluator& evaluator,
                                            std::size_t index, const Layout& layout) {
  const Expr& e = *s.args[0];
  const Value v = evaluator.eval(e, index);
  const std::int64_t operand = operand_of(s, v, layout.address[index], layout.length[index]);
  const bool distance = s.relative() && v.address;
  const std::int32_t value = as_int32(
      in_range(operand, kMin32, kMax32, s.line, e.start, distance ? "jump distance" : "operand"));
  std::vector<std::uint8_t> code =
      s.kind == Kind::opr ? encode_opr(value) : isa::encode(s.op, value);
  if (std::int64_t(code.size()) > layout.length[index])
    throw std::logic_error("assembler: an instruction outgrew its sized length");
  // Filled out to the sized length with pfix 0, which keeps the operand's value (see header).
  code.insert(code.begin(), std::size_t(layout.length[index]) - code.size(), kPfixZero);
  return code;
}

std::vector<std::uint8_t> statement_bytes(const Statement& s, Evaluator& evaluator,
                                          std::size_t index, const Layout& layout) {
  std::vector<std::uint8_t> out;
  switch (s.kind) {
    case Kind::instruction:
      if (!s.variable_length()) return isa::encode(s.op);
      return instruction_bytes(s, evaluator, index, layout);
    case Kind::opr:
      return instruction_bytes(s, evaluator, index, layout);
    case Kind::byte:
      for (const ExprPtr& e : s.args)
        out.push_back(std::uint8_t(
            in_range(evaluator.eval(*e, index).v, -128, 255, s.line, e->start, "'.byte' value")));
      return out;
    case Kind::word:
      for (const ExprPtr& e : s.args) {
        auto w = std::uint32_t(in_range(evaluator.eval(*e, index).v, kMin32, kMax32, s.line,
                                        e->start, "'.word' value"));
        for (int b = 0; b < 4; ++b) out.push_back(std::uint8_t(w >> (8 * b)));  // little-endian
      }
      return out;
    case Kind::ascii:
      return s.text;
    case Kind::align:
    case Kind::space:
      return std::vector<std::uint8_t>(std::size_t(layout.length[index]), s.fill);
    case Kind::constant:
      evaluator.eval(*s.args[0], index);  // reports what is wrong with it even if it is unused
      return out;
    case Kind::none:
      return out;
  }
  return out;
}

Program emit(const std::vector<Statement>& statements, const Names& names, const Layout& layout,
             std::uint32_t origin) {
  Program program;
  program.origin = origin;
  Evaluator evaluator(statements, names, &layout);
  for (std::size_t i = 0; i < statements.size(); ++i) {
    const Statement& s = statements[i];
    if (layout.address[i] + layout.length[i] > kAddressSpace)
      fail(s.line, std::max(s.column, 1),
           "the program passes the top of the 32-bit address space (#FFFFFFFF); lower the origin");
    std::vector<std::uint8_t> bytes = statement_bytes(s, evaluator, i, layout);
    program.bytes.insert(program.bytes.end(), bytes.begin(), bytes.end());
    program.listing.push_back(
        ListingLine{s.line, std::uint32_t(layout.address[i]), std::move(bytes), s.source});
  }
  for (const auto& [name, d] : names) {
    if (d.label)
      program.labels[name] = std::uint32_t(layout.address[d.statement]);
    else
      program.constants[name] = evaluator.eval(*statements[d.statement].args[0], d.statement).v;
  }
  return program;
}

}  // namespace

Program assemble(std::string_view source, const Options& options) {
  try {
    std::vector<Statement> statements = parse(source);
    const Names names = collect_names(statements);
    fix_counts(statements, names);
    auto [lengths, passes] = size_instructions(statements, names, options.origin);
    Program program =
        emit(statements, names, lay_out(statements, lengths, options.origin), options.origin);
    program.sizing_passes = passes;
    return program;
  } catch (const Failure& f) {
    throw AssemblyError(options.source_name, f.line, f.column, f.message);
  }
}

std::string Program::listing_text() const {
  constexpr std::size_t kPerRow = 8;
  std::string out;
  for (const ListingLine& l : listing) {
    std::size_t done = 0;
    do {
      std::string row = hex(l.address + std::uint32_t(done), 8).substr(1) + "  ";
      std::string bytes;
      for (std::size_t k = done; k < std::min(done + kPerRow, l.bytes.size()); ++k)
        bytes += hex(l.bytes[k], 2).substr(1) + " ";
      bytes.resize(3 * kPerRow, ' ');
      row += bytes;
      if (done == 0) row += " " + l.source;
      while (!row.empty() && row.back() == ' ') row.pop_back();
      out += row + "\n";
      done += kPerRow;
    } while (done < l.bytes.size());
  }
  return out;
}

// ---------------------------------------------------------------------------------------------
// Disassembly.

namespace {

struct Decoded {
  int function = -1;  // the high nibble of the byte that ends the chain; -1 if cut off
  std::uint32_t operand = 0;
  std::size_t length = 0;
};

// The operand register as the hardware builds it (CWG, "prefixing"): pfix n sets O to
// (O | n) << 4, nfix n to (~(O | n)) << 4, and the next function sees O | n.
Decoded decode(const std::uint8_t* bytes, std::size_t size, std::size_t offset) {
  constexpr int kPfix = 0x2, kNfix = 0x6;
  std::uint32_t o = 0;
  for (std::size_t i = offset; i < size; ++i) {
    const int function = bytes[i] >> 4;
    const std::uint32_t n = bytes[i] & 0xFu;
    if (function == kPfix)
      o = (o | n) << 4;
    else if (function == kNfix)
      o = ~(o | n) << 4;
    else
      return Decoded{function, o | n, i - offset + 1};
  }
  return Decoded{-1, o, size - offset};
}

std::optional<isa::Op> find_op(isa::Encoding encoding, std::int64_t code) {
  for (int i = 0; i < isa::kOpCount; ++i) {
    const isa::OpInfo& info = isa::info(static_cast<isa::Op>(i));
    if (info.encoding == encoding && info.code == code) return info.op;
  }
  return std::nullopt;
}

std::string operand_text(std::int32_t v) {
  if (v >= -65536 && v <= 65535) return std::to_string(v);
  return hex(std::uint32_t(v), 8);
}

Instruction from_decoded(const Decoded& d, std::size_t offset, std::uint32_t base) {
  constexpr int kOpr = 0xF;
  Instruction in;
  in.length = int(d.length);
  in.operand = std::int32_t(d.operand);
  if (d.function == kOpr) {
    in.op = find_op(isa::Encoding::operate, in.operand);
    in.mnemonic = in.op ? std::string(isa::mnemonic(*in.op)) : "opr";
    in.has_operand = !in.op;
    in.text = in.op ? in.mnemonic : "opr " + hex(std::uint32_t(in.operand), 2);
    return in;
  }
  in.op = find_op(isa::Encoding::direct, d.function);
  in.mnemonic = std::string(isa::mnemonic(*in.op));
  in.has_operand = true;
  in.text = in.mnemonic + " " + operand_text(in.operand);
  if (*in.op == isa::Op::j || *in.op == isa::Op::cj || *in.op == isa::Op::call) {
    in.target = std::uint32_t(base + offset + d.length + std::uint32_t(in.operand));
    in.text += " (to " + hex(*in.target, 8) + ")";
  }
  return in;
}

}  // namespace

Instruction disassemble(const std::uint8_t* bytes, std::size_t size, std::size_t offset,
                        std::uint32_t base_address) {
  if (offset >= size)
    throw std::out_of_range("disassemble: offset " + std::to_string(offset) +
                            " is past the end of " + std::to_string(size) + " bytes");
  const Decoded d = decode(bytes, size, offset);
  if (d.function < 0) {
    Instruction in;
    in.length = int(d.length);
    in.complete = false;
    in.text = "(pfix/nfix chain runs past the end of the code)";
    return in;
  }
  Instruction in = from_decoded(d, offset, base_address);
  // An fpu-entry operation is `ldc code; fpentry` (opcode.hpp): fold the pair when it is one.
  if (in.op == isa::Op::ldc && offset + d.length < size) {
    const Decoded next = decode(bytes, size, offset + d.length);
    std::optional<isa::Op> fpu = find_op(isa::Encoding::fpu_entry, in.operand);
    if (fpu && next.function == 0xF &&
        next.operand == std::uint32_t(isa::info(isa::Op::fpentry).code)) {
      in.op = fpu;
      in.mnemonic = in.text = std::string(isa::mnemonic(*fpu));
      in.has_operand = false;
      in.operand = 0;
      in.length = int(d.length + next.length);
    }
  }
  return in;
}

Instruction disassemble(const std::vector<std::uint8_t>& bytes, std::size_t offset,
                        std::uint32_t base_address) {
  return disassemble(bytes.data(), bytes.size(), offset, base_address);
}

}  // namespace t800::assembly
