// A processor farm: a master hands a fixed set of tasks to workers on other transputers and gets
// their results back, served in rounds -- one round is a shared input broadcast to every worker,
// then tasks -> results -- so a master can call round() again and again (once per evaluation, four
// times per RK4 step). Channels to workers that are not the master's neighbours are routed through
// the simulator's routers.
//
// Schedules (FarmOptions::schedule):
//   static_list          the tasks are allocated before the run by list scheduling on their
//                        predicted costs and each worker's hop distance
//                        (t800sim/farm_schedule.hpp); one order and one reply per worker and round
//   on_demand            each reply earns its worker the next task (longest first, or in the
//                        tasks' order); `in_flight` tasks per worker (a feeder buffers them). The
//                        master waits for the replies in a PAR of one dialogue per worker, or in
//                        one ALT over them all (FarmOptions::alt_master)
//   explicit_allocation  the allocation is given as text, "P1: a b c; P2: d e" (errors name the
//                        bad token)
// Recovery (static and explicit, opt-in): the master's order and its wait for the reply give up at
// a deadline (Process::out_or_fail / in_or_fail; routers on the way forward with the same
// deadline, so a halted processor anywhere in a worker's subtree is noticed, not waited for); a
// failed worker's tasks go to the others. Orders and replies then carry a checksum: a worker that
// gets a corrupted order answers with an empty reply, a corrupted reply fails its check, and the
// master sends that worker its order once more before giving it up. The run's fault report says
// who noticed what and how the farm recovered.
//
//   using Farm = t800sim::Farm<REAL64, REAL64>;        // shared input, one result per task
//   Farm farm(tasks, [](int task, const double& x) { return f(task, x); });
//   b.process("master", [&](Process& p) { auto r = farm.round(p, 2.0); farm.finish(p); });
//   farm.build(b, "master", {"P1", "P2", "P3"});
#pragma once

#include <algorithm>
#include <cstdint>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "t800sim/alt.hpp"
#include "t800sim/farm_protocol.hpp"
#include "t800sim/farm_schedule.hpp"
#include "t800sim/kernel.hpp"
#include "t800sim/process.hpp"
#include "t800sim/program.hpp"

namespace t800sim {

enum class FarmSchedule { static_list, on_demand, explicit_allocation };

struct FarmOptions {
  FarmSchedule schedule = FarmSchedule::static_list;
  std::string allocation;                         // explicit_allocation
  std::string allocation_setting = "allocation";  // what its errors call the allocation
  int in_flight = 2;                              // on_demand: tasks out per worker
  // on_demand: the master waits for its workers' replies in one ALT over all of them (occam's
  // ALT i = 0 FOR n, each reply answered before the next is taken) instead of a PAR of one
  // dialogue per worker.
  bool alt_master = false;
  // on_demand: the tasks go out longest first by their predicted cycles, or in their own order --
  // a master that cannot know a task's cost before it has run (a ray tracer's lines).
  bool longest_first = true;
  // on_demand: a worker's result leaves through a one-place buffer beside its computer, which
  // starts its next task at once instead of waiting for the result to cross the link (TN07's
  // workers hand their results to the router on their transputer).
  bool buffered_replies = false;
  bool recovery = false;  // static_list, explicit_allocation
  // How long the master waits for a worker beyond its predicted time (0: that predicted time
  // again, plus 50 us).
  double timeout_us = 0;
};

// A task: its name (allocations and reports use it) and the kernel a worker runs for it, whose
// code each worker that may run it holds and whose cycles the static schedule plans with.
struct FarmTask {
  std::string name;
  Kernel kernel;
};

// One round as the master saw it: first order sent -> last reply received, and each worker's busy
// time inside that window.
struct FarmRoundTiming {
  double start_us = 0, end_us = 0;
  std::vector<double> busy_us;
};

namespace detail {
// What the farm knows of the machine (sdk/farm_support.cpp).
struct FarmPlan {
  int master = 0;
  std::vector<int> workers;  // processors
  std::vector<std::string> worker_names;
  std::vector<std::int64_t> task_cycles;  // on the first worker, all on chip: what schedules use
  Allocation allocation;                  // static and explicit
};
FarmPlan plan_farm(const Builder& b, const std::string& master,
                   const std::vector<std::string>& worker_processors,
                   const std::vector<FarmTask>& tasks, const FarmOptions& options,
                   std::int64_t shared_bytes, std::int64_t result_bytes);
// What a worker should take for `tasks` with `bytes` on its links, hop by hop (recovery's
// deadlines).
double farm_predicted_us(Process& master, const FarmPlan& plan, std::size_t w,
                         const std::vector<FarmTask>& tasks, const std::vector<INT>& task_list,
                         std::int64_t bytes);
std::vector<double> farm_busy_now(Process& p, const FarmPlan& plan);
void farm_lost(Process& master, const FarmPlan& plan, const std::vector<std::size_t>& ws);
void farm_corrupted(Process& master, const FarmPlan& plan, std::size_t w, bool order);
void farm_resent(Process& master, const FarmPlan& plan, std::size_t w);
void farm_recovered(Process& master, const FarmPlan& plan, const std::vector<std::size_t>& ws,
                    const std::string& to);
[[noreturn]] void farm_stop(Process& p, const std::string& why);
}  // namespace detail

template <class Shared, class Result>
class Farm {
 public:
  using SharedValue = value_of<Shared>;
  using TaskResult = value_of<Result>;
  // What a worker computes for a task, after its kernel's time has been taken (pure C++).
  using Work = std::function<TaskResult(int task, const SharedValue& shared)>;
  using Order = FarmOrder<SharedValue>;
  using Reply = FarmReply<TaskResult>;

