// CSV lines (RFC 4180 quoting) for sweep results and trace files. Fields never span lines: writers
// replace line breaks with spaces, so files can be read line by line (and by any CSV reader).
#pragma once

#include <string>
#include <vector>

namespace tools {

// Appends one field, quoted when it holds a comma or a quote (newlines become spaces).
void append_csv_field(std::string& line, const std::string& field);
std::string csv_line(const std::vector<std::string>& fields);  // with the trailing newline
std::vector<std::string> parse_csv_line(const std::string& line);

// A number as CSV text: empty for NaN, else with `decimals` decimals.
std::string csv_number(double value, int decimals);
// The number in a CSV field: NaN for an empty field; throws std::invalid_argument for anything
// else.
double csv_to_number(const std::string& field);

}  // namespace tools
