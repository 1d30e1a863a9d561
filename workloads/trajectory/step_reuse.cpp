#include "workloads/trajectory/step_reuse.hpp"

#include "network/process.hpp"
#include "t800sim/process.hpp"

namespace workloads {

StepReuse::StepReuse(network::Machine& machine) : machine_(machine) {
  const network::MachineOptions& options = machine.options();
  if (!options.fidelity.reuse_steps)
    off_ = "fidelity.reuse_steps = false";
  else if (options.fidelity.compute == t800::ComputeFidelity::fine)
    off_ =
        "compute fidelity 'fine' wakes every CPU at the absolute timeslice ticks: no step is "
        "translation-invariant";
}

void StepReuse::boundary(t800sim::Process& master) {
  master.impl().deschedule();
  master.impl().reschedule();
}

bool StepReuse::replay(t800sim::Process& master, const Signature& signature,
                       const std::string& refused, StepTimes& times) {
  if (!enabled()) return false;
  why_ = refused;
  if (why_.empty()) {
    why_ = network::unquiet(machine_);
    if (!why_.empty()) why_ += " at the step's start";
  }
  if (!why_.empty()) return false;
  const auto known = recorded_.find(signature);
  if (known == recorded_.end()) return false;
  // Every other process stays blocked, waiting for input, as it would be between steps.
  network::replay(master.impl(), known->second.activity);
  times = known->second.times;
  ++reused_;
  return true;
}

void StepReuse::simulating() {
  ++simulated_;
  if (enabled()) before_ = network::snapshot(machine_);
}

void StepReuse::simulated(const Signature& signature, const std::string& disagreement,
                          const StepTimes& times) {
  if (!enabled()) return;
  if (why_.empty()) why_ = invariance(disagreement);
  if (why_.empty()) {
    recorded_.emplace(signature, Recorded{network::delta_since(machine_, before_), times});
    why_ = "the first step of its signature (recorded)";
  }
  ++simulated_because_[why_];
}

void StepReuse::failed(const std::string& what) {
  if (enabled()) ++simulated_because_[why_.empty() ? what : why_];
}

// Why the step just simulated may not stand for later steps of its signature; empty when it may.
std::string StepReuse::invariance(const std::string& disagreement) const {
  if (network::clock_events(machine_) != before_.clock)
    return "a CPU's timeslice clock was involved (t800::CpuStatistics clock_dependent or "
           "timeslices changed): the step is not translation-invariant";
  const std::string busy = network::unquiet(machine_);
  if (!busy.empty()) return busy + " at the step's end";
  return disagreement;
}

// How many steps were simulated and how many reused, and why steps were simulated.
ResultValue StepReuse::report() const {
  ResultValue out;
  out.set("enabled", enabled());
  if (!enabled()) out.set("refused", off_);
  out.set("simulated_steps", simulated_);
  out.set("reused_steps", reused_);
  out.set("signatures_recorded", std::int64_t(recorded_.size()));
  ResultValue because = ResultValue::list();
  for (const auto& [why, count] : simulated_because_) {
    ResultValue row;
    row.set("reason", why);
    row.set("steps", count);
    because.push(row);
  }
  out.set("simulated_because", because);
  out.set(
      "traces",
      "a reused step's intervals are the recorded step's, shifted in time (traces keep reuse on)");
  return out;
}

}  // namespace workloads
