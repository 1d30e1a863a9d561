#include "network/process.hpp"

#include <cmath>

#include "network/channel.hpp"
#include "network/machine.hpp"
#include "t800/timing_table.hpp"

namespace network {

Process::Process(Machine& machine, int node, std::string name, t800::Priority priority)
    : machine_(machine), node_(node) {
  descriptor_.name = std::move(name);
  descriptor_.priority = priority;
}

bool Process::on_host() const {
  return node_ == Machine::kHost;
}

void Process::compute(std::int64_t cycles, const std::string& label) {
  if (on_host() || cycles <= 0) return;  // the host PC is not what is being measured
  machine_.transputer(node_).cpu().execute(descriptor_, cycles, t800::ProcessorState::compute,
                                           label);
}

void Process::compute(const t800::OperationMix& mix, const std::string& label) {
  compute(t800::ComputeWork{mix, nullptr}, label);
}

void Process::compute(const t800::ComputeWork& work, const std::string& label) {
  if (on_host()) return;
  compute(machine_.compute_model(node_).cycles(work), label);
}

void Process::communicate(std::int64_t bytes, bool copies) {
  if (on_host()) return;
  const std::int64_t cycles = machine_.compute_model(node_).communication_cycles(bytes, copies);
  machine_.transputer(node_).cpu().execute(descriptor_, cycles, t800::ProcessorState::communicate,
                                           {});
}

void Process::deschedule() {
  if (!on_host()) machine_.transputer(node_).cpu().deschedule(descriptor_);
}

void Process::reschedule() {
  if (!on_host()) machine_.transputer(node_).cpu().acquire(descriptor_);
}

void Process::out(Channel& channel, t800::Message message) {
  set_status("out on channel", &channel);
  channel.last_writer.set(*this);
  channel_ = &channel;
  outputting_ = true;
  channel.transport->send(*this, std::move(message));
  channel_ = nullptr;
  set_status("running");
}

t800::Message Process::in(Channel& channel) {
  set_status("in on channel", &channel);
  channel.last_reader.set(*this);
  channel_ = &channel;
  outputting_ = false;
  t800::Message m = channel.transport->receive(*this);
  channel_ = nullptr;
  set_status("running");
  return m;
}

// Branch i of a PAR, named after it: the record of the previous PAR's branch i where it can start
// again (Process::reusable; always, but for a preemption's interrupt still due), else a new one.
// Its body is referred to, not copied: PAR returns only when every branch has ended.
Process& Process::start_branch(std::size_t i, t800::Priority priority, const Body& body) {
  Body run = [&body](Process& child) {
    body(child);
    child.compute(t800::timing::end_process_cycles(), "endp");
  };
  if (i < branch_records_.size() && branch_records_[i]->reusable()) {
    machine_.spawn_again(*branch_records_[i], priority, std::move(run));
    return *branch_records_[i];
  }
  Process& child =
      machine_.spawn(node_, name() + "." + std::to_string(i), priority, std::move(run));
  if (i < branch_records_.size())
    branch_records_[i] = &child;
  else
    branch_records_.push_back(&child);
  return child;
}

void Process::par(const std::vector<Body>& branches) {
  std::vector<Process*> children;
  for (std::size_t i = 0; i < branches.size(); ++i) {
    compute(t800::timing::start_process_cycles(), "startp");
    children.push_back(&start_branch(i, descriptor_.priority, branches[i]));
  }
  set_status("waiting for its parallel branches");
  branches_ = children;
  deschedule();
  for (Process* child : children)
    while (!child->ended()) sc_core::wait(child->ended_event());
  branches_.clear();
  reschedule();
  set_status("running");
}

void Process::pri_par(const Body& high, const std::vector<Body>& low) {
  std::vector<Process*> children;
  auto start = [&](const Body& body, t800::Priority priority, std::size_t i) {
    compute(t800::timing::start_process_cycles(), "startp");
    children.push_back(&start_branch(i, priority, body));
  };
  start(high, t800::Priority::high, 0);
  for (std::size_t i = 0; i < low.size(); ++i) start(low[i], t800::Priority::low, i + 1);
  set_status("waiting for its parallel branches");
  deschedule();
  for (Process* child : children)
    while (!child->ended()) sc_core::wait(child->ended_event());
  reschedule();
  set_status("running");
}

double Process::tick_us() const {
  return descriptor_.priority == t800::Priority::high ? 1.0 : 64.0;
}

std::int64_t Process::clock() const {
  return std::int64_t(std::floor(now_us() / tick_us() + 1e-9));
}

sc_core::sc_time Process::time_after(std::int64_t t) const {
  return sc_core::sc_time(double(t + 1) * tick_us(), sc_core::SC_US);
}

void Process::wait_after(std::int64_t t) {
  const bool future = clock() <= t;
  run_instructions({{t800::isa::Op::ldl, 1, 0, false, {t800::isa::Region::workspace, -1}, "time"},
                    {t800::isa::Op::tin,
                     0,
                     future,
                     false,
                     {t800::isa::Region::workspace, -1},
                     "TIMER ? AFTER"}});
  if (!future) return;
  set_status("waiting for its timer");
  deschedule();
  sc_core::wait(time_after(t) - t800::sim_now());
  reschedule();
  set_status("running");
}

void Process::run_instructions(const t800::isa::Sequence& code) {
  if (on_host()) return;
  const std::int64_t cycles = machine_.compute_model(node_).process_cycles(code);
  machine_.transputer(node_).cpu().execute(descriptor_, cycles, t800::ProcessorState::communicate,
                                           {});
}

void Process::stop(const std::string& why) {
  set_status_text("stopped by a run-time error: " + why);
  deschedule();
  sc_core::sc_event never;
  for (;;) sc_core::wait(never);
}

std::string Process::status() const {
  if (!doing_) return status_text_;
  return about_ ? std::string(doing_) + " " + about_->name : std::string(doing_);
}

void Process::mark_ended() {
  deschedule();
  ended_ = true;
  set_status("ended");
  ended_event_.notify_delta();
  ended_delta_ = sc_core::sc_delta_count();
}

bool Process::reusable() const {
  return ended_ && sc_core::sc_delta_count() > ended_delta_ &&
         t800::sim_now() >= descriptor_.interrupt_due;
}

void Process::begin_again(t800::Priority priority, std::uint64_t spawned) {
  ++incarnation_;
  spawned_ = spawned;
  descriptor_.priority = priority;
  descriptor_.dispatched_at = sc_core::SC_ZERO_TIME;
  doing_ = "not started";
  about_ = nullptr;
  status_text_.clear();
  ended_ = false;
  daemon_ = false;
  channel_ = nullptr;
  outputting_ = false;
  branches_.clear();
}

}  // namespace network
