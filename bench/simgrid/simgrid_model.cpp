// The workloads bench/simgrid_bench.cpp times, modelled in SimGrid's S4U API: the reference
// t800sim's speed is compared with (issue 14). Built only when CMake finds SimGrid (Debian's
// libsimgrid-dev), and only on request: `cmake --build build --target simgrid_model`.
//
// Usage: simgrid_model PLAN.json [SimGrid options such as --cfg=...]
// The plan (written by simgrid_bench from t800sim's own topology, allocation and costs) says what
// to run: "stream" (one-way messages between two neighbours), "pingpong" (there and back) or "farm"
// (the dynamics farm's static round: the master sends each worker its input, the workers compute
// and return their results through software routers). Prints one JSON object: the simulated time,
// the farm's Tp and the host wall time of the run.
//
// The model mirrors t800sim's, at the level SimGrid works at:
// * a transputer is a host whose speed is its clock (amounts are cycles); low-priority work holds
//   the CPU until it deschedules (a FIFO mutex per host), routers run at high priority (a large
//   share of the CPU, since SimGrid shares a CPU rather than preempting it);
// * a link direction is a SimGrid link whose latency and bandwidth give t800sim's closed form of an
//   uncontended message, latency + bytes * byte period (t800/link_timing.hpp); its messages pass
//   one at a time (one receiver posts one receive at a time);
// * a channel is direct when it is alone on its link direction, else routed: store-and-forward
//   through a router on every transputer the message enters, with an 8-byte header, as
//   network/transport/store_and_forward.hpp does.
#include <chrono>
#include <cstdio>
#include <deque>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>
#include <simgrid/s4u.hpp>

namespace sg4 = simgrid::s4u;
using nlohmann::json;

namespace {

// --- the plan ------------------------------------------------------------------------------------

struct Channel {
  std::vector<int> path;  // hosts from writer to reader
  bool routed = false;
};

struct Worker {
  int node = 0;
  int to = 0, from = 0;  // channel indices
  double compute_cycles = 0;
  long input_bytes = 0, result_bytes = 0;
};

struct Plan {
  std::string kind;
  double cycle_s = 0;                // one processor cycle
  double latency_s = 0, byte_s = 0;  // a link direction: latency + bytes * byte_s
  long header_bytes = 0;             // added to routed messages
  int hosts = 2;
  std::vector<std::pair<int, int>> edges;
  std::map<std::pair<long, bool>, double> comm_cycles;  // (bytes, copies) -> cycles of in/out
  // stream, pingpong
  long bytes = 0, messages = 0;
  // farm
  int master = 0;
  double startp_cycles = 0, endp_cycles = 0;
  std::vector<Channel> channels;
  std::vector<Worker> workers;

  double communication(long length, bool copies) const {
    const auto found = comm_cycles.find({length, copies});
    if (found == comm_cycles.end())
      throw std::runtime_error("plan: no communication cost for " + std::to_string(length) +
                               " bytes" + (copies ? " (copied)" : ""));
    return found->second;
  }
};

Plan read_plan(const std::string& file) {
  std::ifstream in(file);
  if (!in) throw std::runtime_error("cannot read plan " + file);
  const json j = json::parse(in);
  Plan p;
  p.kind = j.at("kind");
  p.cycle_s = j.at("cycle_s");
  p.latency_s = j.at("link").at("latency_s");
  p.byte_s = j.at("link").at("byte_s");
  p.header_bytes = j.value("header_bytes", 0L);
  p.hosts = j.at("hosts");
  for (const auto& e : j.at("edges")) p.edges.emplace_back(e.at(0), e.at(1));
  for (const auto& c : j.at("comm_cycles")) p.comm_cycles[{c.at(0), c.at(1)}] = c.at(2);
  p.bytes = j.value("bytes", 0L);
  p.messages = j.value("messages", 0L);
  if (p.kind != "farm") return p;
  p.master = j.at("master");
  p.startp_cycles = j.at("startp_cycles");
  p.endp_cycles = j.at("endp_cycles");
  for (const auto& c : j.at("channels"))
    p.channels.push_back({c.at("path").get<std::vector<int>>(), c.at("routed")});
  for (const auto& w : j.at("workers"))
    p.workers.push_back({w.at("node"), w.at("to"), w.at("from"), w.at("compute_cycles"),
                         w.at("input_bytes"), w.at("result_bytes")});
  return p;
}

// --- the platform --------------------------------------------------------------------------------

constexpr double kHighPriority = 1e6;  // a router's share of the CPU against a low-priority process

struct Node {
  sg4::Host* host = nullptr;
  sg4::MutexPtr cpu;  // held by the low-priority process running
};

struct Message {
  int channel = 0;
  long bytes = 0;  // the message's own bytes (without a routing header)
};

// Messages a router delivered to the reader of a routed channel.
struct Inbox {
  std::deque<Message*> messages;
  sg4::SemaphorePtr count = sg4::Semaphore::create(0);
};

class Model {
 public:
  explicit Model(const Plan& plan) : plan_(plan), inboxes_(plan.channels.size()) {
    auto* zone = sg4::create_full_zone("transputers");
    for (int i = 0; i < plan.hosts; ++i) {
      Node n;
      n.host = zone->create_host("P" + std::to_string(i), 1.0 / plan.cycle_s)->seal();
      n.cpu = sg4::Mutex::create();
      nodes_.push_back(n);
    }
    for (const auto& [a, b] : plan.edges) {
      link(zone, a, b);
      link(zone, b, a);
    }
    zone->seal();
  }

