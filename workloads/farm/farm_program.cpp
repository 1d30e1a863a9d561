#include "workloads/farm/farm_program.hpp"

#include <algorithm>
#include <optional>
#include <stdexcept>

#include "workloads/setting_error.hpp"

#include "t800/link_timing.hpp"
#include "t800/timing_table.hpp"
#include "workloads/dynamics/evaluate.hpp"

namespace workloads {

namespace {
constexpr std::int64_t kIntBytes = 4;  // a subtask index or a marker: one occam INT
constexpr int kEndOfRound = -1;
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
}

template <class S>
std::vector<dynamics::Subtask> FarmProgram<S>::subtasks() const {
  std::vector<dynamics::Subtask> s;
  for (const FarmTask& t : work_.tasks) s.push_back(t.subtask);
  return s;
}

template <class S>
void FarmProgram<S>::build(network::Machine& m, const std::string& master_process) {
  work_ = farm_work(model_, settings_.variant, m.compute_model(workers_.front()), sizeof(S) == 8);
  if (settings_.schedule != "on-demand") allocation_ = allocate(m);
  for (int w : workers_) {
    to_.push_back(&m.channel("to " + m.node_name(w), master_, w));
    from_.push_back(&m.channel("from " + m.node_name(w), w, master_));
    queue_.push_back(&m.channel("queue " + m.node_name(w), w, w));
  }
  for (std::size_t w = 0; w < workers_.size(); ++w) {
    if (!has_work(w)) continue;
    m.spawn(workers_[w], "worker", t800::Priority::low,
            [this, w](network::Process& p) { worker(p, w); });
    // The worker's code: its subtasks' PROCs (on demand it may get any of them).
    if (settings_.schedule == "on-demand")
      for (const FarmTask& t : work_.tasks) m.declare_code(workers_[w], "worker", t.work.code);
    else
      for (int t : allocation_[w])
        m.declare_code(workers_[w], "worker", work_.tasks[std::size_t(t)].work.code);
  }
  m.declare_code(master_, master_process, work_.master_input.code);
  m.declare_code(master_, master_process, work_.master_assembly.code);
}

// The list scheduler's view of each worker: its distance from the master in hops sets when its
// input arrives and what each returned value costs (schedule.hpp).
template <class S>
Allocation FarmProgram<S>::allocate(const network::Machine& m) const {
  std::vector<std::string> task_names, worker_names;
  for (const FarmTask& t : work_.tasks) task_names.push_back(t.subtask.name);
  for (int w : workers_) worker_names.push_back(m.node_name(w));
  if (settings_.schedule == "explicit")
    return parse_allocation(settings_.allocation, task_names, worker_names);

  const double cycle_ns = m.compute_model(master_).cycle_ns();
  const t800::LinkTiming link(m.options().link);
  const double hop_overhead =
      double(m.compute_model(master_).communication_cycles(0, false)) * cycle_ns;
  const std::int64_t input_bytes = dynamics::worker_input_reals(model_) * kReal;
  std::vector<double> task_ns;
  for (const FarmTask& t : work_.tasks) task_ns.push_back(double(t.cycles) * cycle_ns);
  std::vector<WorkerCosts> costs;
  for (int w : workers_) {
    const double hops = double(m.route(master_, w).size() - 1);
    costs.push_back({hops * (link.arrival_ns(input_bytes) + hop_overhead),
                     hops * kReal * link.byte_period_ns,
                     hops * (link.data_packet_ns + hop_overhead)});
  }
  return schedule_static(task_ns, costs);
}

// A static schedule may leave a worker without subtasks (more workers than subtasks): it is not
// started.
template <class S>
bool FarmProgram<S>::has_work(std::size_t w) const {
  return settings_.schedule == "on-demand" || !allocation_[w].empty();
}

template <class S>
std::vector<double> FarmProgram<S>::workers_busy_now(network::Machine& m) const {
  std::vector<double> busy;
  for (int w : workers_) busy.push_back(m.transputer(w).activity().busy_us_now());
  return busy;
}

template <class S>
FarmRound FarmProgram<S>::evaluate(network::Process& p, const dynamics::JointVector& q,
                                   const dynamics::JointVector& qd,
                                   dynamics::DynamicsData<S>& data) {
  FarmRound round;
  round.start_us = p.now_us();
  p.compute(work_.master_input, "sin/cos");
  // The message's size is the model's (worker_input_reals), whatever it holds; skipping, it holds
  // nothing the workers read.
  const std::optional<dynamics::WorkerInput<S>> input =
      settings_.skip_numerics ? dynamics::WorkerInput<S>{}
                              : dynamics::make_worker_input<S>(model_, q);
  data.values.assign(work_.tasks.size(), S(0));
  done_by_.assign(workers_.size(), {});
  next_ = 0;
  const std::int64_t input_bytes = dynamics::worker_input_reals(model_) * kReal;
  std::vector<network::Process::Body> talk;
  for (std::size_t w = 0; w < workers_.size(); ++w) {
    if (!has_work(w)) continue;
    talk.push_back([this, w, input_bytes, &input, &data](network::Process& branch) {
      branch.out(*to_[w], {input_bytes, input, "input"});
      if (settings_.schedule == "on-demand")
        hand_out(branch, w, data);
      else
        collect(branch, w, data);
    });
  }
  round.farm_start_us = p.now_us();
  const std::vector<double> busy_before = workers_busy_now(p.machine());
  p.par(talk);
  round.farm_end_us = p.now_us();
  const std::vector<double> busy_after = workers_busy_now(p.machine());
  for (std::size_t w = 0; w < workers_.size(); ++w)
    round.busy_in_farm_us.push_back(busy_after[w] - busy_before[w]);
  p.compute(work_.master_assembly, "assemble");
  if (!settings_.skip_numerics) dynamics::assemble(subtasks(), qd, data);
  round.end_us = p.now_us();
  return round;
}

template <class S>
void FarmProgram<S>::finish(network::Process& p) {
  std::vector<network::Process::Body> stop;
  for (std::size_t w = 0; w < workers_.size(); ++w)
    if (has_work(w))
      stop.push_back([this, w](network::Process& branch) {
        branch.out(*to_[w], {kIntBytes, std::optional<dynamics::WorkerInput<S>>{}, "finish"});
      });
  p.par(stop);
}

// Static: one message back from each worker with its values, in its allocation's order.
template <class S>
void FarmProgram<S>::collect(network::Process& p, std::size_t w, dynamics::DynamicsData<S>& data) {
  const auto values = std::any_cast<std::vector<S>>(p.in(*from_[w]).payload);
  for (std::size_t i = 0; i < values.size(); ++i) data.values[allocation_[w][i]] = values[i];
  done_by_[w] = allocation_[w];
}

// On demand: each worker holds up to `buffer` subtasks; every result returned earns it the next
// one, longest first. When none is left it gets an end-of-round marker, and the master waits for
// what it still has out.
template <class S>
void FarmProgram<S>::hand_out(network::Process& p, std::size_t w, dynamics::DynamicsData<S>& data) {
  int outstanding = 0;
  bool ended = false;
  auto give = [&] {
    if (next_ < int(work_.tasks.size())) {
      p.out(*to_[w], {kIntBytes, dispatch_order()[next_++], "subtask"});
      ++outstanding;
    } else if (!ended) {
      p.out(*to_[w], {kIntBytes, kEndOfRound, "end of round"});
      ended = true;
    }
  };
  for (int i = 0; i < settings_.buffer; ++i) give();
  while (outstanding > 0) {
    const auto result = std::any_cast<std::pair<int, S>>(p.in(*from_[w]).payload);
    data.values[result.first] = result.second;
    done_by_[w].push_back(result.first);
    --outstanding;
    give();
  }
  if (!ended) give();
}

template <class S>
void FarmProgram<S>::worker(network::Process& p, std::size_t w) {
  for (;;) {
    const auto input =
        std::any_cast<std::optional<dynamics::WorkerInput<S>>>(p.in(*to_[w]).payload);
    if (!input) return;
    if (settings_.schedule == "on-demand")
      on_demand_round(p, w, *input);
    else
      static_round(p, w, *input);
  }
}

template <class S>
void FarmProgram<S>::static_round(network::Process& p, std::size_t w,
                                  const dynamics::WorkerInput<S>& input) {
  std::vector<S> values;
  for (int t : allocation_[w]) values.push_back(run_task(p, t, input));
  p.out(*from_[w], {std::int64_t(values.size()) * kReal, values, "results"});
}

// A feeder takes assignments off the link while a computer works through them, so the next subtask
// is already on the worker when the current one ends (the buffering that keeps links busy).
template <class S>
void FarmProgram<S>::on_demand_round(network::Process& p, std::size_t w,
                                     const dynamics::WorkerInput<S>& input) {
  network::Channel& queue = *queue_[w];
  p.par({[this, w, &queue](network::Process& feeder) {
           for (;;) {
             const int task = std::any_cast<int>(feeder.in(*to_[w]).payload);
             feeder.out(queue, {kIntBytes, task, "queued"});
             if (task == kEndOfRound) return;
           }
         },
         [this, w, &queue, &input](network::Process& computer) {
           for (;;) {
             const int task = std::any_cast<int>(computer.in(queue).payload);
             if (task == kEndOfRound) return;
             const S value = run_task(computer, task, input);
             computer.out(*from_[w], {kIntBytes + kReal, std::make_pair(task, value), "result"});
           }
         }});
}

template <class S>
S FarmProgram<S>::run_task(network::Process& p, int t, const dynamics::WorkerInput<S>& input) {
  const FarmTask& task = work_.tasks[t];
  p.compute(task.work, task.subtask.name);  // the cost known at build time, not by evaluating
  if (settings_.skip_numerics) return S(0);
  return dynamics::evaluate_subtask<S>(model_, task.subtask, input);
}

template <class S>
const std::vector<int>& FarmProgram<S>::dispatch_order() {
  if (order_.empty()) {
    for (int i = 0; i < int(work_.tasks.size()); ++i) order_.push_back(i);
    std::stable_sort(order_.begin(), order_.end(),
                     [&](int a, int b) { return work_.tasks[a].cycles > work_.tasks[b].cycles; });
  }
  return order_;
}

template class FarmProgram<float>;
template class FarmProgram<double>;

}  // namespace workloads
