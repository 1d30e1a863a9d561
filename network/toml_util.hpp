// What every reader of a TOML configuration file needs: positions for errors, plain type names,
// reading a file with clear errors, and the small text helpers of messages. Used by topology,
// scene, robot and paper files.
#pragma once

#include <string>
#include <vector>

#include <toml++/toml.h>

#include "network/config_error.hpp"

namespace network {

// Where a node is. A node that came from somewhere other than `file` (a --set override parsed on
// its own) keeps its origin's name but not its line numbers, which would mean nothing in `file`.
SourcePos pos_of(const toml::source_region& source, const std::string& file);

// "string", "integer", "floating-point number", ... for "expected X, got Y" messages.
std::string type_name(const toml::node& node);

// Reads a TOML file; a missing file, a directory, a file beyond the limits of
// network/toml_limits.hpp or a syntax error becomes a ConfigError. `what` names the kind of file in
// the message ("scene file", "topology file").
toml::table parse_toml_file(const std::string& path, const std::string& what);

// The same for text already in memory; `file` names it in errors.
toml::table parse_toml_text(std::string_view text, const std::string& file);

// toml++'s value<double>() gives nothing for integers beyond 2^53; this converts any number node.
double number(const toml::node& node);

std::string join(const std::vector<std::string>& items);  // "a, b, c"
std::string number_text(double value);                    // 20 -> "20", 2.5 -> "2.5"
std::string number_text(const toml::node& node);          // an integer node exactly
std::string plural(std::size_t n, const char* word);      // "1 link", "3 links"

}  // namespace network
