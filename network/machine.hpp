// A topology elaborated into SystemC: one Transputer per processor, one Link per connection (and
// one to the host PC), the channels workloads declare, and the router processes that routed
// channels need.
//
// Use: declare channels, spawn processes, then run(). One Machine (one simulation) per OS process:
// SystemC cannot be restarted (docs/architecture.md).
#pragma once

#include <chrono>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "network/channel.hpp"
#include "network/faults.hpp"
#include "network/fidelity.hpp"
#include "network/process.hpp"
#include "network/routes.hpp"
#include "network/topology.hpp"
#include "t800/compute_model.hpp"
#include "t800/transputer.hpp"

namespace network {

class StoreAndForward;

// A trace's expected size: the intervals kept after `done` of `total` units of a workload's
// progress, scaled to all of them (a trajectory's steps record alike).
struct TraceForecast {
  std::int64_t intervals = 0, done = 0, total = 0;
};

struct MachineOptions {
  t800::LinkConfig link;  // default for connections without their own speed
  t800::Precision precision = t800::Precision::real64;
  double code_efficiency = 1.0;
  bool checked = true;          // occam's run-time checks compiled into the generated code
  bool keep_intervals = false;  // for traces
  Fidelity fidelity;
  // Limits (seconds; 0 = none): the run stops when its simulated time or the host's wall time
  // reaches one, with processes still running (Machine::limit_reached says which).
  double max_sim_s = 0, max_wall_s = 0;
  // After run(), end every process (their coroutine stacks unwound and freed) so that the Machine
  // can be destroyed. A program that exits after its one simulation (SystemC runs one per process)
  // leaves them standing and the Machine alive (workloads::run keeps it): the operating system
  // reclaims it all at once. On a 1023-worker farm the teardown took two thirds of the command's
  // wall time. A build with AddressSanitizer always tears down: its leak checker does not read the
  // coroutine stacks, so what a standing process holds would be reported lost.
  bool tear_down = true;
  // Called by workloads that know how far they are (a trajectory: steps done of all), for a
  // progress display; may be empty.
  std::function<void(std::int64_t done, std::int64_t total)> progress;
  // With keep_intervals: the intervals a trace may hold (0 = no limit). A run whose trace would
  // pass it is stopped as soon as that is known (Machine::trace_forecast), else when it does.
  std::int64_t max_trace_intervals = 0;
  // With keep_intervals: told the trace's expected size once a workload's first progress report
  // lets it be extrapolated; may be empty.
  std::function<void(const TraceForecast&)> trace_forecast;
  // Heartbeats (Machine::heartbeat) in a row at one simulated instant that make a livelock: work
  // handed back and forth without simulated time advancing. A core synchronises with SystemC at
  // least once per simulated cycle it waits, so no program that makes progress comes near.
  std::int64_t livelock_heartbeats = 1'000'000;
};

enum class Limit { none, sim_time, wall_time, trace_size, livelock, interrupted };
// The report's name of a limit: "max_sim_time", "max_wall_time", "max_trace_intervals",
// "livelock", "interrupted" ("" for none).
const char* to_string(Limit limit);

// A process that had not ended when the simulation ran out of events.
struct BlockedProcess {
  std::string process, processor, status;
  std::string waits_for;  // whom, network/wait_cycle.hpp
};

class Machine {
 public:
  static constexpr int kHost = -1;

  Machine(const Topology& topology, const MachineOptions& options);
  ~Machine();
  Machine(const Machine&) = delete;
  Machine& operator=(const Machine&) = delete;

  // Declares a channel from node `from` to node `to` (processor indices or kHost).
  Channel& channel(const std::string& name, int from, int to);
  // Places a process on a node; it starts when the simulation starts (or at once, if it is
  // running).
  Process& spawn(int node, const std::string& name, t800::Priority priority, Process::Body body);
  // Before the run: a kernel (an occam PROC) the named process on `node` will run. Its code, frame
  // and arrays are part of the processor's footprint, which decides what lives in on-chip RAM.
  void declare_code(int node, const std::string& process,
                    std::shared_ptr<const t800::codegen::Recording> kernel);

  // Runs until every process has ended or nothing can happen any more; returns the processes left
  // blocked (empty on a clean end: a deadlock otherwise).
  std::vector<BlockedProcess> run();
  // Whether run() ends the processes it leaves (MachineOptions::tear_down): if not, the Machine
  // must outlive the program's use of SystemC.
  bool tears_down() const;
  // Which limit stopped the run (MachineOptions::max_sim_s, max_wall_s, max_trace_intervals), if
  // one did, or a livelock or a stop request (network/stop_request.hpp).
  Limit limit_reached() const { return limit_; }
  // The signal whose stop request stopped the run (Limit::interrupted), else 0.
  int stop_signal() const { return stop_signal_; }
  // After a stop (limit_reached() is not none): the processes that had not ended, with what each
  // was doing.
  const std::vector<BlockedProcess>& running_at_stop() const { return running_at_stop_; }
  // Called by a process that runs long between its waits (an instruction-set simulator's core, at
  // each synchronisation with SystemC), so that a run stops even where simulated time stands
  // still: MachineOptions::livelock_heartbeats at one instant stop it as a livelock; a stop
  // request and the wall-time limit are read every 1024 heartbeats. A stopped run's processes
  // are not resumed: stopping() says so to a process that would go on (network/heartbeat.cpp).
  void heartbeat();
  bool stopping() const { return limit_ != Limit::none; }
  // The trace intervals kept so far (every processor's and link direction's).
  std::int64_t kept_intervals() const;
  // The trace's forecast, once a workload's progress has given one (intervals < 0 before).
  const TraceForecast& trace_forecast() const { return forecast_; }
  // After a deadlock, the cycle of waits among the blocked processes, if they close one
  // (network/wait_cycle.hpp).
  const std::vector<std::string>& wait_cycle() const { return wait_cycle_; }
  // What run() does first: channels routed, memory of every processor placed (footprints known).
  // Called alone, it lets a tool look at the machine without running it.
  void prepare();

