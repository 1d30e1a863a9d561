#include "t800/fidelity.hpp"

namespace t800 {

std::string_view to_string(LinkFidelity fidelity) {
  switch (fidelity) {
    case LinkFidelity::automatic:
      return "auto";
    case LinkFidelity::message:
      return "message";
    case LinkFidelity::packet:
      return "packet";
  }
  return "?";
}

std::string_view to_string(ComputeFidelity fidelity) {
  switch (fidelity) {
    case ComputeFidelity::automatic:
      return "auto";
    case ComputeFidelity::block:
      return "block";
    case ComputeFidelity::fine:
      return "fine";
  }
  return "?";
}

std::optional<LinkFidelity> parse_link_fidelity(std::string_view text) {
  for (LinkFidelity f : {LinkFidelity::automatic, LinkFidelity::message, LinkFidelity::packet})
    if (text == to_string(f)) return f;
  return std::nullopt;
}

std::optional<ComputeFidelity> parse_compute_fidelity(std::string_view text) {
  for (ComputeFidelity f :
       {ComputeFidelity::automatic, ComputeFidelity::block, ComputeFidelity::fine})
    if (text == to_string(f)) return f;
  return std::nullopt;
}

std::string_view to_string(ComputeCost cost) {
  return cost == ComputeCost::mix ? "mix" : "instructions";
}

std::optional<ComputeCost> parse_compute_cost(std::string_view text) {
  for (ComputeCost c : {ComputeCost::instructions, ComputeCost::mix})
    if (text == to_string(c)) return c;
  return std::nullopt;
}

}  // namespace t800