  Farm(std::vector<FarmTask> tasks, Work work, FarmOptions options = {})
      : tasks_(std::move(tasks)), work_(std::move(work)), options_(std::move(options)) {
    if (tasks_.empty()) throw std::invalid_argument("a farm needs at least one task");
    if (options_.in_flight < 1)
      throw std::invalid_argument("a farm's in_flight is at least 1, not " +
                                  std::to_string(options_.in_flight));
    if (options_.recovery && on_demand())
      throw std::invalid_argument("a farm recovers with a static or explicit schedule");
    if (!on_demand() &&
        (options_.alt_master || !options_.longest_first || options_.buffered_replies))
      throw std::invalid_argument(
          "a farm's alt_master, longest_first and buffered_replies are on-demand settings");
  }
  // Its processes hold on to it: it stays where it was built.
  Farm(const Farm&) = delete;
  Farm& operator=(const Farm&) = delete;

  // Declares one worker process on each of `worker_processors` ("worker[i]") and the channels
  // between them and `master`, a process declared before (its placement is where the schedule
  // measures hops from); plans the allocation; declares each worker's code. `typical` is a shared
  // input of the size the rounds will send (a counted or block protocol's length is the value's):
  // the static schedule plans with its bytes.
  void build(Builder& b, const std::string& master,
             const std::vector<std::string>& worker_processors, const SharedValue& typical = {}) {
    plan_ = detail::plan_farm(b, master, worker_processors, tasks_, options_,
                              protocol<Shared>::bytes(typical), result_bytes());
    const int n = int(worker_processors.size());
    std::vector<bool> working;  // a worker with no tasks is not run (no thread for it)
    for (int w = 0; w < n; ++w) working.push_back(has_work(std::size_t(w)));
    b.processes("worker", n, [this](Process& p, int w) { worker(p, std::size_t(w)); })
        .placed_on(worker_processors)
        .running(working);
    for (int w = 0; w < n; ++w) {
      const std::string me = member(std::size_t(w));
      const std::string& at = worker_processors[std::size_t(w)];
      to_.push_back(b.channel<FarmOrders<Shared>>("to " + at, master, me));
      from_.push_back(b.channel<FarmReplies<Result>>("from " + at, me, master));
      queue_.push_back(b.channel<INT>("queue " + at, me, me));
      if (on_demand() && options_.buffered_replies)
        outbox_.push_back(b.channel<FarmReplies<Result>>("outbox " + at, me, me));
    }
    for (std::size_t w = 0; w < worker_processors.size(); ++w) {
      if (!has_work(w)) continue;
      // Its tasks' PROCs (on demand, or recovering, it may get any of them).
      if (on_demand() || options_.recovery)
        for (const FarmTask& t : tasks_) b.code(member(w), t.kernel);
      else
        for (int t : plan_.allocation[w]) b.code(member(w), tasks_[std::size_t(t)].kernel);
    }
  }

