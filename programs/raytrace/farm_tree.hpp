// The shape of the farm on whatever network it runs: the master on the processor wired to the host,
// one worker on every other processor, and the tree that work and results travel along -- the
// network's breadth-first spanning tree from the master, so every hop is one link (a tree network
// is its own spanning tree; a chain is a tree of one child per node). Work goes down it, results
// come up it, forwarded by the processes on each transputer, never by the simulator's routers.
#pragma once

#include <deque>
#include <stdexcept>
#include <string>
#include <vector>

#include "t800sim/program.hpp"

namespace raytrace {

class FarmTree {
 public:
  explicit FarmTree(const t800sim::Network& network) {
    const int n = network.processors();
    root_ = network.host_processor();
    if (n < 2)
      throw std::invalid_argument("the farm needs a worker processor beside the master's " +
                                  network.processor_name(root_) +
                                  " (network.family with network.workers >= 1)");
    std::vector<int> parent(std::size_t(n), -2);  // -2: not reached yet
    parent[std::size_t(root_)] = -1;
    std::deque<int> queue{root_};
    std::vector<int> order;  // processors in breadth-first order, the root first
    while (!queue.empty()) {
      const int at = queue.front();
      queue.pop_front();
      order.push_back(at);
      for (int next : network.neighbours(at))
        if (parent[std::size_t(next)] == -2) {
          parent[std::size_t(next)] = at;
          queue.push_back(next);
        }
    }
    for (int p = 0; p < n; ++p)
      if (parent[std::size_t(p)] == -2)
        throw std::invalid_argument("processor " + network.processor_name(p) +
                                    " has no path of links to the master's processor " +
                                    network.processor_name(root_));
    // Worker w runs on order[w + 1]; its parent is the master (-1) or another worker.
    std::vector<int> worker_of(std::size_t(n), -1);
    for (std::size_t w = 0; w + 1 < order.size(); ++w)
      worker_of[std::size_t(order[w + 1])] = int(w);
    workers_.resize(order.size() - 1);
    for (std::size_t w = 0; w < workers_.size(); ++w) {
      const int processor = order[w + 1];
      workers_[w].processor = network.processor_name(processor);
      workers_[w].parent = worker_of[std::size_t(parent[std::size_t(processor)])];
    }
    for (std::size_t w = 0; w < workers_.size(); ++w) {
      const int up = workers_[w].parent;
      (up < 0 ? master_children_ : workers_[std::size_t(up)].children).push_back(int(w));
    }
    // Breadth-first order puts every child after its parent: sizes from the leaves up.
    for (std::size_t w = workers_.size(); w-- > 0;) {
      workers_[w].subtree += 1;
      if (workers_[w].parent >= 0)
        workers_[std::size_t(workers_[w].parent)].subtree += workers_[w].subtree;
    }
    master_processor_ = network.processor_name(root_);
  }

  struct Worker {
    std::string processor;
    int parent = -1;            // a worker's index, or -1: the master
    std::vector<int> children;  // workers
    int subtree = 0;            // workers at or below this one
  };

  int workers() const { return int(workers_.size()); }
  const Worker& worker(int w) const { return workers_.at(std::size_t(w)); }
  const std::vector<int>& master_children() const { return master_children_; }
  const std::string& master_processor() const { return master_processor_; }
  std::vector<std::string> worker_processors() const {
    std::vector<std::string> names;
    for (const Worker& w : workers_) names.push_back(w.processor);
    return names;
  }

 private:
  int root_ = 0;
  std::string master_processor_;
  std::vector<Worker> workers_;
  std::vector<int> master_children_;
};

}  // namespace raytrace
