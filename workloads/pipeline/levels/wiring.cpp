#include "workloads/pipeline/levels/wiring.hpp"

#include <memory>
#include <string>

#include "network/channel.hpp"
#include "workloads/pipeline/relay.hpp"

namespace workloads::levels {

namespace {

bool behind(const network::Machine& machine, int relay, int level, int node) {
  return relay >= 0 && machine.link_between(relay, level) && machine.link_between(relay, node);
}

// A level-2 processor that is L1's neighbour gets a channel of its own; one behind the fan-out X
// shares X's channel; any other gets a channel the network routes.
void plan_level1_side(Wiring& w, network::Machine& machine, const PipelineShape& shape,
                      const PipelineNodes& nodes, Serve serve, SpawnRelay spawn) {
  Relay fan_out;
  fan_out.node = machine.topology().find("X");
  for (int e = 0; e < shape.m; ++e) {
    const int node = nodes.e[std::size_t(e)];
    const std::string name = "E" + std::to_string(e + 1);
    if (!machine.link_between(nodes.l1, node) && behind(machine, fan_out.node, nodes.l1, node)) {
      fan_out.served.push_back(e);
      fan_out.outputs.push_back(&machine.channel("X->" + name, fan_out.node, node));
      w.e_in.push_back(fan_out.outputs.back());
      continue;
    }
    w.e_in.push_back(&machine.channel("L1->" + name, nodes.l1, node));
    w.out_ports.push_back({w.e_in.back(), {e}});
  }
  if (fan_out.served.empty()) return;
  fan_out.inputs.push_back(&machine.channel("L1->X", nodes.l1, fan_out.node));
  w.out_ports.push_back({fan_out.inputs.back(), fan_out.served});
  fan_out.rounds = serve == Serve::once ? 1 : Relay::kUntilStopped;
  spawn(machine, shape, fan_out);
}

// The same on L3's side, with the fan-in Y.
void plan_level3_side(Wiring& w, network::Machine& machine, const PipelineShape& shape,
                      const PipelineNodes& nodes, Serve serve, SpawnRelay spawn) {
  Relay fan_in;
  fan_in.node = machine.topology().find("Y");
  for (int e = 0; e < shape.m; ++e) {
    const int node = nodes.e[std::size_t(e)];
    const std::string name = "E" + std::to_string(e + 1);
    // E1 also forwards the pivot rows, which the fan-in's schedule does not carry.
    if (e > 0 && !machine.link_between(nodes.l3, node) &&
        behind(machine, fan_in.node, nodes.l3, node)) {
      fan_in.served.push_back(e);
      fan_in.inputs.push_back(&machine.channel(name + "->Y", node, fan_in.node));
      w.e_out.push_back(fan_in.inputs.back());
      w.e_behind_fan_in.push_back(true);
      continue;
    }
    w.e_out.push_back(&machine.channel(name + "->L3", node, nodes.l3));
    w.e_behind_fan_in.push_back(false);
    w.in_ports.push_back({w.e_out.back(), {e}});
  }
  if (fan_in.served.empty()) return;
  fan_in.outputs.push_back(&machine.channel("Y->L3", fan_in.node, nodes.l3));
  w.in_ports.push_back({fan_in.outputs.back(), fan_in.served});
  fan_in.rounds = serve == Serve::once ? 1 : Relay::kUntilStopped;
  spawn(machine, shape, fan_in);
}

}  // namespace

Wiring Wiring::plan(network::Machine& machine, const PipelineShape& shape,
                    const PipelineNodes& nodes, int client, Serve serve, SpawnRelay fan_out,
                    SpawnRelay fan_in) {
  Wiring w;
  w.input = &machine.channel("system", client, nodes.l1);
  plan_level1_side(w, machine, shape, nodes, serve, fan_out);
  plan_level3_side(w, machine, shape, nodes, serve, fan_in);
  w.back = &machine.channel("L3->L1", nodes.l3, nodes.l1);
  w.to_l4 = &machine.channel("L3->L4", nodes.l3, nodes.l4);
  if (serve == Serve::until_finish) w.reply = &machine.channel("qdd", nodes.l4, client);
  // The typed ends of the levels' channels (not the relays' own).
  std::vector<network::Channel*> all{w.input, w.reply, w.back, w.to_l4};
  all.insert(all.end(), w.e_in.begin(), w.e_in.end());
  all.insert(all.end(), w.e_out.begin(), w.e_out.end());
  for (const auto* ports : {&w.out_ports, &w.in_ports})
    for (const Port& port : *ports) all.push_back(port.channel);
  for (network::Channel* channel : all) {
    if (!channel || w.typed_.count(channel)) continue;
    auto slot = std::make_unique<t800sim::detail::ChannelSlot>();
    slot->name = channel->name;
    slot->impl = channel;
    w.typed_[channel] = std::move(slot);
  }
  return w;
}

t800sim::detail::ChannelSlot* Wiring::typed(const network::Channel* channel) const {
  const auto found = typed_.find(channel);
  return found == typed_.end() ? nullptr : found->second.get();
}

std::vector<int> Wiring::takers(const PipelineShape& shape, const Port& port, int k) {
  std::vector<int> out;
  for (int e : port.served)
    if (shape.participates(k, e)) out.push_back(e);
  return out;
}

}  // namespace workloads::levels
