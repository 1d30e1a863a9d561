#include "t800sim/farm_schedule.hpp"

#include <algorithm>
#include <numeric>
#include <sstream>
#include <stdexcept>

#include "workloads/setting_error.hpp"

namespace t800sim {

namespace {

double finish(const std::vector<int>& tasks, const std::vector<double>& task_ns,
              const WorkerCosts& w) {
  double t = w.start_ns + w.finish_ns;
  for (int i : tasks) t += task_ns[i] + w.per_result_ns;
  return t;
}

int most_loaded(const std::vector<double>& finish_ns) {
  return int(std::max_element(finish_ns.begin(), finish_ns.end()) - finish_ns.begin());
}

// One improving move or swap of a task off the most loaded worker; false when none lowers the
// makespan.
bool improve_once(Allocation& a, const std::vector<double>& task_ns,
                  const std::vector<WorkerCosts>& w) {
  std::vector<double> f = estimated_finish_ns(a, task_ns, w);
  const int hot = most_loaded(f);
  const double makespan = f[hot];
  for (std::size_t ti = 0; ti < a[hot].size(); ++ti) {
    const int task = a[hot][ti];
    for (std::size_t other = 0; other < a.size(); ++other) {
      if (int(other) == hot) continue;
      const double hot_without = f[hot] - task_ns[task] - w[hot].per_result_ns;
      // move
      const double other_with = f[other] + task_ns[task] + w[other].per_result_ns;
      if (std::max(hot_without, other_with) < makespan - 1e-9) {
        a[hot].erase(a[hot].begin() + long(ti));
        a[other].push_back(task);
        return true;
      }
      // swap with a shorter task of the other worker
      for (std::size_t oi = 0; oi < a[other].size(); ++oi) {
        const int back = a[other][oi];
        const double delta = task_ns[task] - task_ns[back];
        if (delta <= 0) continue;
        if (std::max(f[hot] - delta, f[other] + delta) < makespan - 1e-9) {
          std::swap(a[hot][ti], a[other][oi]);
          return true;
        }
      }
    }
  }
  return false;
}

std::vector<std::string> split(const std::string& text, char separator) {
  std::vector<std::string> parts;
  std::stringstream in(text);
  for (std::string part; std::getline(in, part, separator);) parts.push_back(part);
  return parts;
}

std::string trimmed(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\n");
  if (b == std::string::npos) return {};
  return s.substr(b, s.find_last_not_of(" \t\n") - b + 1);
}

int index_of(const std::vector<std::string>& names, const std::string& name) {
  auto it = std::find(names.begin(), names.end(), name);
  return it == names.end() ? -1 : int(it - names.begin());
}

// The first few names, for an error that says what would be valid.
std::string some_names(const std::vector<std::string>& names) {
  constexpr std::size_t kShown = 6;
  std::string s;
  for (std::size_t i = 0; i < names.size() && i < kShown; ++i) s += (i ? " " : "") + names[i];
  return names.size() > kShown ? s + " ... " + names.back() : s;
}

}  // namespace

std::vector<double> estimated_finish_ns(const Allocation& a, const std::vector<double>& task_ns,
                                        const std::vector<WorkerCosts>& workers) {
  std::vector<double> f;
  for (std::size_t w = 0; w < a.size(); ++w) f.push_back(finish(a[w], task_ns, workers[w]));
  return f;
}

Allocation schedule_static(const std::vector<double>& task_ns,
                           const std::vector<WorkerCosts>& workers) {
  std::vector<int> order(task_ns.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](int a, int b) { return task_ns[a] > task_ns[b]; });

  Allocation a(workers.size());
  std::vector<double> f;
  for (const WorkerCosts& w : workers) f.push_back(w.start_ns + w.finish_ns);
  for (int task : order) {
    int best = 0;
    for (std::size_t w = 1; w < workers.size(); ++w)
      if (f[w] + task_ns[task] + workers[w].per_result_ns <
          f[best] + task_ns[task] + workers[best].per_result_ns)
        best = int(w);
    a[best].push_back(task);
    f[best] += task_ns[task] + workers[best].per_result_ns;
  }
  while (improve_once(a, task_ns, workers)) {
  }
  return a;
}

Allocation parse_allocation(const std::string& text, const std::vector<std::string>& task_names,
                            const std::vector<std::string>& worker_names,
                            const std::string& setting) {
  auto fail = [&setting](const std::string& message) {
    throw workloads::SettingError({setting}, setting + ": " + message);
  };
  Allocation a(worker_names.size());
  std::vector<int> owner(task_names.size(), -1);
  for (const std::string& group : split(text, ';')) {
    if (trimmed(group).empty()) continue;
    const auto colon = group.find(':');
    if (colon == std::string::npos)
      fail("'" + trimmed(group) + "' should read 'WORKER: TASK TASK ...'");
    const std::string worker = trimmed(group.substr(0, colon));
    const int w = index_of(worker_names, worker);
    if (w < 0) fail("'" + worker + "' is not a worker of this network");
    std::stringstream tasks(group.substr(colon + 1));
    for (std::string name; tasks >> name;) {
      const int t = index_of(task_names, name);
      if (t < 0)
        fail("no task '" + name + "' in this farm (its tasks: " + some_names(task_names) + ")");
      if (owner[t] >= 0)
        fail("task " + name + " is given to both " + worker_names[owner[t]] + " and " + worker);
      owner[t] = w;
      a[w].push_back(t);
    }
  }
  for (std::size_t t = 0; t < owner.size(); ++t)
    if (owner[t] < 0) fail("task " + task_names[t] + " is given to no worker");
  return a;
}

}  // namespace t800sim
