// What every level of the pipeline is given: the settings and shape (read only), the channels
// (wiring.hpp), the report it writes its observations to (report.hpp), and the record of each
// piece's T800 code that the cost model prices. No level's state: each level owns its own
// (level1.hpp .. level4.hpp).
#pragma once

#include <functional>
#include <string>
#include <utility>
#include <vector>

#include <systemc>

#include "network/machine.hpp"
#include "t800sim/kernel.hpp"
#include "t800sim/process.hpp"
#include "workloads/pipeline/checksum.hpp"
#include "workloads/pipeline/levels/messages.hpp"
#include "workloads/pipeline/levels/report.hpp"
#include "workloads/pipeline/levels/wiring.hpp"
#include "workloads/pipeline/piece_code.hpp"
#include "workloads/pipeline/pipeline_program.hpp"

namespace workloads::levels {

using network::Process;

template <class T>
struct Context {
  const PipelineSettings& settings;
  const PipelineShape& shape;
  const PipelineNodes& nodes;
  const Wiring& wiring;
  Report& report;
  PieceCode<T>& pieces;
  Serve serve;

  int n() const { return shape.n; }

  // Runs a piece of numerical work, then charges its cost to the process's CPU (after the work is
  // tallied: compute() lets the simulation switch to other processes).
  template <class Kernel, class... Inputs>
  auto run_piece(Process& p, const char* label, Kernel kernel, Named<Inputs>... inputs) const {
    auto [result, cost] = pieces.run(label, kernel, inputs...);
    p.compute(cost, label);
    return std::move(result);
  }
  template <class Kernel, class... Inputs>
  auto run_piece(t800sim::Process& p, const char* label, Kernel kernel,
                 Named<Inputs>... inputs) const {
    auto [result, cost] = pieces.run(label, kernel, inputs...);
    p.compute(t800sim::Kernel(std::move(cost)), label);
    return std::move(result);
  }

  // A packet over a channel of the wiring, through the SDK's typed channel (a t800sim::Process
  // view of p): the bytes from the protocol, `label` naming it in traces and fault reports.
  using Packet = typename Messages<T>::Packet;
  using PacketValue = typename Messages<T>::PacketValue;
  void send(Process& p, const network::Channel* c, const PacketValue& v,
            const std::string& label) const {
    t800sim::Process(p).out(t800sim::Out<Packet>(wiring.typed(c)), v, label);
  }
  PacketValue receive(Process& p, const network::Channel* c) const {
    return t800sim::Process(p).in(t800sim::In<Packet>(wiring.typed(c)));
  }

  // Recovery's messages (Messages::Checked) over the same channels, with the SDK's typed ends.
  using Checked = typename Messages<T>::Checked;
  t800sim::Out<Checked> checked_out(const network::Channel* c) const {
    return t800sim::Out<Checked>(wiring.typed(c));
  }
  t800sim::In<Checked> checked_in(const network::Channel* c) const {
    return t800sim::In<Checked>(wiring.typed(c));
  }

  // The checksum loop over a message of `count` REALs and its header, on p's processor.
  void charge_checksum(Process& p, std::size_t count) const {
    const std::int64_t words = 1 + std::int64_t(count) * std::int64_t(sizeof(T) / 4);
    p.compute(p.machine().compute_model(p.node()).process_cycles(checksum_code(words)), "checksum");
  }
  void charge_checksum(t800sim::Process& p, std::size_t count) const {
    charge_checksum(p.impl(), count);
  }
};

// occam PAR; a single branch runs in place.
template <class AnyProcess>
void par(AnyProcess& p, const std::vector<typename AnyProcess::Body>& branches) {
  if (branches.size() == 1) return branches.front()(p);
  p.par(branches);
}

// Once: one round. Until finish: rounds until the level sees the finish (or a failure) and stops.
template <class AnyProcess, class Round>
void loop(Serve serve, AnyProcess& p, Round round) {
  for (int r = 0; serve == Serve::until_finish || r < 1; ++r)
    if (!round(p)) return;
}

// Memory shared by the PAR branches of one level (L1's, L3's rows; a buffered level-2 stage's
// buffers): a branch that needs a row another branch has not stored yet gives up the CPU until it
// has. An occam programmer would put a buffer process in front; here the rows stay where they are,
// so the wait itself costs nothing.
struct Shared {
  sc_core::sc_event changed;
  template <class Ready>
  void wait_until(Process& p, Ready ready) {
    if (ready()) return;
    p.deschedule();
    while (!ready()) sc_core::wait(changed);
    p.reschedule();
  }
  template <class Ready>
  void wait_until(t800sim::Process& p, Ready ready) {
    wait_until(p.impl(), ready);
  }
  void notify() { changed.notify(sc_core::SC_ZERO_TIME); }
};

}  // namespace workloads::levels
