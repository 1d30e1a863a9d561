// The paper's Gaussian-elimination pipeline (Fig. 7) on a network of T800s, workload kind
// "elimination":
//   L1       augments D with the right-hand side, checks the pivot (simple interchange or partial
//            pivoting), normalises the pivot row, hands the other rows to level 2 (round-robin,
//            schedule.hpp), and gets the reduced matrix back from L3 for the next step;
//   E1..Em   level 2: eliminate the leading element of each row they get; E1 also forwards the
//            pivot row to L3;
//   L3       collects the rows, checks that all arrived and are finite (and, with the growth check,
//            how much the pivots have grown), rebuilds the reduced matrix and returns it to L1;
//            passes each pivot row (a row of U) on to L4;
//   L4       back substitution: q̈.
// With workload.overlap the steps are pipelined: L3 streams each checked row straight back and L1
// starts the next step as soon as its pivot choice has the rows it reads (pipeline_program.hpp).
// PipelineSettings::buffered runs each level-2 processor as a buffered stage (input, eliminator,
// output in PAR); docs/table6.md compares these structures against Table 6.
// The levels are PipelineProgram (pipeline_program.hpp) serving one system from the host; the
// trajectory workload runs the same program for every evaluation. Each level is a process of its
// own (levels/level1.hpp .. level4.hpp) that owns its state and talks to the others only through
// channels; the messages and their bytes are levels/messages.hpp. Every level calls the same pieces
// as the sequential solver (workloads/elimination/gauss.hpp), so q̈ is bit-identical to
// elimination::solve at the same precision and pivoting. Costs come from the pieces' counted work
// through the machine's CostModel; message sizes follow from each message's protocol
// (levels/messages.hpp): the REAL32/REAL64 rows plus one INT32 header word (row number or step, and
// a status flag).
//
// Tp: from the moment L1 has received the system from the host until L4 has q̈ (the host link's
// input time is reported apart as input_us). The topologies are configs/topologies/
// elimination-m1..m5.toml; processors are found by name: L1, E1..Em, L3, L4 (X and Y, where
// present, are link processors that run only the SDK's relays, t800sim/relay.hpp).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "t800/cost_model.hpp"
#include "workloads/elimination/gauss.hpp"
#include "workloads/elimination/system.hpp"
#include "workloads/pipeline/pipeline_program.hpp"
#include "workloads/run/workload.hpp"

namespace workloads {

class EliminationPipeline : public Workload {
 public:
  // The system is given in double and rounded to the precision (REAL32: to float).
  EliminationPipeline(const PipelineSettings& settings,
                      const elimination::LinearSystem<double>& system,
                      const network::Topology& topology);
  ~EliminationPipeline() override;

  void build(network::Machine& machine) override;
  ResultValue results(const network::Machine& machine) const override;
  const PipelineOutcome& outcome() const;
  int m() const;

  class Engine;

 private:
  std::unique_ptr<Engine> engine_;
};

// The "elimination" workload kind from a scene's parameters (registered in
// elimination_workload.cpp).
std::unique_ptr<Workload> make_elimination(const WorkloadContext& context);
// The pipeline's settings the parameters give (workload.m, precision, pivoting, ...), and the
// workload with settings of the caller's (a structure no scene parameter selects yet, e.g.
// PipelineSettings::buffered; the system still comes from the parameters).
PipelineSettings elimination_settings(const Params& params);
std::unique_ptr<Workload> make_elimination_with(const WorkloadContext& context,
                                                const PipelineSettings& settings);

// ---- Table 6 ----
// The scene to run: configs/scenes/elimination.toml (relative to the repository root).
constexpr const char* kEliminationScene = "configs/scenes/elimination.toml";
// The topology for m level-2 processors, relative to the repository root:
// "configs/topologies/elimination-m3.toml".
std::string elimination_topology(int m);
// The --set overrides that run kEliminationScene for m (1..5): the m-processor topology (relative
// to the scene file, as scenes name topologies) and workload.m.
std::vector<std::string> table6_overrides(int m);

}  // namespace workloads
