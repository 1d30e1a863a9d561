#include "t800sim/pipeline.hpp"

#include <algorithm>
#include <numeric>

namespace t800sim::detail {

std::string member(const std::string& name, bool group, int i) {
  return group ? name + "[" + std::to_string(i) + "]" : name;
}

std::string link_name(const std::string& from, const std::string& to, int j, int i) {
  return from + "->" + to + "[" + std::to_string(j) + "][" + std::to_string(i) + "]";
}

std::vector<int> partners(int i, int count, int other, int rounds) {
  std::vector<int> out;
  const int period = std::lcm(count, other);
  for (int r = i; r < std::min(rounds, period); r += count)
    if (std::find(out.begin(), out.end(), r % other) == out.end()) out.push_back(r % other);
  return out;
}

std::vector<int> joined(bool all, int i, int count, int other, int rounds) {
  if (!all) return partners(i, count, other, rounds);
  std::vector<int> every(static_cast<std::size_t>(other));
  std::iota(every.begin(), every.end(), 0);
  return every;
}

ProcessDecl& members(Builder& b, const std::string& name, int count, bool group,
                     Process::IndexedBody body) {
  if (group) return b.processes(name, count, std::move(body));
  return b.process(name, [body = std::move(body)](Process& p) { body(p, 0); });
}

}  // namespace t800sim::detail
