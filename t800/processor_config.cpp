#include "t800/processor_config.hpp"

namespace t800 {

double cycle_ns(SpeedGrade grade) {
  switch (grade) {
    case SpeedGrade::T800_20: return 50.0;
    case SpeedGrade::T800_25: return 40.0;
    case SpeedGrade::T800_30: return 100.0 / 3.0;
  }
  return 50.0;
}

std::string_view to_string(SpeedGrade grade) {
  switch (grade) {
    case SpeedGrade::T800_20: return "T800-20";
    case SpeedGrade::T800_25: return "T800-25";
    case SpeedGrade::T800_30: return "T800-30";
  }
  return "?";
}

std::optional<SpeedGrade> parse_speed_grade(std::string_view text) {
  for (SpeedGrade g : {SpeedGrade::T800_20, SpeedGrade::T800_25, SpeedGrade::T800_30})
    if (text == to_string(g)) return g;
  return std::nullopt;
}

std::string_view to_string(Placement placement) {
  return placement == Placement::on_chip ? "onchip" : "external";
}

std::optional<Placement> parse_placement(std::string_view text) {
  if (text == "onchip") return Placement::on_chip;
  if (text == "external") return Placement::external;
  return std::nullopt;
}

std::string_view to_string(LinkProtocol protocol) {
  return protocol == LinkProtocol::overlapped ? "overlapped" : "t414";
}

std::optional<LinkProtocol> parse_link_protocol(std::string_view text) {
  if (text == "overlapped") return LinkProtocol::overlapped;
  if (text == "t414") return LinkProtocol::t414;
  return std::nullopt;
}

bool is_valid_link_speed(double mbps) { return mbps == 5.0 || mbps == 10.0 || mbps == 20.0; }

}  // namespace t800
