// Command-line mistakes CLI11 reports vaguely ("A subcommand is required", "The following arguments
// were not expected: SCENE --workers") said plainly: what was wrong and what would be valid.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

namespace tools {

// The message for a parse error of `t800sim ARGS...` (args without the program name), or nullopt to
// let CLI11 print its own (help, version, errors it already says well).
std::optional<std::string> explain_parse_error(const CLI::App& app,
                                               const std::vector<std::string>& args,
                                               const CLI::ParseError& error);

// The scene files in configs/scenes/ (found as find_repository_file finds files), for messages;
// empty when the directory cannot be found.
std::vector<std::string> shipped_scenes();

}  // namespace tools
