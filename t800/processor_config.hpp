// The configurable facts of one transputer and its links: plain data, filled in by network/ from topology
// files, read by the cost model and the SystemC modules.
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace t800 {

// Speed grades of the T800 (docs/t800-timing.md section 1).
enum class SpeedGrade { T800_20, T800_25, T800_30 };

double cycle_ns(SpeedGrade grade);
std::string_view to_string(SpeedGrade grade);
std::optional<SpeedGrade> parse_speed_grade(std::string_view text);  // "T800-20", "T800-25", "T800-30"

// Where code and data live (docs/t800-timing.md section 5).
enum class Placement { on_chip, external };
std::string_view to_string(Placement placement);
std::optional<Placement> parse_placement(std::string_view text);  // "onchip" or "external"

struct MemoryConfig {
  Placement data = Placement::on_chip;
  Placement code = Placement::on_chip;
  int wait_states = 0;  // programmed wait states per external access
};

struct ProcessorConfig {
  SpeedGrade grade = SpeedGrade::T800_20;
  MemoryConfig memory;
};

// T800 links acknowledge a byte as soon as its packet starts arriving; T414 links only after the whole packet
// (docs/t800-timing.md section 6).
enum class LinkProtocol { overlapped, t414 };
std::string_view to_string(LinkProtocol protocol);
std::optional<LinkProtocol> parse_link_protocol(std::string_view text);  // "overlapped" or "t414"

// The link speeds a T800 supports, in Mbit/s.
bool is_valid_link_speed(double mbps);  // 5, 10 or 20

struct LinkConfig {
  double speed_mbps = 20.0;
  LinkProtocol protocol = LinkProtocol::overlapped;
};

}  // namespace t800
