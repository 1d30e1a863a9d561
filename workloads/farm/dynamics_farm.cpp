#include "workloads/farm/dynamics_farm.hpp"

#include <cmath>
#include <stdexcept>

#include "t800/link_timing.hpp"
#include "t800/timing_table.hpp"
#include "workloads/dynamics/assembly.hpp"
#include "workloads/dynamics/evaluate.hpp"
#include "workloads/dynamics/worker_input.hpp"
#include "workloads/farm/farm_tasks.hpp"
#include "workloads/farm/schedule.hpp"

namespace workloads {

namespace {

using dynamics::JointVector;

constexpr std::int64_t kIntBytes = 4;  // a subtask index or a stop marker: one occam INT
constexpr int kStop = -1;

JointVector joint_vector(const Params& p, const std::string& name) {
  const std::vector<double>& v = p.real_list(name);
  if (v.size() != dynamics::kJoints)
    throw std::invalid_argument("workload." + name + " needs " + std::to_string(dynamics::kJoints) +
                                " values, got " + std::to_string(v.size()));
  JointVector out;
  for (int i = 0; i < dynamics::kJoints; ++i) {
    if (!std::isfinite(v[i])) throw std::invalid_argument("workload." + name + " has a non-finite value");
    out(i) = v[i];
  }
  return out;
}

template <class S>
class DynamicsFarm : public Workload {
 public:
  DynamicsFarm(const WorkloadContext& c)
      : model_(require_robot(c)),
        variant_(*dynamics::parse_model_variant(c.params.text("model"))),
        schedule_(c.params.text("schedule")),
        buffer_(int(c.params.integer("buffer"))),
        farm_window_(c.params.text("tp_window") == "farm"),
        q_(joint_vector(c.params, "q")),
        qd_(joint_vector(c.params, "qd")) {
    if (!dynamics::within_limits(model_, q_))
      throw std::invalid_argument("workload.q is outside the joint limits of " + model_.name);
    master_ = c.topology.host_processor();
    if (master_ < 0) throw std::invalid_argument("the farm's master must be wired to the host");
    for (int i = 0; i < int(c.topology.processors.size()); ++i)
      if (i != master_) workers_.push_back(i);
    if (workers_.empty()) throw std::invalid_argument("the farm needs at least one worker besides the master");
    allocation_text_ = c.params.text("allocation");
    if (schedule_ == "explicit" && allocation_text_.empty())
      throw std::invalid_argument("workload.schedule = \"explicit\" needs workload.allocation");
  }

  void build(network::Machine& m) override {
    work_ = farm_work(model_, variant_, m.cost_model(master_));
    if (schedule_ != "on-demand") allocation_ = allocate(m);
    auto& state = m.channel("state", network::Machine::kHost, master_);
    for (int w : workers_) {
      to_.push_back(&m.channel("to " + m.node_name(w), master_, w));
      from_.push_back(&m.channel("from " + m.node_name(w), w, master_));
      queue_.push_back(&m.channel("queue " + m.node_name(w), w, w));
    }
    m.spawn(network::Machine::kHost, "host", t800::Priority::low, [&state](network::Process& p) {
      p.out(state, {2 * dynamics::kJoints * kReal, {}, "state"});
    });
    m.spawn(master_, "master", t800::Priority::low, [this, &state](network::Process& p) { master(p, state); });
    for (std::size_t w = 0; w < workers_.size(); ++w) {
      if (!has_work(w)) continue;
      m.spawn(workers_[w], "worker", t800::Priority::low, [this, w](network::Process& p) {
        if (schedule_ == "on-demand")
          on_demand_worker(p, w);
        else
          static_worker(p, w);
      });
    }
  }

