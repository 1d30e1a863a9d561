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

std::string fan_out_name(const std::string& stage) {
  return stage + "_fan_out";
}
std::string fan_in_name(const std::string& stage) {
  return stage + "_fan_in";
}

std::string in_channel(const StageWiring& w, const std::string& stage, int j, int i) {
  if (w.via_fan_out[std::size_t(i)]) return link_name(fan_out_name(stage), stage, 0, i);
  if (w.before_via_fan_in[std::size_t(j)]) return link_name(fan_in_name(w.before), stage, 0, i);
  return link_name(w.before, stage, j, i);
}

std::string out_channel(const StageWiring& w, const std::string& stage, int i, int j) {
  if (w.via_fan_in[std::size_t(i)]) return link_name(stage, fan_in_name(stage), i, 0);
  if (w.after_via_fan_out[std::size_t(j)]) return link_name(stage, fan_out_name(w.after), i, 0);
  return link_name(stage, w.after, i, j);
}

std::vector<bool> behind(const Network& network, const std::string& neighbour,
                         const std::string& relay, const std::vector<std::string>& members) {
  const auto index = [&](const std::string& processor) {
    const int i = network.find(processor);
    if (i < 0) throw std::logic_error("pipeline relay: no processor " + processor);
    return i;
  };
  const auto linked = [&](int a, int b) {
    const std::vector<int> n = network.neighbours(a);
    return std::find(n.begin(), n.end(), b) != n.end();
  };
  const int from = index(neighbour), via = index(relay);
  std::vector<bool> out;
  for (const std::string& m : members) {
    const int to = index(m);
    out.push_back(!linked(from, to) && linked(via, from) && linked(via, to));
  }
  return out;
}

ProcessDecl& members(Builder& b, const std::string& name, int count, bool group,
                     Process::IndexedBody body) {
  if (group) return b.processes(name, count, std::move(body));
  return b.process(name, [body = std::move(body)](Process& p) { body(p, 0); });
}

}  // namespace t800sim::detail
