// Link processors for level 2 processors that L1 or L3 cannot reach directly (four links per T800):
// a fan-out X between L1 and some level-2 processors, a fan-in Y between them and L3. They run
// what an occam programmer of 1990 wrote for this (the T800 has no hardware routing): an input
// process and one output process per link, joined by internal channels, so that X takes the next
// row from L1 while it is still sending the previous one on. X receives each step's pivot row once
// and copies it to every processor it serves. They know the pipeline's schedule (schedule.hpp),
// so no routing header is needed; they stop on a stop message (its header word's status flag says
// failure or finish; which also ends a pipeline that serves until finish, pipeline_program.hpp).
#pragma once

#include <string>
#include <vector>

#include "network/machine.hpp"
#include "workloads/pipeline/schedule.hpp"

namespace workloads {

// The trace label of a stop message (a bare header word); control flow reads the value, not this.
constexpr const char* kFailLabel = "fail";

struct Relay {
  static constexpr int kUntilStopped = -1;
  int node = -1;
  int rounds = 1;           // systems it carries; kUntilStopped: until a stop (fail) message
  std::vector<int> served;  // level-2 processors (0-based) behind this relay, ascending
  // Fan-out: one input (from L1) and one output per served processor. Fan-in: the reverse.
  std::vector<network::Channel*> inputs, outputs;
};

// Processes of the SDK (t800sim::Process) forwarding packets of REAL T rows (levels/messages.hpp)
// over typed channels; a stop (the header word's flag) they pass on and end.
template <class T>
void spawn_fan_out(network::Machine& machine, const PipelineShape& shape, const Relay& relay);
template <class T>
void spawn_fan_in(network::Machine& machine, const PipelineShape& shape, const Relay& relay);
using SpawnRelay = void (*)(network::Machine&, const PipelineShape&, const Relay&);

// The served processors of a relay that take part in step k, and the rows (in order) it carries.
std::vector<int> relay_participants(const PipelineShape& shape, const Relay& relay, int k);
std::vector<std::size_t> relay_rows(const PipelineShape& shape, const std::vector<int>& served,
                                    int k);

}  // namespace workloads
