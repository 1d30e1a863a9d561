// The channels between the pipeline's levels and which level-2 processor each reaches: planned once
// before the run from the topology (four links per T800), with the relays on the link processors X
// and Y spawned where L1 or L3 cannot reach a level-2 processor directly (relay.hpp). The levels
// only read it.
#pragma once

#include <map>
#include <memory>
#include <vector>

#include "network/machine.hpp"
#include "t800sim/channel.hpp"
#include "workloads/pipeline/pipeline_program.hpp"
#include "workloads/pipeline/relay.hpp"
#include "workloads/pipeline/schedule.hpp"

namespace workloads::levels {

// A channel out of L1 (into L3) and the level-2 processors whose rows it carries.
struct Port {
  network::Channel* channel = nullptr;
  std::vector<int> served;
};

struct Wiring {
  network::Channel* input = nullptr;           // client -> L1: the system, or finish
  network::Channel* reply = nullptr;           // L4 -> client: q̈ (Serve::until_finish only)
  network::Channel* back = nullptr;            // L3 -> L1: the reduced matrix, row by row
  network::Channel* to_l4 = nullptr;           // L3 -> L4: the pivot rows (the rows of U)
  std::vector<network::Channel*> e_in, e_out;  // each level-2 processor's input and output
  std::vector<bool> e_behind_fan_in;
  std::vector<Port> out_ports, in_ports;  // L1's output channels, L3's input channels
  // The SDK's typed end (t800sim/channel.hpp) of each channel planned here (nullptr: none).
  t800sim::detail::ChannelSlot* typed(const network::Channel* channel) const;

  // Declares the channels (and spawns the relays, spawn_fan_out<T> and spawn_fan_in<T> of the
  // levels' precision) in the order the simulation has always made them.
  static Wiring plan(network::Machine& machine, const PipelineShape& shape,
                     const PipelineNodes& nodes, int client, Serve serve, SpawnRelay fan_out,
                     SpawnRelay fan_in);

  // Of a port's level-2 processors, those that take part in step k.
  static std::vector<int> takers(const PipelineShape& shape, const Port& port, int k);

 private:
  std::map<const network::Channel*, std::unique_ptr<t800sim::detail::ChannelSlot>> typed_;
};

}  // namespace workloads::levels
