#include "workloads/run/result_value.hpp"

#include <cmath>
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
      if (std::string at = (*l)[i].first_non_finite(path + "[" + std::to_string(i) + "]"); !at.empty())
        return at;
  if (const auto* r = std::get_if<Record>(&v_))
    for (const auto& [key, value] : *r)
      if (std::string at = value.first_non_finite(path.empty() ? key : path + "." + key); !at.empty())
        return at;
  return "";
}

namespace {
std::string quote(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    switch (c) {
      case '"': out += "\\\""; break;
      case '\\': out += "\\\\"; break;
      case '\n': out += "\\n"; break;
      case '\t': out += "\\t"; break;
      default:
        if (static_cast<unsigned char>(c) < 0x20)
          out += fmt::format("\\u{:04x}", c);
        else
          out += c;
    }
  }
  return out + "\"";
}

std::string number_text(double x) {
  if (!std::isfinite(x)) return "null";  // JSON has no NaN or infinity
  return fmt::format("{}", x);
}
}  // namespace

std::string ResultValue::to_json() const {
  struct Visitor {
    std::string operator()(double x) const { return number_text(x); }
    std::string operator()(std::int64_t x) const { return std::to_string(x); }
    std::string operator()(bool x) const { return x ? "true" : "false"; }
    std::string operator()(const std::string& s) const { return quote(s); }
    std::string operator()(const List& l) const {
      std::string out = "[";
      for (std::size_t i = 0; i < l.size(); ++i) out += (i ? ", " : "") + l[i].to_json();
      return out + "]";
    }
    std::string operator()(const Record& r) const {
      std::string out = "{";
      for (std::size_t i = 0; i < r.size(); ++i)
        out += (i ? ", " : "") + quote(r[i].first) + ": " + r[i].second.to_json();
      return out + "}";
    }
  };
  return std::visit(Visitor{}, v_);
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
