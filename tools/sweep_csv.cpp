#include "tools/sweep_csv.hpp"

#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

namespace tools {

void append_csv_field(std::string& line, const std::string& field) {
  const bool quote = field.find_first_of(",\"") != std::string::npos;
  if (quote) line += '"';
  for (char c : field) {
    if (c == '\n' || c == '\r') c = ' ';
    if (c == '"') line += '"';
    line += c;
  }
  if (quote) line += '"';
}

std::string csv_line(const std::vector<std::string>& fields) {
  std::string line;
  for (std::size_t i = 0; i < fields.size(); ++i) {
    if (i) line += ',';
    append_csv_field(line, fields[i]);
  }
  return line + "\n";
}

std::vector<std::string> parse_csv_line(const std::string& line) {
  std::vector<std::string> fields(1);
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted && c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
      fields.back() += '"';
      ++i;
    } else if (c == '"') {
      quoted = !quoted;
    } else if (c == ',' && !quoted) {
      fields.emplace_back();
    } else if (c != '\r') {
      fields.back() += c;
    }
  }
  return fields;
}

std::string csv_number(double value, int decimals) {
  return std::isnan(value) ? std::string() : fmt::format("{:.{}f}", value, decimals);
}

double csv_to_number(const std::string& field) {
  if (field.empty()) return std::nan("");
  std::size_t used = 0;
  double value = 0;
  try {
    value = std::stod(field, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != field.size()) throw std::invalid_argument("'" + field + "' is not a number");
  return value;
}

}  // namespace tools
