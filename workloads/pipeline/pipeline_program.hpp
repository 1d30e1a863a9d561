// The Fig. 7 Gaussian-elimination pipeline as a program that serves solves, like FarmProgram: a
// client process (the host for Table 6, the farm's master in a trajectory) sends one system at a
// time to L1 and, when the program serves until finish(), gets q̈ back from L4; the levels loop
// over rounds until the client calls finish(). The levels, their channels and the relays are
// described in pipeline.hpp; each level is a process of its own in levels/, a stage of the SDK's
// pipeline skeleton (t800sim/pipeline.hpp).
//
// A failed round (no usable pivot, a non-finite value) stops every level, as in the one-shot
// pipeline: the client gets the failure and must not send again (finish() is then a no-op).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "network/machine.hpp"
#include "workloads/elimination/gauss.hpp"
#include "workloads/elimination/system.hpp"
#include "workloads/pipeline/schedule.hpp"

namespace workloads {

struct PipelineSettings {
  int m = 0;  // level-2 processors used, E1..Em; 0 = every E<i> the topology has
  t800::Precision precision = t800::Precision::real64;
  elimination::PivotRule rule;
  // Pipelined steps (Serve::once only): L3 streams each eliminated row back to L1 as it arrives,
  // and L1 starts step k + 1 as soon as it has the rows its pivot choice needs. false = strict
  // steps: L3 returns the whole reduced matrix after checking it.
  bool overlap = false;
  // Buffered level 2: each level-2 processor runs an input process, the eliminator and an output
  // process in PAR, joined by one-row buffers (the classic occam buffered stage), so the next row
  // comes in and the previous one goes out while a row is eliminated. false = one process that
  // takes a row, eliminates it and sends it on before it takes the next.
  bool buffered = false;
  // Recovery (strict, unbuffered steps, every level-2 processor L1's and L3's neighbour): every
  // message out of L1 and level 2 carries a checksum; level 2 marks a row whose input was damaged,
  // level 3 waits for a step's rows in an ALT with a timer guard, and asks L1 to resend what is
  // missing or damaged through another level-2 processor. L1's outputs give up at a deadline
  // (OutputOrFail), and a level-2 processor that failed is not used again.
  bool recovery = false;
  double timeout_us = 1000;  // how long L1 and L3 wait for the next message of a step
};

// What one round produced, as the levels saw it.
struct PipelineOutcome {
  elimination::Status status = elimination::Status::ok;
  int failed_step = -1;
  std::string failure;          // which level saw what, for the report; empty when solved
  std::vector<double> qdd;      // the solution, exactly as computed (float widens exactly)
  std::vector<int> pivot_rows;  // original row of each step's pivot
  int interchanges = 0;
  double growth = 1;
  double input_start_us = 0, start_us = 0, end_us = 0;
  double returned_us = 0;    // the client has q̈ (serve = until_finish only)
  double eliminated_us = 0;  // L4 has every row of U (back substitution starts)
  // Level 2's window: the first pivot row reaching a level-2 processor, the last row leaving one.
  double level2_first_us = -1, level2_last_us = 0;
  std::vector<double> step_start_us;  // when L1 began each step's pivot search
  double tp_us() const { return end_us - start_us; }
};

// The processors of the pipeline, found by name: L1, E1..Em, L3, L4.
struct PipelineNodes {
  int l1 = -1, l3 = -1, l4 = -1;
  std::vector<int> e;

  static constexpr const char* kLevel1 = "L1";
  static constexpr const char* kLevel3 = "L3";
  static constexpr const char* kLevel4 = "L4";
  static std::string level2_name(int e) { return "E" + std::to_string(e + 1); }  // 0-based e
};
// The number of consecutive level-2 processors E1, E2, ... the topology has.
int level2_count(const network::Topology& topology);
// Throws std::invalid_argument naming the missing processor.
PipelineNodes find_pipeline_nodes(const network::Topology& topology, int m);

// once: one system, q̈ stays on L4 (Table 6: nothing moves after Tp); until_finish: q̈ goes back
// to the client every round, and the levels loop until finish().
enum class Serve { once, until_finish };

template <class S>
class PipelineProgram {
 public:
  PipelineProgram(const PipelineSettings& settings, const PipelineNodes& nodes, int n);
  ~PipelineProgram();
  PipelineProgram(const PipelineProgram&) = delete;
  PipelineProgram& operator=(const PipelineProgram&) = delete;

  // Before the run: declares the four levels, the relays and their channels (client -> L1, and
  // L4 -> client when serving until finish) through the SDK's pipeline skeleton, on a Builder of
  // its own, and makes them real on the machine. `client` is the caller's process's processor
  // (network::Machine::kHost: the host), spawned by the caller.
  void build(network::Machine& machine, int client, Serve serve);
  // From the client's process: sends the system to L1 (its REAL values) and starts a round.
  void send(network::Process& client, const elimination::LinearSystem<S>& system);
  // send(), then waits for q̈ from L4 (Serve::until_finish).
  const PipelineOutcome& solve(network::Process& client,
                               const elimination::LinearSystem<S>& system);
  // From the client's process after the last solve: every level ends.
  void finish(network::Process& client);

  const PipelineOutcome& outcome() const;
  const PipelineSettings& settings() const;
  const PipelineShape& shape() const;

  class Levels;

 private:
  std::unique_ptr<Levels> levels_;  // the level processes, their channels, the report
};

extern template class PipelineProgram<float>;
extern template class PipelineProgram<double>;

}  // namespace workloads