  // One round, from the master's process: `shared` to every worker, each task's result back
  // (indexed as the tasks are).
  std::vector<TaskResult> round(Process& master, const SharedValue& shared) {
    results_.assign(tasks_.size(), TaskResult{});
    done_by_.assign(plan_.workers.size(), {});
    outstanding_.assign(plan_.workers.size(), 0);
    ended_.assign(plan_.workers.size(), false);
    next_ = 0;
    failed_.clear();
    recovery_started_us_ = recovery_done_us_ = -1;
    std::vector<Process::Body> talk;
    for (std::size_t w = 0; w < plan_.workers.size(); ++w) {
      if (!has_work(w) || !alive(w)) continue;
      talk.push_back([this, w, &shared](Process& branch) {
        Order order{Order::Kind::round, shared, on_demand() ? std::vector<INT>{} : allocation(w)};
        if (options_.recovery) {
          if (!exchange(branch, w, std::move(order))) failed_.push_back(w);
          return;
        }
        branch.out(to_[w], std::move(order));
        if (!on_demand())
          collect(branch, w);
        else if (options_.alt_master)
          fill(branch, w);
        else
          hand_out(branch, w);
      });
    }
    timing_.start_us = master.now_us();
    const std::vector<double> busy_before = detail::farm_busy_now(master, plan_);
    master.par(talk);
    if (on_demand() && options_.alt_master) serve_all(master);
    if (!failed_.empty()) reassign(master, shared);
    timing_.end_us = master.now_us();
    const std::vector<double> busy_after = detail::farm_busy_now(master, plan_);
    timing_.busy_us.clear();
    for (std::size_t w = 0; w < busy_after.size(); ++w)
      timing_.busy_us.push_back(busy_after[w] - busy_before[w]);
    return results_;
  }

  // After the last round: every worker ends. A worker given up may still be alive (its order was
  // held up behind a router that waited for a halted processor): it is told too, one after the
  // other, each with a deadline past every one given before, so that no router still holding a
  // message for a halted processor makes it miss its own.
  void finish(Process& master) {
    std::vector<Process::Body> stop;
    for (std::size_t w = 0; w < plan_.workers.size(); ++w)
      if (has_work(w) && alive(w))
        stop.push_back([this, w](Process& branch) { branch.out(to_[w], seal(Order{})); });
    master.par(stop);
    for (std::size_t w : lost_) {
      const Order end = seal(Order{});
      latest_deadline_us_ =
          std::max(latest_deadline_us_, master.now_us()) + deadline_after(master, w, end);
      master.out_or_fail(to_[w].out(), end, latest_deadline_us_);
    }
  }

  const std::vector<FarmTask>& tasks() const { return tasks_; }
  const std::vector<std::string>& worker_processors() const { return plan_.worker_names; }
  // The cycles the static schedule planned each task with.
  const std::vector<std::int64_t>& task_cycles() const { return plan_.task_cycles; }
  // The tasks each worker ran in the last round.
  const std::vector<std::vector<int>>& done_by() const { return done_by_; }
  const FarmRoundTiming& last_round() const { return timing_; }
  // Recovery: the workers given up, in order; in the last round, when the master noticed a failed
  // worker and when the reassigned tasks' results were all in (-1 without one).
  std::vector<std::string> lost_workers() const {
    std::vector<std::string> names;
    for (std::size_t w : lost_) names.push_back(plan_.worker_names[w]);
    return names;
  }
  double recovery_started_us() const { return recovery_started_us_; }
  double recovery_done_us() const { return recovery_done_us_; }

 private:
  static constexpr INT kEndOfRound = -1;

