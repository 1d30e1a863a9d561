// What every level of the pipeline is given: the settings and shape (read only), the report it
// writes its observations to (report.hpp), and the record of each piece's T800 code that the cost
// model prices. No level's state or channels: each level owns its own (level1.hpp .. level4.hpp;
// its channels, ends.hpp, come from the pipeline skeleton). Every level is a process of the SDK
// (t800sim/process.hpp).
#pragma once

#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "t800sim/kernel.hpp"
#include "t800sim/process.hpp"
#include "t800sim/shared.hpp"
#include "workloads/pipeline/checksum.hpp"
#include "workloads/pipeline/levels/ends.hpp"
#include "workloads/pipeline/levels/messages.hpp"
#include "workloads/pipeline/levels/report.hpp"
#include "workloads/pipeline/piece_code.hpp"
#include "workloads/pipeline/pipeline_program.hpp"

namespace workloads::levels {

// Every level is a process of the SDK.
using Process = t800sim::Process;
using t800sim::Shared;

template <class T>
struct Context {
  const PipelineSettings& settings;
  const PipelineShape& shape;
  const PipelineNodes& nodes;
  Report& report;
  PieceCode<T>& pieces;
  Serve serve;

  int n() const { return shape.n; }

  // Runs a piece of numerical work, then charges its cost to the process's CPU (after the work is
  // tallied: compute() lets the simulation switch to other processes).
  template <class Kernel, class... Inputs>
  auto run_piece(Process& p, const char* label, Kernel kernel, Named<Inputs>... inputs) const {
    auto [result, cost] = pieces.run(label, kernel, inputs...);
    p.compute(t800sim::Kernel(std::move(cost)), label);
    return std::move(result);
  }

  // A packet over a level's channel, through its typed end: the bytes from the protocol, `label`
  // naming it in traces and fault reports.
  using Packet = typename Messages<T>::Packet;
  using PacketValue = typename Messages<T>::PacketValue;
  static void send(Process& p, Slot c, PacketValue v, const std::string& label) {
    p.out(t800sim::Out<Packet>(c), std::move(v), label);
  }
  static PacketValue receive(Process& p, Slot c) { return p.in(t800sim::In<Packet>(c)); }

  // Recovery's messages (Messages::Checked) over the same boundaries.
  using Checked = typename Messages<T>::Checked;
  static t800sim::Out<Checked> checked_out(Slot c) { return t800sim::Out<Checked>(c); }
  static t800sim::In<Checked> checked_in(Slot c) { return t800sim::In<Checked>(c); }

  // The checksum loop over a message of `count` REALs and its header, on p's processor.
  void charge_checksum(Process& p, std::size_t count) const {
    const std::int64_t words = 1 + std::int64_t(count) * std::int64_t(sizeof(T) / 4);
    p.compute(p.cycles(checksum_code(words)), "checksum");
  }

  // Processor names for a fault report's path: level 1, level-2 processor e (0-based), level 3.
  static std::vector<std::string> path(bool from_l1, int e, bool to_l3) {
    std::vector<std::string> names;
    if (from_l1) names.push_back(PipelineNodes::kLevel1);
    names.push_back(PipelineNodes::level2_name(e));
    if (to_l3) names.push_back(PipelineNodes::kLevel3);
    return names;
  }
};

// occam PAR; a single branch runs in place.
inline void par(Process& p, const std::vector<Process::Body>& branches) {
  if (branches.size() == 1) return branches.front()(p);
  p.par(branches);
}

// A level's rounds (StageEnds::rounds: one system, or until the level sees the finish or a
// failure, kUntilStop); a round returns false when the level stops.
template <class Round>
void loop(int rounds, Process& p, Round round) {
  for (int r = 0; rounds == t800sim::kUntilStop || r < rounds; ++r)
    if (!round(p)) return;
}

}  // namespace workloads::levels
