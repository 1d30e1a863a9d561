#include "sdk/booted.hpp"

#include <algorithm>
#include <stdexcept>

#include "network/channel.hpp"
#include "network/machine.hpp"
#include "workloads/boot/boot_session.hpp"
#include "workloads/boot/iss_node.hpp"
#include "workloads/boot/link_port.hpp"

namespace t800sim::detail {

namespace {

std::string names(const network::Topology& topology) {
  std::string text;
  for (const network::ProcessorSpec& p : topology.processors)
    text += (text.empty() ? "" : ", ") + p.name;
  return text;
}

}  // namespace

BootedProcessors::BootedProcessors(const std::string& kind, const Builder& builder,
                                   const network::Topology& topology)
    : kind_(kind), builder_(&builder) {
  for (const std::string& name : builder.declared_booted()) {
    const int node = topology.find(name);
    if (node < 0)
      throw std::invalid_argument("workload " + kind + ": booted processor " + name +
                                  " is not in the network; its processors are " + names(topology));
    if (std::find(nodes_.begin(), nodes_.end(), node) != nodes_.end())
      throw std::invalid_argument("workload " + kind + ": processor " + name +
                                  " is declared booted twice");
    nodes_.push_back(node);
  }
  if (nodes_.empty() && !builder.declared_byte_links().empty())
    throw std::invalid_argument("workload " + kind + ": byte link " +
                                builder.declared_byte_links().front()->name +
                                " leads to no booted processor: declare it with b.booted(...)");
}

BootedProcessors::~BootedProcessors() = default;
BootedProcessors::BootedProcessors(BootedProcessors&&) noexcept = default;
BootedProcessors& BootedProcessors::operator=(BootedProcessors&&) noexcept = default;

void BootedProcessors::join(network::Machine& machine, const std::vector<PlacedProcess>& placed) {
  const auto booted = [&](int node) {
    return std::find(nodes_.begin(), nodes_.end(), node) != nodes_.end();
  };
  const std::string where = "workload " + kind_ + ": ";
  for (const PlacedProcess& p : placed)
    if (booted(p.node))
      throw std::invalid_argument(where + "process " + p.name + " is placed on " +
                                  machine.node_name(p.node) +
                                  ", which is booted: it runs machine code, not processes");
  for (const ChannelSlot& c : builder_->declared_channels()) {
    if (!c.impl) continue;
    for (int node : c.impl->path)
      if (booted(node))
        throw std::invalid_argument(where + "channel " + c.name + " is routed through " +
                                    machine.node_name(node) +
                                    ", which is booted: it forwards no channel's messages");
  }
  for (const auto& link : builder_->declared_byte_links()) {
    const auto at = std::find_if(placed.begin(), placed.end(),
                                 [&](const PlacedProcess& p) { return p.name == link->process; });
    if (at == placed.end())
      throw std::invalid_argument(where + "byte link " + link->name + " is joined to process " +
                                  link->process + ", which the program does not declare");
    const int to = machine.topology().find(link->processor);
    if (to < 0 || !booted(to))
      throw std::invalid_argument(
          where + "byte link " + link->name + " leads to " + link->processor +
          ", which is not booted: declare it with b.booted(\"" + link->processor + "\")");
    const auto wire = machine.link_between(at->node, to);
    if (!wire)
      throw std::invalid_argument(where + "byte link " + link->name + ": process " + link->process +
                                  " is on " + machine.node_name(at->node) +
                                  ", which is not wired to " + link->processor +
                                  "; place it on a neighbour");
    for (const auto& other : builder_->declared_byte_links())
      if (other != link && other->link == wire->first)
        throw std::invalid_argument(where + "byte links " + other->name + " and " + link->name +
                                    " are the same link");
    link->link = wire->first;
    link->end = wire->second;
  }
}

void BootedProcessors::spawn(network::Machine& machine) {
  if (nodes_.empty()) return;
  workloads::boot::register_byte_payload();
  session_ = std::make_unique<workloads::boot::BootSession>(std::size_t(machine.processors()));
  for (int node : nodes_) {
    iss_.push_back(std::make_unique<workloads::boot::IssNode>(machine, node, *session_,
                                                              workloads::boot::IssNodeOptions{}));
    workloads::boot::IssNode* iss = iss_.back().get();
    // A daemon: the run ends when the program's own processes have, whatever the booted code does.
    machine.spawn(node, "iss", t800::Priority::low, [iss](network::Process& p) { iss->run(p); })
        .set_daemon();
  }
}

workloads::ResultValue BootedProcessors::results() const {
  workloads::ResultValue list = workloads::ResultValue::list();
  // A core still ahead of the run's end comes back to it before it reports.
  for (const auto& iss : iss_) iss->settle();
  for (std::size_t i = 0; i < nodes_.size() && session_; ++i) {
    const workloads::boot::ProcessorAccount& a = session_->account(nodes_[i]);
    workloads::ResultValue v;
    v.set("name", a.name);
    v.set("booted", a.booted);
    v.set("instructions", a.instructions);
    v.set("cycles", a.cycles);
    v.set("state", iss_[i]->state());
    if (a.halt) v.set("halt", a.halt->reason);
    list.push(std::move(v));
  }
  return list;
}

}  // namespace t800sim::detail
