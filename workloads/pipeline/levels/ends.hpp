// A level's channels, as the pipeline skeleton gives its stage (t800sim/pipeline.hpp: StageEnds),
// kept as the channels' slots: one boundary carries Messages::Packet, or with recovery
// Messages::Checked (pipeline_program.cpp declares which), and the levels use each through the
// typed end of the protocol they send (context.hpp).
#pragma once

#include <vector>

#include "t800sim/pipeline.hpp"

namespace workloads::levels {

using Slot = t800sim::detail::ChannelSlot*;

// A channel to (or from) the stage next to a level, and the members of that stage it joins: one,
// or those behind a relay (which share the channel).
struct Port {
  Slot channel = nullptr;
  std::vector<int> served;
};

struct Ends {
  std::vector<Slot> from, to;  // per member of the stage before / after (level 4 alone: no to)
  std::vector<Port> from_ports, to_ports;
  Slot back = nullptr;         // the loop L3 -> L1 (level 1's input, level 3's output)
  bool behind_fan_in = false;  // level 2: its rows go to L3 through the fan-in Y

  template <class In_, class Out_>
  static Ends of(const t800sim::StageEnds<In_, Out_>& e, Slot back = nullptr) {
    Ends ends;
    for (const auto& c : e.from) ends.from.push_back(c.slot());
    for (const auto& c : e.to) ends.to.push_back(c.slot());
    for (const auto& p : e.from_ports()) ends.from_ports.push_back({p.channel.slot(), p.members});
    for (const auto& p : e.to_ports()) ends.to_ports.push_back({p.channel.slot(), p.members});
    ends.back = back;
    ends.behind_fan_in = e.behind_fan_in;
    return ends;
  }
};

}  // namespace workloads::levels