  // Low-priority work: the process holds its CPU for the whole amount.
  void low(int node, double cycles) const {
    if (cycles <= 0) return;
    nodes_[std::size_t(node)].cpu->lock();
    sg4::this_actor::execute(cycles);
    nodes_[std::size_t(node)].cpu->unlock();
  }
  static void high(double cycles) {
    if (cycles > 0) sg4::this_actor::execute(cycles, kHighPriority);
  }

  static sg4::Mailbox* wire(int from, int to) {
    return sg4::Mailbox::by_name(std::to_string(from) + ">" + std::to_string(to));
  }
  sg4::Host* host(int node) const { return nodes_[std::size_t(node)].host; }
  const Plan& plan() const { return plan_; }
  Inbox& inbox(int channel) { return inboxes_[std::size_t(channel)]; }

  // occam's `!` on a channel of the farm: the instruction, then the link engine (blocking).
  void send(int node, int channel, long bytes) const {
    const Channel& c = plan_.channels[std::size_t(channel)];
    const long wire_bytes = bytes + (c.routed ? plan_.header_bytes : 0);
    low(node, plan_.communication(wire_bytes, false));
    wire(c.path[0], c.path[1])->put(new Message{channel, bytes}, std::uint64_t(wire_bytes));
  }
  // occam's `?`.
  void receive(int node, int channel) {
    const Channel& c = plan_.channels[std::size_t(channel)];
    low(node, plan_.communication(0, false));
    if (!c.routed) {
      delete wire(c.path[c.path.size() - 2], c.path.back())->get<Message>();
      return;
    }
    Inbox& box = inbox(channel);
    box.count->acquire();
    delete box.messages.front();
    box.messages.pop_front();
  }

  // A router at `node` for the link direction from `from`: takes each message off the link, hands
  // it to its reader here or sends it on along its channel's path.
  void route(int node, int from) {
    sg4::Actor::self()->daemonize();
    for (;;) {
      high(plan_.communication(0, false));
      auto* m = wire(from, node)->get<Message>();
      const Channel& c = plan_.channels[std::size_t(m->channel)];
      if (c.path.back() == node) {
        high(plan_.communication(m->bytes, true));
        Inbox& box = inbox(m->channel);
        box.messages.push_back(m);
        box.count->release();
        continue;
      }
      std::size_t here = 0;
      while (c.path[here] != node) ++here;
      const long wire_bytes = m->bytes + plan_.header_bytes;
      high(plan_.communication(wire_bytes, false));
      wire(node, c.path[here + 1])->put(m, std::uint64_t(wire_bytes));
    }
  }

 private:
  void link(sg4::NetZone* zone, int a, int b) {
    const std::string name = std::to_string(a) + ">" + std::to_string(b);
    auto* l = zone->create_link(name, 1.0 / plan_.byte_s)->set_latency(plan_.latency_s)->seal();
    zone->add_route(host(a)->get_netpoint(), host(b)->get_netpoint(), nullptr, nullptr,
                    {sg4::LinkInRoute(l)}, false);
  }

