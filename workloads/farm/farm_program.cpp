#include "workloads/farm/farm_program.hpp"

#include <algorithm>
#include <any>
#include <optional>
#include <stdexcept>

#include "workloads/setting_error.hpp"

#include "network/reliable.hpp"
#include "t800/payload_bytes.hpp"

#include "t800/link_timing.hpp"
#include "t800/timing_table.hpp"
#include "workloads/dynamics/evaluate.hpp"

namespace workloads {

namespace {
constexpr std::int64_t kIntBytes = 4;  // a subtask index or a marker: one occam INT
constexpr int kEndOfRound = -1;

// How the farm's messages change when a byte arrives changed (a corrupting link fault): the input's
// REALs, each result REAL, an on-demand result's index and value.
template <class S>
void register_farm_payloads(const dynamics::RobotModel& model) {
  t800::register_payload_bytes(
      typeid(WorkerOrder<S>), [&model](std::any& a, std::int64_t byte, std::uint8_t mask) {
        auto& order = std::any_cast<WorkerOrder<S>&>(a);
        if (!order.input) return false;
        std::vector<S*> fields = dynamics::message_fields(model, *order.input);
        const std::size_t field = std::size_t(byte) / sizeof(S);
        if (field >= fields.size()) return false;  // the task list of a recovery's order
        *fields[field] = t800::flip_byte(*fields[field], byte % std::int64_t(sizeof(S)), mask);
        return true;
      });
  t800::register_payload_bytes(typeid(std::vector<S>),
                               [](std::any& a, std::int64_t byte, std::uint8_t mask) {
                                 auto& values = std::any_cast<std::vector<S>&>(a);
                                 S& v = values.at(std::size_t(byte) / sizeof(S));
                                 v = t800::flip_byte(v, byte % std::int64_t(sizeof(S)), mask);
                                 return true;
                               });
  t800::register_payload_bytes(
      typeid(std::pair<int, S>), [](std::any& a, std::int64_t byte, std::uint8_t mask) {
        auto& result = std::any_cast<std::pair<int, S>&>(a);
        if (byte < kIntBytes)
          result.first = t800::flip_byte(result.first, byte, mask);
        else
          result.second = t800::flip_byte(result.second, byte - kIntBytes, mask);
        return true;
      });
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
    // The worker's code: its subtasks' PROCs (on demand, or recovering, it may get any of them).
    if (settings_.schedule == "on-demand" || settings_.recovery)
      for (const FarmTask& t : work_.tasks) m.declare_code(workers_[w], "worker", t.work.code);
    else
      for (int t : allocation_[w])
        m.declare_code(workers_[w], "worker", work_.tasks[std::size_t(t)].work.code);
  }
  m.declare_code(master_, master_process, work_.master_input.code);
  m.declare_code(master_, master_process, work_.master_assembly.code);
  register_farm_payloads<S>(model_);
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
  failed_.clear();
  recovery_started_us_ = recovery_done_us_ = -1;
  for (std::size_t w = 0; w < workers_.size(); ++w) {
    if (!has_work(w) || !alive(w)) continue;
    talk.push_back([this, w, input_bytes, &input, &data](network::Process& branch) {
      const WorkerOrder<S> order{
          input, settings_.schedule == "on-demand" ? std::vector<int>{} : allocation_[w]};
      if (settings_.recovery) {
        if (!exchange(branch, w, order, input_bytes, data)) failed_.push_back(w);
        return;
      }
      branch.out(*to_[w], {input_bytes, order, "input"});
      if (settings_.schedule == "on-demand")
        hand_out(branch, w, data);
      else
        collect(branch, w, data);
    });
  }
  round.farm_start_us = p.now_us();
  const std::vector<double> busy_before = workers_busy_now(p.machine());
  p.par(talk);
  if (!failed_.empty()) reassign(p, input, input_bytes, data);
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
    if (has_work(w) && alive(w))
      stop.push_back([this, w](network::Process& branch) {
        branch.out(*to_[w], {kIntBytes, WorkerOrder<S>{}, "finish"});
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
    if (result.first < 0 || std::size_t(result.first) >= data.values.size())
      p.stop("a subtask index out of range (" + std::to_string(result.first) + ")");
    data.values[std::size_t(result.first)] = result.second;
    done_by_[w].push_back(result.first);
    --outstanding;
    give();
  }
  if (!ended) give();
}

template <class S>
void FarmProgram<S>::worker(network::Process& p, std::size_t w) {
  for (;;) {
    const auto order = std::any_cast<WorkerOrder<S>>(p.in(*to_[w]).payload);
    if (!order.input) return;
    if (settings_.schedule == "on-demand")
      on_demand_round(p, w, *order.input);
    else
      static_round(p, w, order.tasks, *order.input);
  }
}

template <class S>
void FarmProgram<S>::static_round(network::Process& p, std::size_t w, const std::vector<int>& tasks,
                                  const dynamics::WorkerInput<S>& input) {
  std::vector<S> values;
  for (int t : tasks) values.push_back(run_task(p, t, input));
  p.out(*from_[w], {std::int64_t(values.size()) * kReal, values, "results"});
}

// ---- recovery ----

template <class S>
bool FarmProgram<S>::alive(std::size_t w) const {
  return std::find(lost_.begin(), lost_.end(), workers_[w]) == lost_.end();
}

// What the list scheduler expects worker w to take for `tasks` subtasks of its allocation: its
// subtasks' compute and the input and results on the link, hop by hop.
template <class S>
double FarmProgram<S>::predicted_us(const network::Machine& m, std::size_t w,
                                    const std::vector<int>& tasks) const {
  const t800::LinkTiming link(m.options().link);
  const double hops = double(m.topology().shortest_path(master_, workers_[w]).size() - 1);
  // The tasks' cycles on this worker, with its memory as placed (code off chip costs more).
  const t800::ComputeModel& model = m.compute_model(workers_[w]);
  double compute_ns = 0;
  for (int t : tasks) compute_ns += double(model.cycles(work_.tasks[std::size_t(t)].work));
  compute_ns *= model.cycle_ns();
  const std::int64_t bytes =
      (dynamics::worker_input_reals(model_) + std::int64_t(tasks.size())) * kReal;
  return (compute_ns + hops * link.arrival_ns(bytes)) / 1000.0;
}

// The order out, the results back, each given up at its deadline: the worker's predicted time plus
// the timeout (workload.recovery_timeout_us, or the predicted time again and 50 us).
template <class S>
bool FarmProgram<S>::exchange(network::Process& p, std::size_t w, const WorkerOrder<S>& order,
                              std::int64_t bytes, dynamics::DynamicsData<S>& data) {
  network::Machine& m = p.machine();
  const double predicted = predicted_us(m, w, order.tasks);
  const double slack = settings_.timeout_us > 0 ? settings_.timeout_us : predicted + 50.0;
  if (!network::out_or_fail(p, *to_[w], {bytes, order, "input"}, p.now_us() + predicted + slack))
    return false;
  const auto reply = network::in_or_fail(p, *from_[w], p.now_us() + predicted + slack);
  if (!reply) return false;
  const auto& values = std::any_cast<const std::vector<S>&>(reply->payload);
  for (std::size_t i = 0; i < values.size() && i < order.tasks.size(); ++i)
    data.values[std::size_t(order.tasks[i])] = values[i];
  done_by_[w].insert(done_by_[w].end(), order.tasks.begin(), order.tasks.end());
  return true;
}

// The failed workers' subtasks go to the others, each to the surviving worker with the least
// predicted work so far (longest first), in one more round of exchanges; a worker that fails in it
// is given up too, until every subtask has a result or no worker is left.
template <class S>
void FarmProgram<S>::reassign(network::Process& p,
                              const std::optional<dynamics::WorkerInput<S>>& input,
                              std::int64_t input_bytes, dynamics::DynamicsData<S>& data) {
  network::Machine& m = p.machine();
  recovery_started_us_ = p.now_us();
  while (!failed_.empty()) {
    std::vector<int> orphans;
    for (std::size_t w : failed_) {
      lost_.push_back(workers_[w]);
      const std::vector<int> path = m.topology().shortest_path(master_, workers_[w]);
      m.faults().detected(m, path,
                          "the master's InputOrFail / OutputOrFail deadline (" +
                              m.node_name(workers_[w]) + " did not answer)");
      orphans.insert(orphans.end(), allocation_[w].begin(), allocation_[w].end());
      allocation_[w].clear();
    }
    std::vector<std::size_t> survivors;
    for (std::size_t w = 0; w < workers_.size(); ++w)
      if (alive(w) && has_work(w)) survivors.push_back(w);
    if (survivors.empty()) return;  // nobody left: the fault stays unrecovered
    std::stable_sort(orphans.begin(), orphans.end(), [&](int a, int b) {
      return work_.tasks[std::size_t(a)].cycles > work_.tasks[std::size_t(b)].cycles;
    });
    std::vector<double> load(workers_.size(), 0);
    for (std::size_t w : survivors)
      for (int t : allocation_[w]) load[w] += double(work_.tasks[std::size_t(t)].cycles);
    std::vector<std::vector<int>> extra(workers_.size());
    for (int t : orphans) {
      std::size_t best = survivors.front();
      for (std::size_t w : survivors)
        if (load[w] < load[best]) best = w;
      extra[best].push_back(t);
      load[best] += double(work_.tasks[std::size_t(t)].cycles);
    }
    const std::vector<std::size_t> lost_now = failed_;
    failed_.clear();
    std::vector<network::Process::Body> talk;
    for (std::size_t w : survivors) {
      if (extra[w].empty()) continue;
      allocation_[w].insert(allocation_[w].end(), extra[w].begin(), extra[w].end());
      talk.push_back([this, w, &extra, &input, input_bytes, &data](network::Process& branch) {
        // A recovery's order names its subtasks: one INT each and the count.
        const std::int64_t bytes = input_bytes + kIntBytes * std::int64_t(extra[w].size() + 1);
        if (!exchange(branch, w, WorkerOrder<S>{input, extra[w]}, bytes, data))
          failed_.push_back(w);
      });
    }
    p.par(talk);
    if (!failed_.empty()) continue;
    recovery_done_us_ = p.now_us();
    for (std::size_t w : lost_now) {
      std::string to;
      for (std::size_t s : survivors)
        if (!extra[s].empty()) to += (to.empty() ? "" : ", ") + m.node_name(workers_[s]);
      m.faults().recovered(m, m.topology().shortest_path(master_, workers_[w]),
                           "the master gave " + m.node_name(workers_[w]) + "'s subtasks to " + to);
    }
  }
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
