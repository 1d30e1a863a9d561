// The configurable facts of one transputer and its links: plain data, filled in by network/ from
// topology files, read by the compute model and the SystemC modules.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "t800/processors/processor_model.hpp"

namespace t800 {

// A processor's cycle time (its type's, processors/processor_model.hpp).
double cycle_ns(ProcessorType type);

// Where code and data live (docs/t800-timing.md, "Memory"). automatic: what fits in on-chip RAM
// goes there, the rest in external memory, by the placement policy of memory_map.hpp.
enum class Placement { automatic, on_chip, external };
std::string_view to_string(Placement placement);
std::optional<Placement> parse_placement(std::string_view text);  // "auto", "onchip" or "external"

struct MemoryConfig {
  Placement data = Placement::automatic;  // workspaces and arrays
  Placement code = Placement::automatic;
  int wait_states = 0;  // programmed wait states per external memory access
};

struct ProcessorConfig {
  ProcessorType type = ProcessorType::T800_20;
  MemoryConfig memory;
};

std::string_view to_string(LinkProtocol protocol);
std::optional<LinkProtocol> parse_link_protocol(std::string_view text);  // "overlapped" or "t414"

// The link speeds a T800 supports, in Mbit/s.
bool is_valid_link_speed(double mbps);  // 5, 10 or 20

struct LinkConfig {
  double speed_mbps = 20.0;
  LinkProtocol protocol = LinkProtocol::overlapped;
};

}  // namespace t800
