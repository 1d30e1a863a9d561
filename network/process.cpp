#include "network/process.hpp"

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
  set_status("out on channel " + channel.name);
  channel.last_writer = this;
  channel_ = &channel;
  outputting_ = true;
  send(*this, channel, std::move(message));
  channel_ = nullptr;
  set_status("running");
}

t800::Message Process::in(Channel& channel) {
  set_status("in on channel " + channel.name);
  channel.last_reader = this;
  channel_ = &channel;
  outputting_ = false;
  t800::Message m = receive(*this, channel);
  channel_ = nullptr;
  set_status("running");
  return m;
}

void Process::par(const std::vector<Body>& branches) {
  std::vector<Process*> children;
  for (std::size_t i = 0; i < branches.size(); ++i) {
    compute(t800::timing::start_process_cycles(), "startp");
    const Body& body = branches[i];
    children.push_back(&machine_.spawn(node_, name() + "." + std::to_string(i),
                                       descriptor_.priority, [body](Process& child) {
                                         body(child);
                                         child.compute(t800::timing::end_process_cycles(), "endp");
                                       }));
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

void Process::mark_ended() {
  deschedule();
  ended_ = true;
  status_ = "ended";
  ended_event_.notify(sc_core::SC_ZERO_TIME);
}

}  // namespace network
