#include "workloads/run/result_value.hpp"

#include <cmath>
#include <iterator>
#include <stdexcept>

#include <fmt/format.h>

namespace workloads {

ResultValue& ResultValue::set(const std::string& key, ResultValue value) {
  if (!is_record()) v_ = Record{};
  auto& r = std::get<Record>(v_);
  for (auto& [k, v] : r)
    if (k == key) return v = std::move(value);
  r.emplace_back(key, std::move(value));
  return r.back().second;
}

void ResultValue::push(ResultValue value) {
  if (!is_list()) v_ = List{};
  std::get<List>(v_).push_back(std::move(value));
}

const ResultValue* ResultValue::get(const std::string& key) const {
  if (!is_record()) return nullptr;
  for (const auto& [k, v] : record())
    if (k == key) return &v;
  return nullptr;
}

double ResultValue::number() const {
  if (auto d = std::get_if<double>(&v_)) return *d;
  if (auto i = std::get_if<std::int64_t>(&v_)) return double(*i);
  throw std::logic_error("result value is not a number");
}

std::string ResultValue::first_non_finite(const std::string& path) const {
  if (const auto* x = std::get_if<double>(&v_)) return std::isfinite(*x) ? "" : path;
  if (const auto* l = std::get_if<List>(&v_))
    for (std::size_t i = 0; i < l->size(); ++i)
      if (std::string at = (*l)[i].first_non_finite(path + "[" + std::to_string(i) + "]");
          !at.empty())
        return at;
  if (const auto* r = std::get_if<Record>(&v_))
    for (const auto& [key, value] : *r)
      if (std::string at = value.first_non_finite(path.empty() ? key : path + "." + key);
          !at.empty())
        return at;
  return "";
}

namespace {

// The length of the well-formed UTF-8 sequence at s[i] (RFC 3629: no overlong forms, no
// surrogates, nothing past U+10FFFF), or 0 when the byte there starts none.
std::size_t utf8_sequence(const std::string& s, std::size_t i) {
  const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(s[k]); };
  const unsigned char lead = byte(i);
  if (lead < 0x80) return 1;
  std::size_t n = 0;
  unsigned char low = 0x80, high = 0xBF;  // the second byte's range
  if (lead >= 0xC2 && lead <= 0xDF) {
    n = 2;
  } else if (lead >= 0xE0 && lead <= 0xEF) {
    n = 3;
    if (lead == 0xE0) low = 0xA0;
    if (lead == 0xED) high = 0x9F;
  } else if (lead >= 0xF0 && lead <= 0xF4) {
    n = 4;
    if (lead == 0xF0) low = 0x90;
    if (lead == 0xF4) high = 0x8F;
  } else {
    return 0;
  }
  if (i + n > s.size() || byte(i + 1) < low || byte(i + 1) > high) return 0;
  for (std::size_t k = 2; k < n; ++k)
    if (byte(i + k) < 0x80 || byte(i + k) > 0xBF) return 0;
  return n;
}

}  // namespace

// Everything is appended to one string: a string made and copied per value and per level of nesting
// was most of the cost of a large farm's report.
void append_json_string(std::string& out, const std::string& s) {
  out += '"';
  for (std::size_t i = 0; i < s.size();) {
    const char c = s[i];
    const std::size_t n = utf8_sequence(s, i);
    if (n == 0) {
      out += "\\ufffd";  // a byte that is not UTF-8 (JSON text must be): the replacement character
      ++i;
      continue;
    }
    if (n > 1) {
      out.append(s, i, n);
      i += n;
      continue;
    }
    ++i;
    switch (c) {
      case '"':
        out += "\\\"";
        break;
      case '\\':
        out += "\\\\";
        break;
      case '\n':
        out += "\\n";
        break;
      case '\t':
        out += "\\t";
        break;
      default:
        if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f)
          fmt::format_to(std::back_inserter(out), "\\u{:04x}", int(c));
        else
          out += c;
    }
  }
  out += '"';
}

std::string json_string(const std::string& s) {
  std::string out;
  append_json_string(out, s);
  return out;
}

void ResultValue::append_json(std::string& out) const {
  if (const auto* x = std::get_if<double>(&v_)) {
    if (std::isfinite(*x))
      fmt::format_to(std::back_inserter(out), "{}", *x);
    else
      out += "null";  // JSON has no NaN or infinity
  } else if (const auto* i = std::get_if<std::int64_t>(&v_)) {
    fmt::format_to(std::back_inserter(out), "{}", *i);
  } else if (const auto* b = std::get_if<bool>(&v_)) {
    out += *b ? "true" : "false";
  } else if (const auto* s = std::get_if<std::string>(&v_)) {
    append_json_string(out, *s);
  } else if (const auto* l = std::get_if<List>(&v_)) {
    out += '[';
    for (std::size_t k = 0; k < l->size(); ++k) {
      if (k) out += ", ";
      (*l)[k].append_json(out);
    }
    out += ']';
  } else {
    const Record& r = record();
    out += '{';
    for (std::size_t k = 0; k < r.size(); ++k) {
      if (k) out += ", ";
      append_json_string(out, r[k].first);
      out += ": ";
      r[k].second.append_json(out);
    }
    out += '}';
  }
}

std::string ResultValue::to_json() const {
  std::string out;
  append_json(out);
  return out;
}

std::string ResultValue::to_text(int indent) const {
  const std::string pad(indent, ' ');
  if (is_record()) {
    std::string out;
    for (const auto& [k, v] : record()) {
      if (v.is_record() || (v.is_list() && !v.items().empty() && v.items()[0].is_record()))
        out += pad + k + ":\n" + v.to_text(indent + 2);
      else
        out += pad + k + ": " + v.to_text(0) + "\n";
    }
    return out;
  }
  if (is_list()) {
    if (!items().empty() && items()[0].is_record()) {
      std::string out;
      for (const ResultValue& v : items()) out += pad + "-\n" + v.to_text(indent + 2);
      return out;
    }
    return to_json();
  }
  if (auto d = std::get_if<double>(&v_)) return fmt::format("{:.6g}", *d);
  if (auto s = std::get_if<std::string>(&v_)) return *s;
  return to_json();
}

}  // namespace workloads