  ResultValue results(const network::Machine& m) const override {
    ResultValue r;
    r.set("model", dynamics::to_string(variant_));
    r.set("schedule", schedule_);
    r.set("precision", sizeof(S) == 4 ? "real32" : "real64");
    r.set("subtasks", std::int64_t(work_.tasks.size()));
    r.set("workers", std::int64_t(workers_.size()));
    // Tp is the window the scene chose (workload.tp_window); both are reported.
    const double origin = farm_window_ ? farm_start_us_ : start_us_;
    const double tp_us = farm_window_ ? farm_end_us_ - farm_start_us_ : end_us_ - start_us_;
    r.set("tp_window", farm_window_ ? "farm" : "evaluation");
    r.set("tp_us", tp_us);
    r.set("tp_ms", tp_us / 1000.0);
    r.set("evaluation_us", end_us_ - start_us_);
    r.set("farm_us", farm_end_us_ - farm_start_us_);
    ResultValue per_worker = ResultValue::list();
    for (std::size_t w = 0; w < workers_.size(); ++w) {
      const t800::ProcessorActivity& a = m.transputer(workers_[w]).activity();
      ResultValue row;
      row.set("name", m.node_name(workers_[w]));
      row.set("busy_us", a.busy_us());
      row.set("compute_us", a.compute_us());
      const double busy = farm_window_ ? busy_at_farm_end_[w] - busy_at_farm_start_[w] : a.busy_us();
      row.set("busy_in_tp_us", busy);
      row.set("utilisation_pct", 100.0 * busy / tp_us);
      // When it last stopped working, relative to the start of Tp: the farm's wind-down.
      row.set("end_us", a.last_busy_us() - origin);
      ResultValue names = ResultValue::list();
      for (int t : done_by_[w]) names.push(work_.tasks[t].subtask.name);
      row.set("subtasks", names);
      per_worker.push(row);
    }
    r.set("per_worker", per_worker);
    r.set("D", matrix_value());
    r.set("c", vector_value(data_.c));
    r.set("h", vector_value(data_.h));
    return r;
  }

  const dynamics::DynamicsData<S>& data() const { return data_; }

 private:
  static constexpr std::int64_t kReal = sizeof(S);

  // The list scheduler's view of each worker: its distance from the master in hops.
  Allocation allocate(const network::Machine& m) const {
    std::vector<std::string> task_names, worker_names;
    for (const FarmTask& t : work_.tasks) task_names.push_back(t.subtask.name);
    for (int w : workers_) worker_names.push_back(m.node_name(w));
    if (schedule_ == "explicit") return parse_allocation(allocation_text_, task_names, worker_names);

    const double cycle_ns = m.cost_model(master_).cycle_ns();
    const t800::LinkTiming link(m.options().link);
    const double hop_overhead = t800::timing::kCommFixed * cycle_ns;
    const std::int64_t input_bytes = dynamics::worker_input_reals(model_) * kReal;
    std::vector<double> task_ns;
    for (const FarmTask& t : work_.tasks) task_ns.push_back(double(t.cycles) * cycle_ns);
    std::vector<WorkerCosts> costs;
    for (int w : workers_) {
      const double hops = double(m.topology().shortest_path(master_, w).size() - 1);
      costs.push_back({hops * (link.arrival_ns(input_bytes) + hop_overhead),
                       hops * kReal * link.byte_period_ns, hops * (link.data_packet_ns + hop_overhead)});
    }
    return schedule_static(task_ns, costs);
  }

  std::vector<double> workers_busy_now(network::Machine& m) const {
    std::vector<double> busy;
    for (int w : workers_) busy.push_back(m.transputer(w).activity().busy_us_now());
    return busy;
  }

  // A static schedule may leave a worker without subtasks (more workers than subtasks): it is not started.
  bool has_work(std::size_t w) const { return schedule_ == "on-demand" || !allocation_[w].empty(); }

  void master(network::Process& p, network::Channel& state) {
    p.in(state);
    start_us_ = p.now_us();
    p.compute(work_.master_input, "sin/cos");
    input_ = dynamics::make_worker_input<S>(model_, q_);
    data_.values.assign(work_.tasks.size(), S(0));
    done_by_.assign(workers_.size(), {});
    const std::int64_t input_bytes = dynamics::worker_input_reals(model_) * kReal;
    std::vector<network::Process::Body> talk;
    for (std::size_t w = 0; w < workers_.size(); ++w) {
      if (!has_work(w)) continue;
      talk.push_back([this, w, input_bytes](network::Process& q) {
        q.out(*to_[w], {input_bytes, input_, "input"});
        if (schedule_ == "on-demand")
          hand_out(q, w);
        else
          collect(q, w);
      });
    }
    farm_start_us_ = p.now_us();
    busy_at_farm_start_ = workers_busy_now(p.machine());
    p.par(talk);
    farm_end_us_ = p.now_us();
    busy_at_farm_end_ = workers_busy_now(p.machine());
    p.compute(work_.master_assembly, "assemble");
    dynamics::assemble(subtasks(), qd_, data_);
    end_us_ = p.now_us();
  }

  // Static: one message back from each worker with its values, in its allocation's order.
  void collect(network::Process& p, std::size_t w) {
    const auto values = std::any_cast<std::vector<S>>(p.in(*from_[w]).payload);
    for (std::size_t i = 0; i < values.size(); ++i) data_.values[allocation_[w][i]] = values[i];
    done_by_[w] = allocation_[w];
  }

