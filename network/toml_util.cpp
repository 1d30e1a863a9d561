#include "network/toml_util.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>

#include <fmt/format.h>

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

// Missing files and directories get a plain message; toml++ would read a directory as an empty
// file.
toml::table parse_toml_file(const std::string& path, const std::string& what) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (fs::is_directory(path, ec))
    throw ConfigError({path, 0, 0}, "this is a directory, not a " + what);
  if (!fs::exists(path, ec)) throw ConfigError({path, 0, 0}, "no such " + what);
  const auto size = fs::file_size(path, ec);
  if (!ec && size > TomlLimits::kMaxBytes)  // not read at all (a device or a pipe has no size)
    throw ConfigError({path, 0, 0}, "the " + what + " is " + std::to_string(size) +
                                        " bytes; at most " + std::to_string(TomlLimits::kMaxBytes) +
                                        " are read");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw ConfigError({path, 0, 0}, "cannot open the " + what);
  std::string text;
  char buffer[1 << 16];
  while (in.read(buffer, sizeof buffer) || in.gcount() > 0) {
    text.append(buffer, static_cast<std::size_t>(in.gcount()));
    if (text.size() > TomlLimits::kMaxBytes) break;  // the limit check below says so
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