  struct DeclaredCode {
    int node;
    std::string process;
    std::shared_ptr<const t800::codegen::Recording> kernel;
  };
  const std::vector<DeclaredCode>& declared_code() const { return declared_code_; }

  const Topology& topology() const { return topology_; }
  int processors() const { return int(transputers_.size()); }
  t800::Transputer& transputer(int node) { return *transputers_.at(node); }
  const t800::Transputer& transputer(int node) const { return *transputers_.at(node); }
  const t800::ComputeModel& compute_model(int node) const { return compute_models_.at(node); }
  const MachineOptions& options() const { return options_; }
  std::string node_name(int node) const;

  struct LinkInfo {
    std::string name;  // "P0.link1-P1.link0"
    int node[2];       // the two ends (kHost for the host)
    t800::Link* link;
  };
  const std::vector<LinkInfo>& links() const { return links_; }
  const std::vector<std::unique_ptr<Channel>>& channels() const { return channels_; }
  double simulated_us() const { return end_us_; }
  std::uint64_t events() const { return events_; }  // SystemC delta cycles of the run
  // Host seconds from this machine's construction to the start of the simulation: the network, the
  // workload's processes and channels, routes, memory (set by run()).
  double elaboration_s() const { return elaboration_s_; }

  // The link from node a to its neighbour b, and a's end of it (of several, the first connection
  // listed); nullopt when they are not neighbours.
  std::optional<std::pair<t800::Link*, int>> link_between(int a, int b) const;
  // The nodes a channel from -> to passes (both included; the host is kHost): a shortest path,
  // lowest link first (network/routes.hpp). Empty when there is none.
  std::vector<int> route(int from, int to) const;
  // The processes running on nodes, for reports: every record, a PAR branch's record where its
  // name was first spawned (see Process::incarnation); and in the order they were spawned.
  const std::vector<std::unique_ptr<Process>>& processes() const { return processes_; }
  std::vector<const Process*> processes_in_start_order() const;
  // As spawn, with the record of an ended process of the same name (Process::reusable).
  void spawn_again(Process& record, t800::Priority priority, Process::Body body);
  // The faults injected into this run and what each did (network/faults.hpp).
  FaultLog& faults() { return faults_; }
  const FaultLog& faults() const { return faults_; }

 private:
  void elaborate_links();
  void finalise_channels();
  void place_memory();
  void start_router(int node, int from, t800::Link& link, int end);

  Topology topology_;
  Routes routes_;
  MachineOptions options_;
  std::vector<std::unique_ptr<t800::Transputer>> transputers_;
  std::vector<t800::ComputeModel> compute_models_;
  std::vector<DeclaredCode> declared_code_;
  bool prepared_ = false;
  std::vector<std::unique_ptr<t800::Link>> link_modules_;
  std::vector<LinkInfo> links_;
  std::vector<std::unique_ptr<Channel>> channels_;
  // By channel id, the transports of the routed channels (null for the others), for the routers.
  std::vector<StoreAndForward*> routed_;
  std::vector<std::unique_ptr<Process>> processes_;
  std::uint64_t spawned_ = 0;
  void start(Process& p, Process::Body body);
  void check_thread_limit(const Process& p) const;
  std::vector<std::pair<Process*, Process::Body>> pending_;
  // SystemC threads that ran a process spawned during the run (a PAR's branch) and wait for the
  // next: creating a thread allocates and maps a stack, the most expensive thing a PAR would
  // otherwise do.
  struct PooledThread {
    Process* process = nullptr;
    Process::Body body;
    sc_core::sc_event assigned;
  };
  void pooled_thread(PooledThread& t);
  void end_threads();
  void run_with_limits();
  bool limited() const;
  bool trace_over_limit() const;
  void forecast_trace(std::int64_t done, std::int64_t total);
  TraceForecast forecast_{-1, 0, 0};
  std::vector<sc_core::sc_process_handle> handles_;  // every thread spawned for a process
  std::vector<std::unique_ptr<PooledThread>> threads_;
  std::vector<PooledThread*> idle_threads_;
  std::vector<int> ended_;
  bool finalised_ = false;
  double end_us_ = 0;
  std::uint64_t events_ = 0;
  std::chrono::steady_clock::time_point created_ = std::chrono::steady_clock::now();
  double elaboration_s_ = 0;
  Limit limit_ = Limit::none;
  int stop_signal_ = 0;
  void stop(Limit why);
  bool should_stop_now(double wall_s);
  struct Heartbeats {
    std::int64_t count = 0, at_this_instant = 0;
    double instant_s = -1;
    std::chrono::steady_clock::time_point started;
  } heartbeats_;
  std::vector<BlockedProcess> running_at_stop_;
  std::vector<std::string> wait_cycle_;
  FaultLog faults_;
};

}  // namespace network
