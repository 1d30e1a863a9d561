// A validated network of transputers: plain data (docs/architecture.md). Built from a topology file
// (topology_file.hpp) or a family generator (families.hpp); elaborated into SystemC modules elsewhere.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "network/config_error.hpp"
#include "t800/processor_config.hpp"

namespace network {

constexpr int kLinksPerProcessor = 4;

struct ProcessorSpec {
  std::string name;
  t800::ProcessorConfig config;
  SourcePos where;
};

// One end of a link: processor index into Topology::processors and link number 0..3.
struct LinkEnd {
  int processor = -1;
  int link = -1;
  bool operator==(const LinkEnd& o) const { return processor == o.processor && link == o.link; }
};

struct Connection {
  LinkEnd a, b;
  std::optional<double> speed_mbps;  // unset: the scene's network.link_speed_mbps
  SourcePos where;
};

struct Topology {
  std::string name;
  std::string description;
  std::string source;  // file it came from, or "family:tree(9)" for generated ones
  std::vector<ProcessorSpec> processors;
  std::vector<Connection> connections;
  std::optional<LinkEnd> host;  // the link of the processor wired to the host PC

  int find(const std::string& name) const;  // index, or -1
  // The connection index plugged into (processor, link), or -1 when that link is unused.
  int connection_at(int processor, int link) const;
  // The far end of the connection at (processor, link); requires connection_at(...) >= 0.
  LinkEnd peer(int processor, int link) const;
  // Processor indices adjacent to p, in link order. (Each call reads the connection list: code
  // that asks often keeps a network::LinkIndex.)
  std::vector<int> neighbours(int p) const;
  // A shortest path from -> to as processor indices (both included); deterministic (lowest link
  // first, network/routes.hpp). Empty when unreachable. (Code that asks often keeps a
  // network::Routes.)
  std::vector<int> shortest_path(int from, int to) const;
  // The processor wired to the host, or -1.
  int host_processor() const { return host ? host->processor : -1; }
};

// The largest network simulated: each transputer costs some 60 KB of host memory and about five SystemC
// threads, whose stacks the host maps one by one (a process may hold some 65,000 maps), and routes are
// found by search; 40,000 transputers ran out of maps (issue 12). Generated families stop here too.
constexpr int kMaxProcessors = 1024;

// Structural checks shared by files and generators: duplicate names, link index 0..3, a link end used
// twice (including by the host), self-loops, speeds, processors unreachable from the host, more than
// kMaxProcessors.
// Throws ConfigError at the offending item's `where`.
void validate(const Topology& topology);

}  // namespace network
