#include "network/topology.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

#include "network/link_index.hpp"
#include "network/routes.hpp"

#include "t800/processor_config.hpp"

namespace network {

int Topology::find(const std::string& wanted) const {
  for (std::size_t i = 0; i < processors.size(); ++i)
    if (processors[i].name == wanted) return static_cast<int>(i);
  return -1;
}

int Topology::connection_at(int processor, int link) const {
  const LinkEnd end{processor, link};
  for (std::size_t i = 0; i < connections.size(); ++i)
    if (connections[i].a == end || connections[i].b == end) return static_cast<int>(i);
  return -1;
}

LinkEnd Topology::peer(int processor, int link) const {
  const Connection& c = connections.at(static_cast<std::size_t>(connection_at(processor, link)));
  return c.a == LinkEnd{processor, link} ? c.b : c.a;
}

// One reading of the list (the first connection listed at each of p's links), not one per link.
std::vector<int> Topology::neighbours(int p) const {
  int far[kLinksPerProcessor] = {-1, -1, -1, -1};
  for (const Connection& c : connections)
    for (const auto& [end, other] : {std::pair{c.a, c.b}, std::pair{c.b, c.a}})
      if (end.processor == p && end.link >= 0 && end.link < kLinksPerProcessor && far[end.link] < 0)
        far[end.link] = other.processor;
  std::vector<int> result;
  for (int q :
       far)  // link order; two links between the same pair (a ring of two) make one neighbour
    if (q >= 0 && std::find(result.begin(), result.end(), q) == result.end()) result.push_back(q);
  return result;
}

std::vector<int> Topology::shortest_path(int from, int to) const {
  return Routes(*this).path(from, to);
}

namespace {

std::string end_name(const Topology& t, const LinkEnd& end) {
  return t.processors[static_cast<std::size_t>(end.processor)].name + ".link" +
         std::to_string(end.link);
}

std::string position_text(const SourcePos& where) {
  if (where.line == 0) return where.file;
  return where.file + ":" + std::to_string(where.line) + ":" + std::to_string(where.column);
}

std::string speed_text(double mbps) {
  // Speeds are whole numbers in every valid case; show fractions only when someone wrote one.
  if (std::abs(mbps) < 1e15 && mbps == std::floor(mbps))
    return std::to_string(static_cast<long long>(mbps));
  std::string text = std::to_string(mbps);
  while (text.back() == '0') text.pop_back();
  return text;
}

void check_names(const Topology& t) {
  std::map<std::string, const ProcessorSpec*> seen;
  for (const ProcessorSpec& p : t.processors) {
    auto [it, fresh] = seen.emplace(p.name, &p);
    if (!fresh)
      throw ConfigError(p.where, "duplicate processor name '" + p.name + "' (first defined at " +
                                     position_text(it->second->where) +
                                     "); every processor needs its own name");
  }
}

// Link numbers and processor indices of one end (generators and files both pass through here).
void check_end(const Topology& t, const LinkEnd& end, const SourcePos& where) {
  const int n = static_cast<int>(t.processors.size());
  if (end.processor < 0 || end.processor >= n)
    throw ConfigError(where, "link end refers to processor #" + std::to_string(end.processor) +
                                 ", but the topology has processors #0 to #" +
                                 std::to_string(n - 1));
  if (end.link < 0 || end.link >= kLinksPerProcessor)
    throw ConfigError(where, "link index " + std::to_string(end.link) + " of processor '" +
                                 t.processors[static_cast<std::size_t>(end.processor)].name +
                                 "' is outside 0-3: a T800 has four links, link0 to link3");
}

void check_host(const Topology& t) {
  const SourcePos whole{t.source, 0, 0};
  if (!t.host)
    throw ConfigError(whole,
                      "no host connection: name the processor link wired to the host PC, "
                      "e.g. host = \"P0.link0\"");
  check_end(t, *t.host, whole);
}

void check_connection(const Topology& t, const Connection& c) {
  check_end(t, c.a, c.where);
  check_end(t, c.b, c.where);
  if (c.a.processor == c.b.processor)
    throw ConfigError(c.where, "link " + end_name(t, c.a) + " - " + end_name(t, c.b) +
                                   " connects processor '" +
                                   t.processors[static_cast<std::size_t>(c.a.processor)].name +
                                   "' to itself; a link must join two different processors");
  if (c.speed_mbps && !t800::is_valid_link_speed(*c.speed_mbps))
    throw ConfigError(c.where, "link speed " + speed_text(*c.speed_mbps) +
                                   " Mbit/s is not supported: a T800 link runs at 5, 10 or 20 "
                                   "Mbit/s");
}

// Each physical link end carries one wire pair: a second use (or the host's) is a wiring error.
void check_ends_unique(const Topology& t) {
  std::map<std::pair<int, int>, std::string> used;  // end -> who uses it, for the message
  used[{t.host->processor, t.host->link}] = "the host";
  for (const Connection& c : t.connections) {
    const std::pair<LinkEnd, LinkEnd> sides[] = {{c.a, c.b}, {c.b, c.a}};
    for (const auto& [end, other] : sides) {
      auto [it, fresh] = used.emplace(std::pair{end.processor, end.link}, "");
      if (!fresh)
        throw ConfigError(c.where, end_name(t, end) + " is already connected to " + it->second +
                                       "; each link end can carry only one connection");
      it->second = end_name(t, other) + " (" + position_text(c.where) + ")";
    }
  }
}

std::vector<bool> reachable_from(const Topology& t, int start) {
  const LinkIndex index(t);
  std::vector<bool> reached(t.processors.size(), false);
  std::vector<int> stack{start};
  reached[static_cast<std::size_t>(start)] = true;
  while (!stack.empty()) {
    const int p = stack.back();
    stack.pop_back();
    for (int q : index.neighbours(p)) {
      if (reached[static_cast<std::size_t>(q)]) continue;
      reached[static_cast<std::size_t>(q)] = true;
      stack.push_back(q);
    }
  }
  return reached;
}

void check_reachable(const Topology& t) {
  const std::vector<bool> reached = reachable_from(t, t.host_processor());
  std::vector<std::string> lost;
  const ProcessorSpec* first = nullptr;
  for (std::size_t p = 0; p < t.processors.size(); ++p) {
    if (reached[p]) continue;
    if (!first) first = &t.processors[p];
    lost.push_back(t.processors[p].name);
  }
  if (lost.empty()) return;
  std::string names;
  for (const std::string& name : lost) names += (names.empty() ? "" : ", ") + name;
  throw ConfigError(first->where, "processor" + std::string(lost.size() > 1 ? "s " : " ") + names +
                                      " cannot be reached from the host (" + end_name(t, *t.host) +
                                      "); link them to the rest of the network");
}

}  // namespace

void validate(const Topology& topology) {
  if (topology.processors.empty())
    throw ConfigError(SourcePos{topology.source, 0, 0},
                      "the topology has no processors: add at least one [[processor]]");
  if (topology.processors.size() > std::size_t(kMaxProcessors))
    throw ConfigError(topology.processors[std::size_t(kMaxProcessors)].where,
                      "the topology has " + std::to_string(topology.processors.size()) +
                          " processors; at most " + std::to_string(kMaxProcessors) + " are simulated");
  check_names(topology);
  check_host(topology);
  for (const Connection& c : topology.connections) check_connection(topology, c);
  check_ends_unique(topology);
  check_reachable(topology);
}

}  // namespace network
