#include "network/wait_cycle.hpp"

#include <algorithm>

#include "network/channel.hpp"
#include "network/machine.hpp"
#include "network/process.hpp"

namespace network {

WaitGraph::WaitGraph(const Machine& machine)
    : machine_(machine), in_start_order_(machine.processes_in_start_order()) {
  for (const Process* q : in_start_order_)
    if (!q->ended() && !q->daemon() && q->branches().empty()) live_leaves_[q->node()].push_back(q);
}

std::string WaitGraph::who(const Process& p) const {
  return p.name() + " on " + machine_.node_name(p.node());
}

// The processes `p` waits for (see the header); empty when nobody could end its wait.
std::vector<WaitGraph::Waited> WaitGraph::waited_for(const Process& p) const {
  std::vector<Waited> out;
  if (!p.branches().empty()) {
    for (const Process* branch : p.branches())
      if (!branch->ended()) out.push_back({branch, false});
    return out;
  }
  const Channel* c = p.channel();
  if (!c) return out;
  const LastUser& other = p.outputting() ? c->last_reader : c->last_writer;
  if (other.process && !other.is(p)) return {{other.process, other.ended()}};
  const auto leaves = live_leaves_.find(p.outputting() ? c->to : c->from);
  if (leaves == live_leaves_.end()) return out;
  for (const Process* q : leaves->second)
    if (q != &p) out.push_back({q, false});
  return out;
}

namespace {

// "waits to output on channel c for", "waits to input from channel c for", "waits for its PAR
// branch".
std::string how(const Process& p) {
  if (!p.branches().empty()) return "waits for its PAR branch";
  if (!p.channel()) return "waits for";
  return p.outputting() ? "waits to output on channel " + p.channel()->name + " for"
                        : "waits to input from channel " + p.channel()->name + " for";
}

}  // namespace

std::string WaitGraph::waits_for(const Process& p) const {
  const std::vector<Waited> others = waited_for(p);
  if (others.empty()) {
    const Channel* c = p.channel();
    if (!c) return "nobody";
    return "nobody: no process on " + machine_.node_name(p.outputting() ? c->to : c->from) +
           (p.outputting() ? " inputs from channel " : " outputs on channel ") + c->name;
  }
  std::string text;
  for (const Waited& q : others) {
    text += (text.empty() ? "" : ", ") + who(*q.process);
    text += q.ended ? ", which has ended" : " (" + q.process->status() + ")";
  }
  return text;
}

std::vector<std::string> WaitGraph::cycle() const {
  enum class Mark { unseen, on_path, done };
  std::map<const Process*, Mark> mark;
  std::vector<const Process*> path;
  std::vector<std::string> cycle;
  // Depth-first search along the waits; a process met again while on the path closes a cycle.
  auto visit = [&](auto&& self, const Process* p) -> bool {
    mark[p] = Mark::on_path;
    path.push_back(p);
    for (const Waited& waited : waited_for(*p)) {
      if (waited.ended) continue;
      const Process* next = waited.process;
      if (mark[next] == Mark::on_path) {
        const auto start = std::find(path.begin(), path.end(), next);
        for (auto it = start; it != path.end(); ++it) {
          const Process* to = (it + 1 == path.end()) ? next : *(it + 1);
          cycle.push_back(who(**it) + " " + how(**it) + " " + who(*to));
        }
        return true;
      }
      if (mark[next] == Mark::unseen && self(self, next)) return true;
    }
    path.pop_back();
    mark[p] = Mark::done;
    return false;
  };
  for (const Process* p : in_start_order_)
    if (!p->ended() && !p->daemon() && mark[p] == Mark::unseen && visit(visit, p)) break;
  return cycle;
}

}  // namespace network
