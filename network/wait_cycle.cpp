#include "network/wait_cycle.hpp"

#include <algorithm>
#include <map>

#include "network/channel.hpp"
#include "network/machine.hpp"
#include "network/process.hpp"

namespace network {

namespace {

std::string who(const Machine& m, const Process& p) {
  return p.name() + " on " + m.node_name(p.node());
}

// A process waited for, and whether it has ended (a channel's last user may have).
struct Waited {
  const Process* process;
  bool ended;
};

// The processes `p` waits for (see the header); empty when nobody could end its wait.
std::vector<Waited> waited_for(const Machine& m, const Process& p) {
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
  const int node = p.outputting() ? c->to : c->from;
  for (const Process* q : m.processes_in_start_order())
    if (q != &p && q->node() == node && !q->ended() && !q->daemon() && q->branches().empty())
      out.push_back({q, false});
  return out;
}

// "waits to output on channel c for", "waits to input from channel c for", "waits for its PAR
// branch".
std::string how(const Process& p) {
  if (!p.branches().empty()) return "waits for its PAR branch";
  if (!p.channel()) return "waits for";
  return p.outputting() ? "waits to output on channel " + p.channel()->name + " for"
                        : "waits to input from channel " + p.channel()->name + " for";
}

}  // namespace

std::string waits_for(const Machine& m, const Process& p) {
  const std::vector<Waited> others = waited_for(m, p);
  if (others.empty()) {
    const Channel* c = p.channel();
    if (!c) return "nobody";
    return "nobody: no process on " + m.node_name(p.outputting() ? c->to : c->from) +
           (p.outputting() ? " inputs from channel " : " outputs on channel ") + c->name;
  }
  std::string text;
  for (const Waited& q : others) {
    text += (text.empty() ? "" : ", ") + who(m, *q.process);
    text += q.ended ? ", which has ended" : " (" + q.process->status() + ")";
  }
  return text;
}

std::vector<std::string> wait_cycle(const Machine& m) {
  enum class Mark { unseen, on_path, done };
  std::map<const Process*, Mark> mark;
  std::vector<const Process*> path;
  std::vector<std::string> cycle;
  // Depth-first search along the waits; a process met again while on the path closes a cycle.
  auto visit = [&](auto&& self, const Process* p) -> bool {
    mark[p] = Mark::on_path;
    path.push_back(p);
    for (const Waited& waited : waited_for(m, *p)) {
      if (waited.ended) continue;
      const Process* next = waited.process;
      if (mark[next] == Mark::on_path) {
        const auto start = std::find(path.begin(), path.end(), next);
        for (auto it = start; it != path.end(); ++it) {
          const Process* to = (it + 1 == path.end()) ? next : *(it + 1);
          cycle.push_back(who(m, **it) + " " + how(**it) + " " + who(m, *to));
        }
        return true;
      }
      if (mark[next] == Mark::unseen && self(self, next)) return true;
    }
    path.pop_back();
    mark[p] = Mark::done;
    return false;
  };
  for (const Process* p : m.processes_in_start_order())
    if (!p->ended() && !p->daemon() && mark[p] == Mark::unseen && visit(visit, p)) break;
  return cycle;
}

}  // namespace network
