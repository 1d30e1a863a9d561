#include "workloads/pipeline/relay.hpp"

#include <algorithm>
#include <memory>

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

void spawn_fan_out(network::Machine& machine, const PipelineShape& shape, const Relay& relay) {
  const auto inner = internal_channels(machine, relay, "X->");
  const auto high = t800::Priority::high;
  machine.spawn(relay.node, "fan-out in", high, [shape, relay, inner](Process& p) {
    for (int r = 0; more(relay, r); ++r)
      for (int k = 0; k < shape.n; ++k) {
        const std::vector<int> takers = relay_participants(shape, relay, k);
        if (takers.empty()) continue;
        const t800::Message pivot = p.in(*relay.inputs.front());
        for (int e : takers) p.out(*inner[slot(relay, e)], pivot);
        if (relay.stops(pivot.payload)) return;
        for (std::size_t i : relay_rows(shape, relay.served, k))
          p.out(*inner[slot(relay, shape.owner(i))], p.in(*relay.inputs.front()));
      }
  });
  for (int e : relay.served) {
    machine.spawn(relay.node, "fan-out E" + std::to_string(e + 1), high,
                  [shape, relay, inner, e](Process& p) {
                    network::Channel& in = *inner[slot(relay, e)];
                    network::Channel& out = *relay.outputs[slot(relay, e)];
                    for (int r = 0; more(relay, r); ++r)
                      for (int k = 0; k < shape.n; ++k) {
                        if (!shape.participates(k, e)) continue;
                        t800::Message pivot = p.in(in);
                        const bool stop = relay.stops(pivot.payload);
                        p.out(out, std::move(pivot));
                        if (stop) return;
                        for (std::size_t count = shape.rows_for(k, e).size(); count > 0; --count)
                          p.out(out, p.in(in));
                      }
                  });
  }
}

void spawn_fan_in(network::Machine& machine, const PipelineShape& shape, const Relay& relay) {
  const auto inner = internal_channels(machine, relay, "Y<-");
  const auto high = t800::Priority::high;
  for (int e : relay.served) {
    // A processor behind the fan-in sends its rows, or one failure message, in every step it has
    // rows.
    machine.spawn(relay.node, "fan-in E" + std::to_string(e + 1), high,
                  [shape, relay, inner, e](Process& p) {
                    network::Channel& in = *relay.inputs[slot(relay, e)];
                    network::Channel& out = *inner[slot(relay, e)];
                    for (int r = 0; more(relay, r); ++r)
                      for (int k = 0; k < shape.n; ++k) {
                        for (std::size_t count = shape.rows_for(k, e).size(); count > 0; --count) {
                          t800::Message m = p.in(in);
                          const bool stop = relay.stops(m.payload);
                          p.out(out, std::move(m));
                          if (stop) return;
                        }
                      }
                  });
  }
  machine.spawn(relay.node, "fan-in out", high, [shape, relay, inner](Process& p) {
    for (int r = 0; more(relay, r); ++r)
      for (int k = 0; k < shape.n; ++k) {
        for (std::size_t i : relay_rows(shape, relay.served, k)) {
          t800::Message m = p.in(*inner[slot(relay, shape.owner(i))]);
          if (!relay.stops(m.payload)) {
            p.out(*relay.outputs.front(), std::move(m));
            continue;
          }
          // Every other processor with rows in this step sends its own failure message: take them.
          for (int e : relay.served)
            if (e != shape.owner(i) && !shape.rows_for(k, e).empty()) p.in(*inner[slot(relay, e)]);
          return;
        }
      }
  });
}

}  // namespace workloads