  static std::string member(std::size_t w) { return "worker[" + std::to_string(w) + "]"; }
  bool on_demand() const { return options_.schedule == FarmSchedule::on_demand; }
  // A static schedule may leave a worker without tasks (more workers than tasks): it waits for the
  // end of the farm only.
  bool has_work(std::size_t w) const { return on_demand() || !plan_.allocation[w].empty(); }
  bool alive(std::size_t w) const {
    return std::find(lost_.begin(), lost_.end(), w) == lost_.end();
  }
  std::vector<INT> allocation(std::size_t w) const {
    return {plan_.allocation[w].begin(), plan_.allocation[w].end()};
  }
  static std::int64_t result_bytes() { return protocol<Result>::bytes(TaskResult{}); }
  template <class M>
  M seal(M m) const {
    return detail::sealed(std::move(m), options_.recovery);
  }

  // Static: one reply from each worker, its results in its allocation's order.
  void collect(Process& p, std::size_t w) {
    const Reply reply = p.in(from_[w]);
    const std::vector<int>& tasks = plan_.allocation[w];
    for (std::size_t i = 0; i < reply.results.size() && i < tasks.size(); ++i)
      results_[std::size_t(tasks[i])] = reply.results[i];
    done_by_[w] = tasks;
  }

  // On demand: each worker holds up to in_flight tasks; every result earns it the next. When none
  // is left it gets an end-of-round order, and the master waits for what it still has out.
  void hand_out(Process& p, std::size_t w) {
    fill(p, w);
    while (outstanding_[w] > 0) {
      take(p, w, p.in(from_[w]));
      give(p, w);
    }
    if (!ended_[w]) give(p, w);
  }

  void fill(Process& p, std::size_t w) {
    for (int i = 0; i < options_.in_flight; ++i) give(p, w);
  }

  // The ALT-ing master: whichever worker answers first (the first in order when several have) has
  // its result taken and is given the next task, until no worker has a task out.
  void serve_all(Process& master) {
    const auto busy = [this] {
      return std::any_of(outstanding_.begin(), outstanding_.end(), [](int n) { return n > 0; });
    };
    while (busy()) {
      Alt alt(master);
      for (std::size_t w = 0; w < from_.size(); ++w)
        alt.input(
            from_[w],
            [this, &master, w](const Reply& r) {
              take(master, w, r);
              give(master, w);
            },
            outstanding_[w] > 0);
      alt.select();
    }
  }

  // Worker w's next task, or once none is left its end-of-round order (and then nothing).
  void give(Process& p, std::size_t w) {
    Order o;
    if (next_ < int(tasks_.size())) {
      o.kind = Order::Kind::task;
      o.task = dispatch_order()[std::size_t(next_++)];
      ++outstanding_[w];
    } else if (!ended_[w]) {
      o.kind = Order::Kind::end_of_round;
      o.task = kEndOfRound;
      ended_[w] = true;
    } else {
      return;
    }
    p.out(to_[w], std::move(o));
  }

  void take(Process& p, std::size_t w, const Reply& r) {
    if (r.task < 0 || std::size_t(r.task) >= results_.size() || r.results.size() != 1)
      detail::farm_stop(p, "a task index out of range (" + std::to_string(r.task) + ")");
    results_[std::size_t(r.task)] = r.results.front();
    done_by_[w].push_back(r.task);
    --outstanding_[w];
  }

  void worker(Process& p, std::size_t w) {
    if (!has_work(w)) return;
    for (;;) {
      const Order order = p.in(to_[w]);
      if (order.kind == Order::Kind::finish) return;
      if (!detail::intact(order)) {  // corrupted on the way: no results, the master asks again
        p.out(from_[w], seal(Reply{}));
        continue;
      }
      if (on_demand())
        on_demand_round(p, w, order.shared);
      else
        static_round(p, w, order.tasks, order.shared);
    }
  }

  void static_round(Process& p, std::size_t w, const std::vector<INT>& tasks,
                    const SharedValue& shared) {
    Reply reply;
    reply.results.reserve(tasks.size());
    for (INT t : tasks) reply.results.push_back(run_task(p, t, shared));
    p.out(from_[w], seal(std::move(reply)));
  }