  const Plan& plan_;
  std::vector<Node> nodes_;
  std::vector<Inbox> inboxes_;
};

// --- the workloads -------------------------------------------------------------------------------

struct Outcome {
  double tp_s = 0;  // the farm's window, else the simulated time
};

void stream(Model& m, Outcome& out) {
  const Plan& p = m.plan();
  sg4::Actor::create("source", m.host(0), [&m, &p] {
    for (long i = 0; i < p.messages; ++i) {
      m.low(0, p.communication(p.bytes, false));
      Model::wire(0, 1)->put(new Message{0, p.bytes}, std::uint64_t(p.bytes));
    }
  });
  sg4::Actor::create("sink", m.host(1), [&m, &p, &out] {
    for (long i = 0; i < p.messages; ++i) {
      m.low(1, p.communication(0, false));
      delete Model::wire(0, 1)->get<Message>();
    }
    out.tp_s = sg4::Engine::get_clock();
  });
}

void pingpong(Model& m, Outcome& out) {
  const Plan& p = m.plan();
  auto bounce = [&m, &p](int self, int other, bool first) {
    for (long i = 0; i < p.messages; ++i) {
      for (int leg = 0; leg < 2; ++leg) {
        if ((leg == 0) == first) {
          m.low(self, p.communication(p.bytes, false));
          Model::wire(self, other)->put(new Message{0, p.bytes}, std::uint64_t(p.bytes));
        } else {
          m.low(self, p.communication(0, false));
          delete Model::wire(other, self)->get<Message>();
        }
      }
    }
  };
  sg4::Actor::create("pinger", m.host(0), [bounce, &out] {
    bounce(0, 1, true);
    out.tp_s = sg4::Engine::get_clock();
  });
  sg4::Actor::create("ponger", m.host(1), [bounce] { bounce(1, 0, false); });
}

// One static round of the farm; Tp runs from the master starting its parallel branches to the last
// branch ending (t800sim's farm window).
void farm(Model& m, Outcome& out) {
  const Plan& p = m.plan();
  std::map<std::pair<int, int>, bool> routers;  // link directions a routed channel enters
  for (const Channel& c : p.channels)
    if (c.routed)
      for (std::size_t i = 0; i + 1 < c.path.size(); ++i)
        routers[{c.path[i], c.path[i + 1]}] = true;
  for (const auto& [hop, used] : routers) {
    const auto [from, node] = hop;
    sg4::Actor::create("router", m.host(node),
                       [&m, node = node, from = from] { m.route(node, from); });
  }
  for (const Worker& w : p.workers)
    sg4::Actor::create("worker", m.host(w.node), [&m, &w] {
      m.receive(w.node, w.to);
      m.low(w.node, w.compute_cycles);
      m.send(w.node, w.from, w.result_bytes);
    });
  sg4::Actor::create("master", m.host(p.master), [&m, &p, &out] {
    const double start = sg4::Engine::get_clock();
    for (std::size_t i = 0; i < p.workers.size(); ++i) m.low(p.master, p.startp_cycles);
    std::vector<sg4::ActorPtr> branches;
    for (const Worker& w : p.workers)
      branches.push_back(sg4::Actor::create("branch", m.host(p.master), [&m, &p, &w] {
        m.send(p.master, w.to, w.input_bytes);
        m.receive(p.master, w.from);
        m.low(p.master, p.endp_cycles);
      }));
    for (const sg4::ActorPtr& b : branches) b->join();
    out.tp_s = sg4::Engine::get_clock() - start;
  });
}

}  // namespace

int main(int argc, char** argv) {
  const auto wall_start = std::chrono::steady_clock::now();
  if (argc < 2) {
    std::cerr << "usage: simgrid_model PLAN.json [SimGrid options]\n";
    return 2;
  }
  try {
    const std::string plan_file = argv[1];
    sg4::Engine engine(&argc, argv);
    // CM02: latency + size / bandwidth, no TCP corrections (the links are not TCP).
    sg4::Engine::set_config("network/model:CM02");
    sg4::Engine::set_config("network/TCP-gamma:0");
    sg4::Engine::set_config("network/crosstraffic:0");
    const Plan plan = read_plan(plan_file);
    Model model(plan);
    Outcome out;
    if (plan.kind == "stream")
      stream(model, out);
    else if (plan.kind == "pingpong")
      pingpong(model, out);
    else if (plan.kind == "farm")
      farm(model, out);
    else
      throw std::runtime_error("unknown plan kind '" + plan.kind + "': stream, pingpong or farm");
    engine.run();
    const double wall =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
    std::cout << json{{"simulated_s", sg4::Engine::get_clock()},
                      {"tp_s", out.tp_s},
                      {"wall_s", wall}}
              << "\n";
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "simgrid_model: error: " << e.what() << "\n";
    return 1;
  }
}
