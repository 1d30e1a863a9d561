#include "workloads/pipeline/relay.hpp"

#include <algorithm>
#include <memory>
#include <tuple>

#include "network/channel.hpp"
#include "t800sim/process.hpp"
#include "workloads/pipeline/levels/messages.hpp"

namespace workloads {

namespace {

using network::Process;

bool more(const Relay& relay, int round) {
  return relay.rounds == Relay::kUntilStopped || round < relay.rounds;
}

std::size_t slot(const Relay& relay, int e) {
  return std::size_t(std::find(relay.served.begin(), relay.served.end(), e) - relay.served.begin());
}

// Internal channels from the input process to each output process (fan-out) or from each input
// process to the output process (fan-in), one per served processor.
std::vector<network::Channel*> internal_channels(network::Machine& machine, const Relay& relay,
                                                 const std::string& prefix) {
  std::vector<network::Channel*> channels;
  for (int e : relay.served)
    channels.push_back(
        &machine.channel(prefix + "E" + std::to_string(e + 1), relay.node, relay.node));
  return channels;
}

// The relays' ends of their channels, typed: packets of a header word and a row of REAL T
// (levels/messages.hpp), each slot shared by the processes that use it.
using Slot = std::shared_ptr<t800sim::detail::ChannelSlot>;
template <class T>
using Packet = typename levels::Messages<T>::Packet;
template <class T>
using Value = typename levels::Messages<T>::PacketValue;

Slot typed(network::Channel* channel) {
  auto slot = std::make_shared<t800sim::detail::ChannelSlot>();
  slot->name = channel->name;
  slot->impl = channel;
  return slot;
}
std::vector<Slot> typed(const std::vector<network::Channel*>& channels) {
  std::vector<Slot> slots;
  for (network::Channel* c : channels) slots.push_back(typed(c));
  return slots;
}
template <class T>
t800sim::In<Packet<T>> in(const Slot& slot) {
  return t800sim::In<Packet<T>>(slot.get());
}
template <class T>
t800sim::Out<Packet<T>> out(const Slot& slot) {
  return t800sim::Out<Packet<T>>(slot.get());
}

// A stop: the header word's flag, as occam's relay reads it.
template <class T>
bool stops(const Value<T>& message) {
  return std::get<0>(message) & levels::header::kStop;
}
// The name traces give a message (as its sender named it); nothing else reads it.
template <class T>
const char* label(const Value<T>& message, bool pivot) {
  return stops<T>(message) ? kFailLabel : pivot ? "pivot row" : "row";
}

}  // namespace

std::vector<int> relay_participants(const PipelineShape& shape, const Relay& relay, int k) {
  std::vector<int> out;
  for (int e : relay.served)
    if (shape.participates(k, e)) out.push_back(e);
  return out;
}

std::vector<std::size_t> relay_rows(const PipelineShape& shape, const std::vector<int>& served,
                                    int k) {
  std::vector<std::size_t> rows;
  for (int i = 1; i <= shape.n - 1 - k; ++i)
    if (std::find(served.begin(), served.end(), shape.owner(std::size_t(i))) != served.end())
      rows.push_back(std::size_t(i));
  return rows;
}

template <class T>
void spawn_fan_out(network::Machine& machine, const PipelineShape& shape, const Relay& relay) {
  const std::vector<Slot> inner = typed(internal_channels(machine, relay, "X->"));
  const std::vector<Slot> outputs = typed(relay.outputs);
  const Slot from_l1 = typed(relay.inputs.front());
  const auto high = t800::Priority::high;
  machine.spawn(relay.node, "fan-out in", high, [shape, relay, inner, from_l1](Process& impl) {
    t800sim::Process p(impl);
    for (int r = 0; more(relay, r); ++r)
      for (int k = 0; k < shape.n; ++k) {
        const std::vector<int> takers = relay_participants(shape, relay, k);
        if (takers.empty()) continue;
        const Value<T> pivot = p.in(in<T>(from_l1));
        for (int e : takers) p.out(out<T>(inner[slot(relay, e)]), pivot, label<T>(pivot, true));
        if (stops<T>(pivot)) return;
        for (std::size_t i : relay_rows(shape, relay.served, k)) {
          const Value<T> row = p.in(in<T>(from_l1));
          p.out(out<T>(inner[slot(relay, shape.owner(i))]), row, label<T>(row, false));
        }
      }
  });
  for (int e : relay.served) {
    machine.spawn(relay.node, "fan-out E" + std::to_string(e + 1), high,
                  [shape, relay, inner, outputs, e](Process& impl) {
                    t800sim::Process p(impl);
                    const auto from = in<T>(inner[slot(relay, e)]);
                    const auto to = out<T>(outputs[slot(relay, e)]);
                    for (int r = 0; more(relay, r); ++r)
                      for (int k = 0; k < shape.n; ++k) {
                        if (!shape.participates(k, e)) continue;
                        const Value<T> pivot = p.in(from);
                        p.out(to, pivot, label<T>(pivot, true));
                        if (stops<T>(pivot)) return;
                        for (std::size_t count = shape.rows_for(k, e).size(); count > 0; --count) {
                          const Value<T> row = p.in(from);
                          p.out(to, row, label<T>(row, false));
                        }
                      }
                  });
  }
}

template <class T>
void spawn_fan_in(network::Machine& machine, const PipelineShape& shape, const Relay& relay) {
  const std::vector<Slot> inner = typed(internal_channels(machine, relay, "Y<-"));
  const std::vector<Slot> inputs = typed(relay.inputs);
  const Slot to_l3 = typed(relay.outputs.front());
  const auto high = t800::Priority::high;
  for (int e : relay.served) {
    // A processor behind the fan-in sends its rows, or one failure message, in every step it has
    // rows.
    machine.spawn(relay.node, "fan-in E" + std::to_string(e + 1), high,
                  [shape, relay, inner, inputs, e](Process& impl) {
                    t800sim::Process p(impl);
                    const auto from = in<T>(inputs[slot(relay, e)]);
                    const auto to = out<T>(inner[slot(relay, e)]);
                    for (int r = 0; more(relay, r); ++r)
                      for (int k = 0; k < shape.n; ++k) {
                        for (std::size_t count = shape.rows_for(k, e).size(); count > 0; --count) {
                          const Value<T> m = p.in(from);
                          p.out(to, m, label<T>(m, false));
                          if (stops<T>(m)) return;
                        }
                      }
                  });
  }
  machine.spawn(relay.node, "fan-in out", high, [shape, relay, inner, to_l3](Process& impl) {
    t800sim::Process p(impl);
    for (int r = 0; more(relay, r); ++r)
      for (int k = 0; k < shape.n; ++k) {
        for (std::size_t i : relay_rows(shape, relay.served, k)) {
          const Value<T> m = p.in(in<T>(inner[slot(relay, shape.owner(i))]));
          if (!stops<T>(m)) {
            p.out(out<T>(to_l3), m, label<T>(m, false));
            continue;
          }
          // Every other processor with rows in this step sends its own failure message: take them.
          for (int e : relay.served)
            if (e != shape.owner(i) && !shape.rows_for(k, e).empty())
              p.in(in<T>(inner[slot(relay, e)]));
          return;
        }
      }
  });
}

template void spawn_fan_out<float>(network::Machine&, const PipelineShape&, const Relay&);
template void spawn_fan_out<double>(network::Machine&, const PipelineShape&, const Relay&);
template void spawn_fan_in<float>(network::Machine&, const PipelineShape&, const Relay&);
template void spawn_fan_in<double>(network::Machine&, const PipelineShape&, const Relay&);

}  // namespace workloads
