#include "sdk/placement.hpp"

#include <map>
#include <stdexcept>

namespace t800sim::detail {

namespace {

std::string member_name(const ProcessDecl& d, int i) {
  return d.group ? d.name + "[" + std::to_string(i) + "]" : d.name;
}

std::string declared_list(const Builder& b) {
  std::string s;
  for (const ProcessDecl& d : b.declared_processes()) {
    if (!s.empty()) s += ", ";
    s += d.group ? d.name + "[0.." + std::to_string(d.count - 1) + "]" : d.name;
  }
  return s.empty() ? "none" : s;
}

std::string processor_list(const network::Topology& t) {
  const std::size_t n = t.processors.size();
  if (n == 0) return "none";
  if (n <= 8) {
    std::string s;
    for (const auto& p : t.processors) s += (s.empty() ? "" : ", ") + p.name;
    return s;
  }
  return t.processors.front().name + " ... " + t.processors.back().name + " (" + std::to_string(n) +
         ")";
}

// What decides one process's processor, before its name is looked up.
struct Choice {
  std::string processor;
  std::string placed_by;
  std::optional<network::SourcePos> where;
};

// The processor for member i of a declaration placed on `names` (one for all, or one each).
std::optional<std::string> pick(const std::vector<std::string>& names, const ProcessDecl& d,
                                int i) {
  if (names.size() == 1) return names.front();
  if (int(names.size()) == d.count) return names[std::size_t(i)];
  return std::nullopt;
}

std::string where_text(const network::SourcePos& w) {
  return w.line > 0 ? w.file + ":" + std::to_string(w.line) : w.file;
}

}  // namespace

std::vector<PlacedProcess> place(const std::string& kind, const Builder& builder,
                                 const network::Topology& topology,
                                 const std::vector<workloads::PlacementEntry>& scene) {
  // The scene's entries by what they name: a declaration, or a group member.
  std::map<std::string, const workloads::PlacementEntry*> by_name;
  for (const workloads::PlacementEntry& e : scene) {
    bool known = false;
    for (const ProcessDecl& d : builder.declared_processes()) {
      if (e.process == d.name) known = true;
      for (int i = 0; d.group && i < d.count; ++i) known = known || e.process == member_name(d, i);
    }
    if (!known)
      throw network::ConfigError(
          e.where, "[placement] names process " + e.process + ", which workload " + kind +
                       " does not declare; it declares " + declared_list(builder));
    if (e.processors.empty())
      throw network::ConfigError(
          e.where, "[placement] " + e.process + ": give a processor name or a list of them");
    by_name[e.process] = &e;
  }

  std::vector<PlacedProcess> placed;
  for (const ProcessDecl& d : builder.declared_processes()) {
    const auto* group_entry = by_name.count(d.name) ? by_name.at(d.name) : nullptr;
    if (group_entry && group_entry->processors.size() != 1 &&
        int(group_entry->processors.size()) != d.count)
      throw network::ConfigError(group_entry->where,
                                 "[placement] " + d.name + ": " + std::to_string(d.count) +
                                     " processes, so one processor for all or a list of " +
                                     std::to_string(d.count) + ", not " +
                                     std::to_string(group_entry->processors.size()));
    if (!d.on.empty() && d.on.size() != 1 && int(d.on.size()) != d.count)
      throw std::invalid_argument("workload " + kind + " places " + d.name + " (" +
                                  std::to_string(d.count) + " processes) on " +
                                  std::to_string(d.on.size()) + " processors");
    for (int i = 0; i < d.count; ++i) {
      const std::string name = member_name(d, i);
      Choice c;
      const auto* own = by_name.count(name) && d.group ? by_name.at(name) : nullptr;
      if (own && own->processors.size() != 1)
        throw network::ConfigError(own->where,
                                   "[placement] " + name + ": one process, one processor");
      if (const auto* e = own ? own : group_entry) {
        c = {*pick(e->processors, d, i), "scene " + where_text(e->where), e->where};
      } else if (d.on_host) {
        if (d.body)
          throw std::invalid_argument("workload " + kind + ": " + name +
                                      " is placed on the host, where only a process its caller "
                                      "spawns runs (declared without a body)");
        placed.push_back({name, &d, i, -1, "the program (the host)", std::nullopt});
        continue;
      } else if (!d.on.empty()) {
        c = {*pick(d.on, d, i), "the program", std::nullopt};
      } else {
        const int host = std::max(topology.host_processor(), 0);
        c = {topology.processors.at(std::size_t(host)).name,
             "default: the processor wired to the host", std::nullopt};
      }
      const int node = topology.find(c.processor);
      if (node < 0) {
        const std::string message = name + " is placed on " + c.processor +
                                    ", which the network does not have; it has " +
                                    processor_list(topology);
        if (c.where) throw network::ConfigError(*c.where, "[placement] " + message);
        throw std::invalid_argument("workload " + kind + ": " + message);
      }
      placed.push_back({name, &d, i, node, c.placed_by, c.where});
    }
  }
  return placed;
}

}  // namespace t800sim::detail
