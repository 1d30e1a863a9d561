#include "tools/sweep_spec.hpp"

#include <cstdint>
#include <limits>
#include <optional>
#include <set>
#include <stdexcept>

namespace tools {

namespace {

// A sweep bigger than this is almost certainly a typo (1..100000), not a plan.
constexpr std::size_t kMaxPoints = 100000;

std::optional<std::int64_t> whole_integer(const std::string& text) {
  if (text.empty()) return std::nullopt;
  std::size_t used = 0;
  try {
    const long long value = std::stoll(text, &used);
    if (used == text.size()) return value;
  } catch (const std::exception&) {
  }
  return std::nullopt;
}

[[noreturn]] void bad_vary(const std::string& flag, const std::string& why) {
  throw std::invalid_argument("--vary " + flag + ": " + why + "; valid forms: " + vary_forms());
}

struct Step {
  bool geometric = false;
  std::int64_t by = 1;
};

Step parse_step(const std::string& flag, const std::string& text) {
  if (text.size() < 2 || (text[0] != 'x' && text[0] != '+'))
    bad_vary(flag, "the step '" + text + "' must be xF (a factor) or +S (an increment)");
  const auto by = whole_integer(text.substr(1));
  const bool geometric = text[0] == 'x';
  if (!by || *by < (geometric ? 2 : 1))
    bad_vary(flag, geometric ? "the factor in '" + text + "' must be an integer of at least 2"
                             : "the increment in '" + text + "' must be a positive integer");
  return {geometric, *by};
}

std::vector<std::string> range_values(const std::string& flag, const std::string& range) {
  const auto dots = range.find("..");
  const auto colon = range.find(':', dots);
  const auto lo = whole_integer(range.substr(0, dots));
  const auto hi =
      whole_integer(range.substr(dots + 2, colon == std::string::npos ? colon : colon - dots - 2));
  if (!lo || !hi) bad_vary(flag, "range bounds must be integers (list other values: 0.5,1,2)");
  if (*lo > *hi) bad_vary(flag, "the range starts above its end");
  const Step step = colon == std::string::npos ? Step{} : parse_step(flag, range.substr(colon + 1));
  if (step.geometric && *lo < 1) bad_vary(flag, "a geometric range must start at 1 or more");
  std::vector<std::string> values;
  for (std::int64_t v = *lo; v <= *hi;) {
    values.push_back(std::to_string(v));
    if (values.size() > kMaxPoints) bad_vary(flag, "the range has more than 100000 values");
    const std::int64_t room = std::numeric_limits<std::int64_t>::max();
    if (step.geometric ? v > room / step.by : v > room - step.by) break;
    v = step.geometric ? v * step.by : v + step.by;
  }
  return values;
}

std::vector<std::string> list_values(const std::string& flag, const std::string& list) {
  std::vector<std::string> values;
  std::size_t start = 0;
  for (;;) {
    const auto comma = list.find(',', start);
    const std::string value =
        list.substr(start, comma == std::string::npos ? comma : comma - start);
    if (value.empty()) bad_vary(flag, "empty value in the list '" + list + "'");
    // "1-8" is a range written the wrong way, not a value anyone means.
    const auto dash = value.find('-', 1);
    if (dash != std::string::npos && whole_integer(value.substr(0, dash)) &&
        whole_integer(value.substr(dash + 1)))
      bad_vary(flag, "'" + value + "' is not a range: write " + value.substr(0, dash) + ".." +
                         value.substr(dash + 1));
    values.push_back(value);
    if (comma == std::string::npos) return values;
    start = comma + 1;
  }
}

}  // namespace

const char* vary_forms() {
  return "KEY=A..B (integers, step 1), KEY=A..B:xF (geometric, factor F >= 2), KEY=A..B:+S (step "
         "S), "
         "KEY=V1,V2,... (a list)";
}

SweepAxis parse_vary(const std::string& flag) {
  const auto eq = flag.find('=');
  if (eq == std::string::npos || eq == 0) bad_vary(flag, "expected KEY=VALUES");
  SweepAxis axis{flag.substr(0, eq), {}};
  const std::string values = flag.substr(eq + 1);
  if (values.empty()) bad_vary(flag, "no values after '='");
  // A range is recognised by "..": only a path ("../topologies/a.toml") has two dots in a row too.
  const bool range =
      values.find("..") != std::string::npos && values.find('/') == std::string::npos;
  axis.values = range ? range_values(flag, values) : list_values(flag, values);
  return axis;
}

std::vector<SweepPoint> sweep_points(const std::vector<SweepAxis>& axes) {
  std::set<std::string> keys;
  std::size_t total = 1;
  for (const SweepAxis& axis : axes) {
    if (!keys.insert(axis.key).second)
      throw std::invalid_argument("--vary " + axis.key +
                                  " is given twice; give one --vary per key");
    total *= axis.values.size();
    if (total > kMaxPoints)
      throw std::invalid_argument(
          "the sweep has more than 100000 points; split it into several sweeps");
  }
  std::vector<SweepPoint> points;
  std::vector<std::size_t> at(axes.size(), 0);
  for (std::size_t n = 0; n < total; ++n) {
    SweepPoint point;
    for (std::size_t a = 0; a < axes.size(); ++a)
      point.emplace_back(axes[a].key, axes[a].values[at[a]]);
    points.push_back(std::move(point));
    // Odometer: the last axis turns fastest.
    for (std::size_t a = axes.size(); a-- > 0;) {
      if (++at[a] < axes[a].values.size()) break;
      at[a] = 0;
    }
  }
  return points;
}

std::string point_text(const SweepPoint& point) {
  std::string text;
  for (const auto& [key, value] : point) text += (text.empty() ? "" : " ") + key + "=" + value;
  return text;
}

}  // namespace tools
