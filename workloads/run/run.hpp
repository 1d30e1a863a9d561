// One simulation from plain inputs to a report: elaborate the machine, build the workload, run,
// account.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "network/machine.hpp"
#include "workloads/dynamics/robot_model.hpp"
#include "workloads/params.hpp"
#include "workloads/placement.hpp"
#include "workloads/run/output_table.hpp"
#include "workloads/run/result_value.hpp"

namespace workloads {

struct RunInputs {
  std::string name;
  network::Topology topology;
  network::MachineOptions options;
  std::string kind;
  Params params;
  std::shared_ptr<const dynamics::RobotModel> robot;  // for workloads with a `robot` parameter
  Placement placement;                                // the scene's [placement]
  // Where options.precision came from, said in the report: a default is stated, never silent.
  std::string precision_source = "the simulator's default";
  std::vector<network::FaultSpec> faults;  // injected into the run (network/faults.hpp)
};

// What ran, on what: every report states it, defaults included.
struct RunSetting {
  std::string kind;  // workload.kind
  t800::Precision precision = t800::Precision::real64;
  std::string precision_source;
  std::string network_source;  // a topology file, "family:tree(9)", or the scene of an inline table
  std::string
      network_family;  // the family the network is link for link (network::family_of), or ""
  std::vector<std::string> processor_types;  // distinct, in processor order
};

// What lives where in a processor's memory (t800/memory_map.hpp).
struct FootprintReport {
  int on_chip_bytes = 0;
  int reserved_bytes = 0, workspace_bytes = 0, data_bytes = 0, code_bytes = 0, library_bytes = 0;
  int external_bytes = 0;             // of those, in external memory
  std::vector<std::string> off_chip;  // the regions placed in external memory
  int external_access_cycles = 0;     // an external access, wait states included
};

struct ProcessorReport {
  std::string name;
  std::string type;  // "T800-20"
  double busy_us = 0, compute_us = 0, communicate_us = 0, idle_us = 0, utilisation = 0;
  FootprintReport memory;
};

struct LinkReport {
  std::string name;  // "P0.link1->P1.link0": the direction whose data it is
  std::int64_t bytes = 0, messages = 0;
  double busy_us = 0,
         utilisation = 0;  // time its wire carries packets (its data, the reverse acknowledges)
};

// One timeline of a trace: a processor's non-idle intervals (state compute or communicate, label
// the compute block's or empty) or a link direction's busy intervals (label the message's).
// Interval.state is a t800::ProcessorState for processors, 1 for links.
struct TraceTrack {
  enum class Kind { processor, link };
  Kind kind = Kind::processor;
  std::string name;  // as in the report's processors and links
  std::vector<t800::Interval> intervals;
};

struct RunReport {
  std::string name;
  double simulated_us = 0;
  double wall_s = 0;
  double elaboration_s = 0;  // of wall_s, the set-up before simulating (Machine::elaboration_s)
  RunSetting setting;
  network::Fidelity fidelity;   // what the run modelled and skipped
  bool run_time_checks = true;  // compiled into the generated code
  std::uint64_t events =
      0;  // SystemC delta cycles: one per batch of process activations at one time
  std::vector<ProcessorReport> processors;
  std::vector<LinkReport> links;
  std::vector<network::BlockedProcess> blocked;  // non-empty: the program deadlocked
  std::vector<std::string> wait_cycle;           // the deadlock's cycle of waits, when there is one
  network::Limit limit = network::Limit::none;   // a limit stopped the run: no workload results
                                                 // (unless Workload::reports_when_stopped)
  int stop_signal = 0;                           // Limit::interrupted: the signal
  std::vector<network::BlockedProcess> running_at_stop;  // after a limit: what had not ended
  network::TraceForecast trace_forecast{-1, 0, 0};       // with a trace, once progress gave one
  // Non-empty: the run ended but its results are not results: the workload reported a failure (a
  // solve without a usable pivot) or a number came out NaN or infinite (REAL32 overflow). Says
  // which.
  std::string failure;
  ResultValue workload;
  std::vector<OutputTable> tables;  // for the workload's output files (Workload::tables)
  std::vector<TraceTrack>
      tracks;  // only with RunInputs.options.keep_intervals (a trace is asked for)
  // What each injected fault did; processes a fault left waiting for ever are listed there, not
  // as a deadlock. A fault that took effect and was not recovered makes the run a failure.
  std::vector<network::FaultRecord> faults;

  ResultValue to_value() const;
};

// Runs one simulation. Only one per OS process (SystemC cannot be restarted). An exception a
// process's body let out is thrown as the workloads::ProcessError recorded for it.
RunReport run(const RunInputs& inputs);

class Workload;
// What run() does before simulating, and all `t800sim check` and `listing` do: the machine
// elaborated with its faults armed, the workload of `inputs` built on it (its processes placed,
// its channels joined, its code declared) and the processors' memory placed. Whatever input run()
// refuses before the first simulated event, this refuses. The workload is kept while the machine
// is used (its processes' bodies refer to it).
struct Realised {
  std::unique_ptr<network::Machine> machine;
  std::unique_ptr<Workload> workload;
};
Realised realise(const RunInputs& inputs);

}  // namespace workloads
