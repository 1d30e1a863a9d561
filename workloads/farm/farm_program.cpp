#include "workloads/farm/farm_program.hpp"

#include <any>
#include <cmath>
#include <stdexcept>

#include "sdk/realise.hpp"
#include "t800/payload_bytes.hpp"
#include "workloads/dynamics/evaluate.hpp"
#include "workloads/dynamics/worker_input.hpp"
#include "workloads/setting_error.hpp"

namespace workloads {

namespace {

// How the farm's messages change when a byte arrives changed (a corrupting link fault): an order's
// shared REALs (not a recovery's task list, nor a control word), each result REAL, an on-demand
// reply's index and value.
template <class S>
void register_farm_payloads() {
  using Order = t800sim::FarmOrder<std::vector<S>>;
  using Reply = t800sim::FarmReply<S>;
  constexpr std::int64_t kInt = t800sim::detail::kFarmIntBytes;
  t800::register_payload_bytes(typeid(Order),
                               [](std::any& a, std::int64_t byte, std::uint8_t mask) {
                                 auto& order = std::any_cast<Order&>(a);
                                 if (order.kind != Order::Kind::round) return false;
                                 const std::size_t field = std::size_t(byte) / sizeof(S);
                                 if (field >= order.shared.size())
                                   return false;  // the task list of a recovery's order
                                 S& v = order.shared[field];
                                 v = t800::flip_byte(v, byte % std::int64_t(sizeof(S)), mask);
                                 return true;
                               });
  t800::register_payload_bytes(
      typeid(Reply), [](std::any& a, std::int64_t byte, std::uint8_t mask) {
        auto& reply = std::any_cast<Reply&>(a);
        if (reply.task >= 0 && byte < kInt) {
          reply.task = t800::flip_byte(reply.task, byte, mask);
          return true;
        }
        const std::int64_t at = reply.task >= 0 ? byte - kInt : byte;
        const std::size_t i = std::size_t(at) / sizeof(S);
        if (i >= reply.results.size()) return false;  // the checksum word
        reply.results[i] = t800::flip_byte(reply.results[i], at % std::int64_t(sizeof(S)), mask);
        return true;
      });
}

t800sim::FarmSchedule schedule_of(const std::string& name) {
  if (name == "on-demand") return t800sim::FarmSchedule::on_demand;
  if (name == "explicit") return t800sim::FarmSchedule::explicit_allocation;
  return t800sim::FarmSchedule::static_list;
}

}  // namespace

template <class S>
FarmProgram<S>::FarmProgram(const dynamics::RobotModel& model, FarmSettings settings, int master,
                            std::vector<int> workers)
    : model_(model), settings_(std::move(settings)), master_(master), workers_(std::move(workers)) {
  if (workers_.empty())
    throw SettingError({kNetworkKey}, "the farm needs at least one worker besides the master");
  if (settings_.schedule == "explicit" && settings_.allocation.empty())
    throw SettingError({"workload.allocation", "workload.schedule"},
                       "workload.schedule = \"explicit\" needs workload.allocation");
  if (settings_.recovery && settings_.schedule == "on-demand")
    throw SettingError({"workload.recovery", "workload.schedule"},
                       "workload.recovery needs workload.schedule = \"static\" or \"explicit\"");
}

template <class S>
t800sim::FarmOptions FarmProgram<S>::options() const {
  t800sim::FarmOptions o;
  o.schedule = schedule_of(settings_.schedule);
  o.allocation = settings_.allocation;
  o.allocation_setting = "workload.allocation";
  o.in_flight = settings_.buffer;
  o.recovery = settings_.recovery;
  o.timeout_us = settings_.timeout_us;
  return o;
}

template <class S>
void FarmProgram<S>::build(network::Machine& m, const std::string& master_process) {
  work_ = farm_work(model_, settings_.variant, m.compute_model(workers_.front()), sizeof(S) == 8);
  std::vector<t800sim::FarmTask> tasks;
  subtasks_.clear();
  replay_.reset();
  rounds_ = 0;
  for (const FarmTask& t : work_.tasks) {
    tasks.push_back({t.subtask.name, t800sim::Kernel(t.work.code, t.ops, 0)});
    subtasks_.push_back(t.subtask);
  }
  farm_ = std::make_unique<Skeleton>(
      std::move(tasks),
      [this](int task, const std::vector<S>& shared) { return run_subtask(task, shared); },
      options());
  builder_ = std::make_unique<t800sim::Builder>(m.topology());
  builder_->attach(m);
  // The master is the caller's process, spawned by it: declared here so the channels reach it.
  builder_->process("master", nullptr).placed_on(m.node_name(master_));
  std::vector<std::string> worker_names;
  for (int w : workers_) worker_names.push_back(m.node_name(w));
  const std::vector<S> typical(std::size_t(dynamics::worker_input_reals(model_)), S(0));
  farm_->build(*builder_, "master", worker_names, typical);
  t800sim::detail::realise("dynamics farm", *builder_, m, {});
  m.declare_code(master_, master_process, work_.master_input.code);
  m.declare_code(master_, master_process, work_.master_assembly.code);
  register_farm_payloads<S>();
}

template <class S>
S FarmProgram<S>::run_subtask(int task, const std::vector<S>& shared) const {
  if (settings_.skip_numerics) return S(0);
  if (replay_) {
    // The first worker to get a round's message has every subtask's value replayed.
    const S value = (*replay_)(shared)[std::size_t(task)];
    if (!std::isnan(value)) return value;
  }
  return kernel_value(task, shared);
}

// The replay gives these bits, except for a NaN (from a corrupted message): NaN either way, but its
// sign and payload depend on how the compiler ordered the kernel's commutative operands.
template <class S>
S FarmProgram<S>::kernel_value(int task, const std::vector<S>& shared) const {
  dynamics::WorkerInput<S> input;
  const std::vector<S*> fields = dynamics::message_fields(model_, input);
  for (std::size_t i = 0; i < fields.size() && i < shared.size(); ++i) *fields[i] = shared[i];
  return dynamics::evaluate_subtask<S>(model_, subtasks_[std::size_t(task)], input);
}

template <class S>
FarmRound FarmProgram<S>::evaluate(t800sim::Process& p, const dynamics::JointVector& q,
                                   const dynamics::JointVector& qd,
                                   dynamics::DynamicsData<S>& data) {
  FarmRound round;
  round.start_us = p.now_us();
  p.compute(t800sim::Kernel(work_.master_input), "sin/cos");
  const std::vector<S> shared = message_for(q);
  count_evaluation();
  data.values = farm_->round(p, shared);
  const t800sim::FarmRoundTiming& timing = farm_->last_round();
  round.farm_start_us = timing.start_us;
  round.farm_end_us = timing.end_us;
  round.busy_in_farm_us = timing.busy_us;
  p.compute(t800sim::Kernel(work_.master_assembly), "assemble");
  if (!settings_.skip_numerics) dynamics::assemble(subtasks_, qd, data);
  round.end_us = p.now_us();
  return round;
}

template <class S>
void FarmProgram<S>::evaluate_on_host(const dynamics::JointVector& q,
                                      const dynamics::JointVector& qd,
                                      dynamics::DynamicsData<S>& data) {
  const std::vector<S> message = message_for(q);
  count_evaluation();
  data.values.resize(subtasks_.size());
  for (std::size_t t = 0; t < subtasks_.size(); ++t) data.values[t] = run_subtask(int(t), message);
  if (!settings_.skip_numerics) dynamics::assemble(subtasks_, qd, data);
}

// The master's message: the worker input's REALs in message order. Its size is the model's
// (worker_input_reals), whatever it holds; skipping, it holds nothing the workers read.
template <class S>
std::vector<S> FarmProgram<S>::message_for(const dynamics::JointVector& q) const {
  dynamics::WorkerInput<S> input;
  if (!settings_.skip_numerics) input = dynamics::make_worker_input<S>(model_, q);
  const std::vector<S*> fields = dynamics::message_fields(model_, input);
  std::vector<S> message(fields.size());
  for (std::size_t i = 0; i < fields.size(); ++i) message[i] = *fields[i];
  return message;
}

// Tracing the kernels costs more than a few evaluations (a scene evaluating once runs the kernels
// alone): the subtasks are replayed from the second evaluation on.
template <class S>
void FarmProgram<S>::count_evaluation() {
  if (!settings_.skip_numerics && ++rounds_ == 2) replay_.emplace(model_, subtasks_);
}

template <class S>
void FarmProgram<S>::finish(t800sim::Process& p) {
  farm_->finish(p);
}

template <class S>
std::unique_ptr<t800sim::Builder> spawn_host_and_master(network::Machine& m, int master,
                                                        const std::string& label,
                                                        const t800sim::Process::Body& body) {
  using State = t800sim::Array<S, 2 * dynamics::kJoints>;
  auto b = std::make_unique<t800sim::Builder>(m.topology());
  b->process("host", nullptr).placed_on_host();
  b->process("master", nullptr).placed_on(m.node_name(master));
  const t800sim::Chan<State> state = b->channel<State>("state", "host", "master");
  t800sim::detail::realise("farm host", *b, m, {});
  t800sim::detail::spawn("dynamics farm", m, network::Machine::kHost, "host",
                         [state, label](t800sim::Process& p) {
                           p.out(state.out(), t800sim::value_of<State>{}, label);
                         });
  t800sim::detail::spawn("dynamics farm", m, master, "master", [state, body](t800sim::Process& p) {
    p.in(state.in());
    body(p);
  });
  return b;
}

template class FarmProgram<float>;
template class FarmProgram<double>;
template std::unique_ptr<t800sim::Builder> spawn_host_and_master<float>(
    network::Machine&, int, const std::string&, const t800sim::Process::Body&);
template std::unique_ptr<t800sim::Builder> spawn_host_and_master<double>(
    network::Machine&, int, const std::string&, const t800sim::Process::Body&);

}  // namespace workloads
