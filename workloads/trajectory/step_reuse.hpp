// Step reuse (fidelity.reuse_steps): a trajectory step whose every data-dependent branch matches
// one already simulated -- the same signature -- and that starts on a quiet machine takes the
// recorded step's time and work instead of being simulated again. A step is recorded only when it
// was proven translation-invariant: no CPU's timeslice clock was involved, the machine was quiet at
// its end, and the simulated numbers agreed with the sequential numerics that gave its signature.
//
// The workload owns the signature (what fixes its step's costs) and the agreement check; this class
// owns the recordings, the replay and the report of why each step was simulated. The workload's
// master is an SDK process (t800sim/process.hpp); replaying is what only the simulator may do --
// let a recorded step's time pass without simulating it -- and this class alone reaches it, through
// network::replay (network/activity_delta.hpp).
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "network/activity_delta.hpp"
#include "workloads/run/result_value.hpp"
#include "workloads/trajectory/step_times.hpp"

namespace t800sim {
class Process;
}

namespace workloads {

class StepReuse {
 public:
  using Signature = std::vector<int>;

  // Reuse is off for the whole run when fidelity.reuse_steps is false, or when compute fidelity
  // 'fine' ties every step to the absolute timeslice ticks.
  explicit StepReuse(network::Machine& machine);
  bool enabled() const { return off_.empty(); }

  // A step boundary, reused or not: the master takes the CPU afresh (a zero-time deschedule and
  // reschedule, so its timeslice starts here whatever came before), and a reused step leaves the
  // scheduler as a simulated one does.
  static void boundary(t800sim::Process& master);
  // A step about to run. `refused` is the workload's reason to simulate it whatever was recorded
  // (empty: none). True when a recorded step was replayed into `times`: the master let its
  // duration pass and its work was credited to every processor and link.
  bool replay(t800sim::Process& master, const Signature& signature, const std::string& refused,
              StepTimes& times);
  // The step is simulated now (after replay() returned false, or with reuse off).
  void simulating();
  // The simulated step ended; `disagreement` is the workload's reason the simulated numbers may not
  // stand for the signature (empty: they agree).
  void simulated(const Signature& signature, const std::string& disagreement,
                 const StepTimes& times);
  // The simulated step ended in a failure (`what` failed).
  void failed(const std::string& what);

  ResultValue report() const;

 private:
  struct Recorded {
    network::ActivityDelta activity;
    StepTimes times;
  };
  std::string invariance(const std::string& disagreement) const;

  network::Machine& machine_;
  std::string off_;  // why reuse is off for the whole run (empty: on)
  std::map<Signature, Recorded> recorded_;
  std::string why_;  // why the step being simulated is simulated (empty: not known yet)
  network::ActivitySnapshot before_;
  std::int64_t simulated_ = 0, reused_ = 0;
  std::map<std::string, std::int64_t> simulated_because_;
};

}  // namespace workloads
