// A farm of your own, on the SDK's farm skeleton (t800sim/farm.hpp), as a t800sim plugin: task i
// sums k * x for k = 1 .. i + 1 (a loop of i + 1 multiply-adds, so the tasks grow in cost), x the
// round's shared input. The master, on the processor wired to the host, runs `rounds` rounds with
// x = 1, 2, ... and checks every result against the closed form x (i + 1)(i + 2) / 2; the workers
// are every other processor, the deeper ones reached through the simulator's routers.
#include <t800sim/farm.hpp>
#include <t800sim/workload.hpp>

namespace {

using namespace t800sim;

using SumFarm = Farm<REAL64, REAL64>;  // shared input: one REAL64; a result: one REAL64

// The PROC a worker runs for task i, recorded as it computes: its T800 code times the task.
Kernel sum_kernel(int task) {
  return record_kernel<Real64>("SUM" + std::to_string(task), [task] {
    Real64 s = 0.0, x = 1.0;
    declare_variable(s, "s");
    declare_variable(x, "x");
    for (std::size_t k : seq<Real64>(std::size_t(task) + 1)) s = s + Real64(double(k + 1)) * x;
  });
}

double sum(int task, const double& x) {
  double s = 0;
  for (int k = 1; k <= task + 1; ++k) s += double(k) * x;
  return s;
}

FarmSchedule schedule_of(const std::string& name) {
  if (name == "on-demand") return FarmSchedule::on_demand;
  if (name == "explicit") return FarmSchedule::explicit_allocation;
  return FarmSchedule::static_list;
}

std::vector<FarmTask> tasks(int n) {
  std::vector<FarmTask> t;
  for (int i = 0; i < n; ++i) t.push_back({"t" + std::to_string(i), sum_kernel(i)});
  return t;
}

class SumFarmProgram : public Program {
 public:
  SumFarmProgram(const Params& p, const Network& n)
      : rounds_(int(p.integer("rounds"))), farm_(tasks(int(p.integer("tasks"))), sum, options(p)) {
    master_ = n.processor_name(n.host_processor());
    for (int i = 0; i < n.processors(); ++i)
      if (i != n.host_processor()) workers_.push_back(n.processor_name(i));
    if (workers_.empty())
      throw SettingError({kNetworkKey}, "the farm needs a processor besides the master's");
  }

  void build(Builder& b) override {
    b.process("master", [this](Process& p) {
       for (int r = 1; r <= rounds_; ++r) {
         const std::vector<double> results = farm_.round(p, double(r));
         for (std::size_t i = 0; i < results.size(); ++i)
           if (results[i] != double(r) * double(i + 1) * double(i + 2) / 2) ++wrong_;
         tp_us_.push_back(farm_.last_round().end_us - farm_.last_round().start_us);
       }
       farm_.finish(p);
     }).placed_on(master_);
    farm_.build(b, "master", workers_);
  }

  void results(Results& r) const override {
    r.set("workers", std::int64_t(workers_.size()));
    r.set("tasks", std::int64_t(farm_.tasks().size()));
    r.set("wrong_results", wrong_);  // against the closed form
    ResultValue tp = ResultValue::list();
    for (double t : tp_us_) tp.push(ResultValue(t));
    r.set("round_tp_us", tp);
    ResultValue done = ResultValue::list();
    for (std::size_t w = 0; w < workers_.size(); ++w) {
      ResultValue row;
      row.set("processor", workers_[w]);
      ResultValue names = ResultValue::list();
      for (int t : farm_.done_by()[w]) names.push(farm_.tasks()[std::size_t(t)].name);
      row.set("tasks", names);
      done.push(row);
    }
    r.set("last_round", done);
    ResultValue lost = ResultValue::list();
    for (const std::string& name : farm_.lost_workers()) lost.push(name);
    r.set("lost_workers", lost);
  }

 private:
  static FarmOptions options(const Params& p) {
    FarmOptions o;
    o.schedule = schedule_of(p.text("schedule"));
    o.allocation = p.text("allocation");
    o.allocation_setting = "workload.allocation";
    o.recovery = p.flag("recovery");
    return o;
  }

  int rounds_;
  SumFarm farm_;
  std::string master_;
  std::vector<std::string> workers_;
  std::int64_t wrong_ = 0;
  std::vector<double> tp_us_;
};

}  // namespace

T800SIM_WORKLOAD(sum_farm) {
  return {"sum-farm",
          "a toy farm on the SDK's skeleton: task i sums k * x for k = 1 .. i + 1, in rounds",
          {integer_param("tasks", 24, "tasks per round", 1, 1000),
           integer_param("rounds", 3, "rounds the master runs (x = 1, 2, ...)", 1, 1000),
           text_param("schedule", "static", "static, on-demand or explicit",
                      {"static", "on-demand", "explicit"}),
           text_param("allocation", "", "explicit: \"P1: t0 t1; P2: t2 ...\""),
           flag_param("recovery", false, "deadlines on the master's exchanges, checksums")},
          [](const Params& p, const Network& n) { return std::make_unique<SumFarmProgram>(p, n); }};
}

T800SIM_PLUGIN();
