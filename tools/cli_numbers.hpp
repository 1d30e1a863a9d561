// Checks for the commands' numeric flags, run on the text as written (CLI11 validators run before
// conversion), so a refused value is quoted as the user typed it: "--timeout nan", not a raw
// conversion message or a NaN silently meaning "no limit".
#pragma once

#include <CLI/CLI.hpp>

namespace tools {

// A finite number of seconds, at least 0 (0: no limit): refuses text that is not a number, NaN,
// infinities and negative values.
CLI::Validator seconds_limit();

// An integer from 0 up to the largest int, such as a point's index.
CLI::Validator index_from_zero();

// A count that limits something, an integer of 0 (no limit) or more.
CLI::Validator count_limit();

}  // namespace tools
