#include "network/toml_util.hpp"

#include <cmath>

#include <fmt/format.h>

#include "network/input_file.hpp"
#include "network/toml_limits.hpp"

namespace network {

SourcePos pos_of(const toml::source_region& source, const std::string& file) {
  if (source.path && *source.path != file) return {*source.path, 0, 0};
  if (source.begin.line == 0) return {file, 0, 0};
  return {file, static_cast<int>(source.begin.line), static_cast<int>(source.begin.column)};
}

std::string type_name(const toml::node& node) {
  switch (node.type()) {
    case toml::node_type::string:
      return "string";
    case toml::node_type::integer:
      return "integer";
    case toml::node_type::floating_point:
      return "floating-point number";
    case toml::node_type::boolean:
      return "boolean";
    case toml::node_type::table:
      return "table";
    case toml::node_type::array:
      return "array";
    case toml::node_type::date:
      return "date";
    case toml::node_type::time:
      return "time";
    case toml::node_type::date_time:
      return "date-time";
    case toml::node_type::none:
      break;
  }
  return "nothing";
}

// A file that is not there, not a regular file or too long gets a plain message before any of it
// is parsed; toml++ would read a directory or an unreadable file as an empty one.
toml::table parse_toml_file(const std::string& path, const std::string& what) {
  std::string text;
  try {
    text = read_input_file(path, TomlLimits::kMaxBytes);
  } catch (const InputFileError& e) {
    if (e.missing) throw ConfigError({path, 0, 0}, "no such " + what);
    throw ConfigError({path, 0, 0}, std::string(e.what()) + "; give a " + what + " (TOML text)");
  }
  return parse_toml_text(text, path);
}

toml::table parse_toml_text(std::string_view text, const std::string& file) {
  check_toml_limits(text, file);
  try {
    return toml::parse(text, std::string_view(file));
  } catch (const toml::parse_error& e) {
    throw ConfigError(pos_of(e.source(), file), std::string(e.description()));
  }
}

double number(const toml::node& node) {
  if (const auto* i = node.as_integer()) return static_cast<double>(i->get());
  return node.as_floating_point()->get();
}

std::string join(const std::vector<std::string>& items) {
  std::string text;
  for (const std::string& item : items) text += (text.empty() ? "" : ", ") + item;
  return text;
}

// The shortest text that reads back as the same double (fmt's default), so a message never rounds
// a value into another (10.000000000000002 is not "10.") nor spells 1e308 in 309 digits.
std::string number_text(double value) {
  return fmt::format("{}", value);
}

// An integer exactly as it was read: 2^63 - 1 is not the double 9223372036854775808.
std::string number_text(const toml::node& node) {
  if (const auto* i = node.as_integer()) return std::to_string(i->get());
  return number_text(number(node));
}

std::string plural(std::size_t n, const char* word) {
  return std::to_string(n) + " " + word + (n == 1 ? "" : "s");
}

}  // namespace network