  // A feeder takes orders off the link while a computer works through them, so the next task is
  // already on the worker when the current one ends (the buffering that keeps links busy); with
  // buffered replies a sender takes each result off the computer and puts it on the link.
  void on_demand_round(Process& p, std::size_t w, const SharedValue& shared) {
    const Chan<INT> queue = queue_[w];
    const bool buffered = options_.buffered_replies;
    std::vector<Process::Body> parts{
        [this, w, queue](Process& feeder) {
          for (;;) {
            const Order o = feeder.in(to_[w]);
            const INT task = o.kind == Order::Kind::task ? o.task : kEndOfRound;
            feeder.out(queue, task);
            if (task == kEndOfRound) return;
          }
        },
        [this, w, queue, buffered, &shared](Process& computer) {
          const Chan<FarmReplies<Result>> reply_to = buffered ? outbox_[w] : from_[w];
          for (;;) {
            const INT task = computer.in(queue);
            if (task == kEndOfRound) break;
            Reply r{task, {run_task(computer, task, shared)}};
            computer.out(reply_to, std::move(r));
          }
          if (buffered) computer.out(reply_to, Reply{kEndOfRound, {}});
        }};
    if (buffered)
      parts.push_back([this, w](Process& sender) {
        for (;;) {
          Reply r = sender.in(outbox_[w]);
          if (r.task == kEndOfRound) return;
          sender.out(from_[w], std::move(r));
        }
      });
    p.par(parts);
  }

  TaskResult run_task(Process& p, INT t, const SharedValue& shared) {
    const FarmTask& task = tasks_[std::size_t(t)];
    p.compute(task.kernel, task.name);
    return work_(t, shared);
  }

  const std::vector<int>& dispatch_order() {
    if (order_.empty()) {
      for (int i = 0; i < int(tasks_.size()); ++i) order_.push_back(i);
      if (options_.longest_first)
        std::stable_sort(order_.begin(), order_.end(), [&](int a, int b) {
          return plan_.task_cycles[std::size_t(a)] > plan_.task_cycles[std::size_t(b)];
        });
    }
    return order_;
  }

  // ---- recovery ----

  enum class Answer { results, silent, corrupted };

  // The order out, the reply back, each given up at its deadline; a corrupted reply, or an empty
  // one (the worker's word that the order arrived corrupted), earns the order once more.
  bool exchange(Process& p, std::size_t w, Order order) {
    order = seal(std::move(order));
    Answer a = exchange_once(p, w, order);
    if (a != Answer::corrupted) return a == Answer::results;
    a = exchange_once(p, w, order);
    if (a == Answer::results) detail::farm_resent(p, plan_, w);
    return a == Answer::results;
  }

  // How long the master waits for one step of an exchange: the worker's predicted time for the
  // order's tasks and bytes, plus the timeout (or that time again and 50 us).
  double deadline_after(Process& p, std::size_t w, const Order& order) const {
    const std::int64_t bytes =
        protocol<Shared>::bytes(order.shared) + std::int64_t(order.tasks.size()) * result_bytes();
    const double predicted = detail::farm_predicted_us(p, plan_, w, tasks_, order.tasks, bytes);
    return predicted + (options_.timeout_us > 0 ? options_.timeout_us : predicted + 50.0);
  }

  Answer exchange_once(Process& p, std::size_t w, const Order& order) {
    const double wait = deadline_after(p, w, order);
    latest_deadline_us_ = std::max(latest_deadline_us_, p.now_us() + wait);
    if (!p.out_or_fail(to_[w].out(), order, p.now_us() + wait)) return Answer::silent;
    const std::optional<Reply> reply = p.in_or_fail(from_[w].in(), p.now_us() + wait);
    if (!reply) return Answer::silent;
    const bool intact = detail::intact(*reply);
    if (!intact || reply->results.size() != order.tasks.size()) {
      detail::farm_corrupted(p, plan_, w, intact);
      return Answer::corrupted;
    }
    for (std::size_t i = 0; i < reply->results.size(); ++i)
      results_[std::size_t(order.tasks[i])] = reply->results[i];
    done_by_[w].insert(done_by_[w].end(), order.tasks.begin(), order.tasks.end());
    return Answer::results;
  }

