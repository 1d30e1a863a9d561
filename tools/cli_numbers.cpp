#include "tools/cli_numbers.hpp"

#include <charconv>
#include <climits>
#include <cmath>
#include <cstdlib>
#include <string>

namespace tools {

CLI::Validator seconds_limit() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        const char* begin = text.c_str();
        char* end = nullptr;
        const double seconds = std::strtod(begin, &end);
        const bool number = !text.empty() && end == begin + text.size();
        if (!number || !std::isfinite(seconds) || seconds < 0)
          return "'" + text + "' is not a number of seconds: give a finite number, at least 0 " +
                 "(0 for no limit)";
        return "";
      },
      "SECONDS");
}

namespace {

// Integers from 0 to `largest`, written in full; `what` says what the value is for ("an index").
CLI::Validator integer_from_zero(long long largest, const std::string& what,
                                 const std::string& hint, const std::string& name) {
  return CLI::Validator(
      [=](std::string& text) -> std::string {
        long long value = -1;
        const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
        if (error != std::errc() || end != text.data() + text.size() || value < 0 ||
            value > largest)
          return "'" + text + "' is not " + what + ": give an integer from 0 to " +
                 std::to_string(largest) + hint;
        return "";
      },
      name);
}

}  // namespace

CLI::Validator index_from_zero() {
  return integer_from_zero(INT_MAX, "an index", "", "INDEX");
}

CLI::Validator count_limit() {
  return integer_from_zero(LLONG_MAX, "a count", " (0 for no limit)", "COUNT");
}

}  // namespace tools