  void static_worker(network::Process& p, std::size_t w) {
    const auto input = std::any_cast<dynamics::WorkerInput<S>>(p.in(*to_[w]).payload);
    std::vector<S> values;
    for (int t : allocation_[w]) values.push_back(run_task(p, t, input));
    p.out(*from_[w], {std::int64_t(values.size()) * kReal, values, "results"});
  }

  // On demand: each worker holds up to `buffer` subtasks; every result returned earns it the next one,
  // longest first. When none is left it gets a stop, and the master waits for what it still has out.
  void hand_out(network::Process& p, std::size_t w) {
    int outstanding = 0;
    bool stopped = false;
    auto give = [&] {
      if (next_ < int(work_.tasks.size())) {
        p.out(*to_[w], {kIntBytes, dispatch_order()[next_++], "subtask"});
        ++outstanding;
      } else if (!stopped) {
        p.out(*to_[w], {kIntBytes, kStop, "stop"});
        stopped = true;
      }
    };
    for (int i = 0; i < buffer_; ++i) give();
    while (outstanding > 0) {
      const auto result = std::any_cast<std::pair<int, S>>(p.in(*from_[w]).payload);
      data_.values[result.first] = result.second;
      done_by_[w].push_back(result.first);
      --outstanding;
      give();
    }
    if (!stopped) give();
  }

  void on_demand_worker(network::Process& p, std::size_t w) {
    const auto input = std::any_cast<dynamics::WorkerInput<S>>(p.in(*to_[w]).payload);
    network::Channel& queue = *queue_[w];
    p.par({[this, w, &queue](network::Process& feeder) {
             for (;;) {
               const int task = std::any_cast<int>(feeder.in(*to_[w]).payload);
               feeder.out(queue, {kIntBytes, task, "queued"});
               if (task == kStop) return;
             }
           },
           [this, w, &queue, &input](network::Process& computer) {
             for (;;) {
               const int task = std::any_cast<int>(computer.in(queue).payload);
               if (task == kStop) return;
               const S value = run_task(computer, task, input);
               computer.out(*from_[w], {kIntBytes + kReal, std::make_pair(task, value), "result"});
             }
           }});
  }

  S run_task(network::Process& p, int t, const dynamics::WorkerInput<S>& input) {
    const FarmTask& task = work_.tasks[t];
    p.compute(task.mix, task.subtask.name);
    return dynamics::evaluate_subtask<S>(model_, task.subtask, input);
  }

  const std::vector<int>& dispatch_order() {
    if (order_.empty()) {
      for (int i = 0; i < int(work_.tasks.size()); ++i) order_.push_back(i);
      std::stable_sort(order_.begin(), order_.end(),
                       [&](int a, int b) { return work_.tasks[a].cycles > work_.tasks[b].cycles; });
    }
    return order_;
  }

  std::vector<dynamics::Subtask> subtasks() const {
    std::vector<dynamics::Subtask> s;
    for (const FarmTask& t : work_.tasks) s.push_back(t.subtask);
    return s;
  }

  ResultValue matrix_value() const {
    ResultValue rows = ResultValue::list();
    for (int i = 0; i < dynamics::kJoints; ++i) {
      ResultValue row = ResultValue::list();
      for (int j = 0; j < dynamics::kJoints; ++j) row.push(double(data_.D(i, j)));
      rows.push(row);
    }
    return rows;
  }

  static ResultValue vector_value(const dynamics::JointVectorT<S>& v) {
    ResultValue out = ResultValue::list();
    for (int i = 0; i < dynamics::kJoints; ++i) out.push(double(v(i)));
    return out;
  }

  const dynamics::RobotModel& model_;
  dynamics::ModelVariant variant_;
  std::string schedule_, allocation_text_;
  int buffer_;
  bool farm_window_;
  JointVector q_, qd_;
  int master_ = 0;
  std::vector<int> workers_;
  FarmWork work_;
  Allocation allocation_;
  std::vector<network::Channel*> to_, from_, queue_;
  dynamics::WorkerInput<S> input_;
  dynamics::DynamicsData<S> data_;
  std::vector<std::vector<int>> done_by_;
  std::vector<int> order_;
  int next_ = 0;
  double start_us_ = 0, end_us_ = 0;            // the evaluation: state held -> D, C, c, h assembled
  double farm_start_us_ = 0, farm_end_us_ = 0;
  std::vector<double> busy_at_farm_start_, busy_at_farm_end_;  // the farm: first input sent -> last result received
};

}  // namespace

std::unique_ptr<Workload> make_dynamics_farm(const WorkloadContext& c) {
  if (c.params.text("precision") == "real64") return std::make_unique<DynamicsFarm<double>>(c);
  return std::make_unique<DynamicsFarm<float>>(c);
}

}  // namespace workloads
