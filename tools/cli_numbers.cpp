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

CLI::Validator index_from_zero() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        long long value = -1;
        const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
        if (error != std::errc() || end != text.data() + text.size() || value < 0 ||
            value > INT_MAX)
          return "'" + text + "' is not an index: give an integer from 0 to " +
                 std::to_string(INT_MAX);
        return "";
      },
      "INDEX");
}

}  // namespace tools