  // The failed workers' tasks go to the others, each to the surviving worker with the least
  // predicted work so far (longest first), in one more round of exchanges; a worker that fails in
  // it is given up too, until every task has a result or no worker is left.
  void reassign(Process& p, const SharedValue& shared) {
    recovery_started_us_ = p.now_us();
    while (!failed_.empty()) {
      std::vector<int> orphans;
      std::sort(failed_.begin(), failed_.end());
      detail::farm_lost(p, plan_, failed_);
      for (std::size_t w : failed_) {
        lost_.push_back(w);
        orphans.insert(orphans.end(), plan_.allocation[w].begin(), plan_.allocation[w].end());
        plan_.allocation[w].clear();
      }
      std::vector<std::size_t> survivors;
      for (std::size_t w = 0; w < plan_.workers.size(); ++w)
        if (alive(w) && has_work(w)) survivors.push_back(w);
      if (survivors.empty()) return;  // nobody left: the fault stays unrecovered
      const std::vector<std::vector<int>> extra = share_out(orphans, survivors);
      const std::vector<std::size_t> lost_now = failed_;
      failed_.clear();
      std::vector<Process::Body> talk;
      for (std::size_t w : survivors) {
        if (extra[w].empty()) continue;
        plan_.allocation[w].insert(plan_.allocation[w].end(), extra[w].begin(), extra[w].end());
        talk.push_back([this, w, &extra, &shared](Process& branch) {
          Order order{Order::Kind::round, shared, {extra[w].begin(), extra[w].end()}};
          order.listed = true;  // a recovery's order names its tasks
          if (!exchange(branch, w, std::move(order))) failed_.push_back(w);
        });
      }
      p.par(talk);
      if (!failed_.empty()) continue;
      recovery_done_us_ = p.now_us();
      std::string to;
      for (std::size_t s : survivors)
        if (!extra[s].empty()) to += (to.empty() ? "" : ", ") + plan_.worker_names[s];
      detail::farm_recovered(p, plan_, lost_now, to);
    }
  }

  std::vector<std::vector<int>> share_out(std::vector<int> orphans,
                                          const std::vector<std::size_t>& survivors) const {
    const auto& cycles = plan_.task_cycles;
    std::stable_sort(orphans.begin(), orphans.end(),
                     [&](int a, int b) { return cycles[std::size_t(a)] > cycles[std::size_t(b)]; });
    std::vector<double> load(plan_.workers.size(), 0);
    for (std::size_t w : survivors)
      for (int t : plan_.allocation[w]) load[w] += double(cycles[std::size_t(t)]);
    std::vector<std::vector<int>> extra(plan_.workers.size());
    for (int t : orphans) {
      std::size_t best = survivors.front();
      for (std::size_t w : survivors)
        if (load[w] < load[best]) best = w;
      extra[best].push_back(t);
      load[best] += double(cycles[std::size_t(t)]);
    }
    return extra;
  }

  std::vector<FarmTask> tasks_;
  Work work_;
  FarmOptions options_;
  detail::FarmPlan plan_;
  std::vector<Chan<FarmOrders<Shared>>> to_;
  std::vector<Chan<FarmReplies<Result>>> from_;
  std::vector<Chan<INT>> queue_;
  std::vector<Chan<FarmReplies<Result>>> outbox_;  // buffered replies only
  std::vector<TaskResult> results_;
  std::vector<std::vector<int>> done_by_;
  std::vector<int> order_;
  int next_ = 0;
  std::vector<int> outstanding_;     // on demand: tasks out per worker
  std::vector<bool> ended_;          // on demand: told the round is over
  std::vector<std::size_t> lost_;    // worker indices, in the order given up
  std::vector<std::size_t> failed_;  // this round's
  FarmRoundTiming timing_;
  double recovery_started_us_ = -1, recovery_done_us_ = -1;
  double latest_deadline_us_ = 0;  // of any order the master sent
};

}  // namespace t800sim
