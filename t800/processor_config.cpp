#include "t800/processor_config.hpp"

namespace t800 {

double cycle_ns(ProcessorType type) {
  return processor_model(type).cycle_ns;
}

std::string_view to_string(Placement placement) {
  switch (placement) {
    case Placement::automatic:
      return "auto";
    case Placement::on_chip:
      return "onchip";
    case Placement::external:
      return "external";
  }
  return "?";
}

std::optional<Placement> parse_placement(std::string_view text) {
  for (Placement p : {Placement::automatic, Placement::on_chip, Placement::external})
    if (text == to_string(p)) return p;
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

bool is_valid_link_speed(double mbps) {
  return mbps == 5.0 || mbps == 10.0 || mbps == 20.0;
}

}  // namespace t800
