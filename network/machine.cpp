#include "network/machine.hpp"

#include <algorithm>
#include <chrono>
#include <map>
#include <stdexcept>

#include <fmt/format.h>

#include "network/limits.hpp"
#include "network/stop_request.hpp"
#include "network/transport/direct_link.hpp"
#include "network/transport/link_io.hpp"
#include "network/transport/rendezvous.hpp"
#include "network/transport/store_and_forward.hpp"
#include "network/wait_cycle.hpp"

namespace network {

namespace {

std::string module_name(const std::string& name) {
  std::string s = name;
  for (char& ch : s)
    if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
  return s;
}

void run_body(Process* p, const Process::Body& body) {
  p->set_status("ready");
  p->reschedule();
  p->set_status("running");
  body(*p);
  p->mark_ended();
}

// The links a routed channel's messages leave each node of its path by.
std::vector<StoreAndForward::Hop> hops_along(const Machine& m, const std::vector<int>& path) {
  std::vector<StoreAndForward::Hop> hops;
  for (std::size_t i = 0; i + 1 < path.size(); ++i) {
    const auto link = m.link_between(path[i], path[i + 1]);
    hops.push_back({link->first, link->second});
  }
  return hops;
}

}  // namespace

Machine::Machine(const Topology& topology, const MachineOptions& options)
    : topology_(topology), routes_(topology_), options_(options) {
  const auto code = std::make_shared<t800::CodeCache>();  // a kernel compiled once for all
  for (const ProcessorSpec& spec : topology_.processors) {
    transputers_.push_back(
        std::make_unique<t800::Transputer>(module_name(spec.name).c_str(), spec.config));
    transputers_.back()->activity().keep_intervals(options.keep_intervals);
    transputers_.back()->cpu().set_fidelity(options.fidelity.compute);
    compute_models_.emplace_back(
        spec.config,
        t800::ComputeSettings{options.precision, options.code_efficiency,
                              options.fidelity.compute_cost, options.checked},
        code);
  }
  elaborate_links();
  if (options_.keep_intervals) {
    // The first progress report forecasts the trace (trace_forecast()).
    options_.progress = [this, report = options_.progress](std::int64_t done, std::int64_t total) {
      if (report) report(done, total);
      forecast_trace(done, total);
    };
  }
}

Machine::~Machine() = default;

std::string Machine::node_name(int node) const {
  return node == kHost ? std::string("host") : topology_.processors.at(node).name;
}

void Machine::elaborate_links() {
  auto end_name = [&](const LinkEnd& e) {
    return topology_.processors[e.processor].name + ".link" + std::to_string(e.link);
  };
  for (std::size_t i = 0; i < topology_.connections.size(); ++i) {
    const Connection& c = topology_.connections[i];
    t800::LinkConfig config = options_.link;
    if (c.speed_mbps) config.speed_mbps = *c.speed_mbps;
    t800::Transputer& a = *transputers_[c.a.processor];
    t800::Transputer& b = *transputers_[c.b.processor];
    link_modules_.push_back(std::make_unique<t800::Link>(("link" + std::to_string(i)).c_str(),
                                                         config, &a.activity(), &b.activity(),
                                                         options_.fidelity.links));
    a.attach(c.a.link, *link_modules_.back(), 0);
    b.attach(c.b.link, *link_modules_.back(), 1);
    links_.push_back({end_name(c.a) + "-" + end_name(c.b),
                      {c.a.processor, c.b.processor},
                      link_modules_.back().get()});
  }
  if (topology_.host) {
    t800::Transputer& t = *transputers_[topology_.host->processor];
    link_modules_.push_back(std::make_unique<t800::Link>("hostlink", options_.link, nullptr,
                                                         &t.activity(), options_.fidelity.links));
    t.attach(topology_.host->link, *link_modules_.back(), 1);
    links_.push_back({"host-" + end_name(*topology_.host),
                      {kHost, topology_.host->processor},
                      link_modules_.back().get()});
  }
  for (auto& l : link_modules_) {
    l->activity(0).keep_intervals(options_.keep_intervals);
    l->activity(1).keep_intervals(options_.keep_intervals);
  }
}

// Connection i is link_modules_[i]; the host's link comes after the connections.
std::optional<std::pair<t800::Link*, int>> Machine::link_between(int a, int b) const {
  if (a == kHost || b == kHost) {
    if (!topology_.host || (a == kHost) == (b == kHost)) return std::nullopt;
    const LinkInfo& host = links_.back();
    if (host.node[0] == a && host.node[1] == b) return std::make_pair(host.link, 0);
    if (host.node[1] == a && host.node[0] == b) return std::make_pair(host.link, 1);
    return std::nullopt;
  }
  const LinkIndex& index = routes_.index();
  int first = -1;
  for (int link = 0; link < kLinksPerProcessor; ++link) {
    const int c = index.connection_at(a, link);
    if (c >= 0 && index.peer(a, link).processor == b && (first < 0 || c < first)) first = c;
  }
  if (first < 0) return std::nullopt;
  const LinkInfo& l = links_[std::size_t(first)];
  return std::make_pair(l.link, l.node[0] == a ? 0 : 1);
}

std::vector<int> Machine::route(int from, int to) const {
  const int host_proc = topology_.host_processor();
  if (from == to) return {from};
  if (from == kHost || to == kHost) {
    if (host_proc < 0) return {};
    std::vector<int> inner =
        from == kHost ? routes_.path(host_proc, to) : routes_.path(from, host_proc);
    if (inner.empty()) return {};
    if (from == kHost)
      inner.insert(inner.begin(), kHost);
    else
      inner.push_back(kHost);
    return inner;
  }
  return routes_.path(from, to);
}

Channel& Machine::channel(const std::string& name, int from, int to) {
  if (finalised_)
    throw std::logic_error("channel " + name + " declared after the simulation started");
  auto c = std::make_unique<Channel>();
  c->id = int(channels_.size());
  c->name = name;
  c->from = from;
  c->to = to;
  c->path = route(from, to);
  if (c->path.empty())
    throw std::runtime_error("channel " + name + ": no route from " + node_name(from) + " to " +
                             node_name(to));
  channels_.push_back(std::move(c));
  return *channels_.back();
}

// A channel gets a link direction to itself when its ends are neighbours and no other channel uses
// that direction; every other inter-processor channel is routed, and every link direction a routed
// channel enters gets a router at its receiving end.
void Machine::finalise_channels() {
  std::map<std::pair<int, int>, int> users;
  for (auto& c : channels_)
    for (std::size_t i = 0; i + 1 < c->path.size(); ++i) ++users[{c->path[i], c->path[i + 1]}];

  std::map<std::pair<int, int>, bool> routed_hop;
  routed_.assign(channels_.size(), nullptr);
  for (auto& c : channels_) {
    if (c->path.size() == 1) {
      c->transport = std::make_unique<Rendezvous>(*c);
    } else if (c->path.size() == 2 && users[{c->from, c->to}] == 1) {
      auto hop = link_between(c->from, c->to);
      c->transport = std::make_unique<DirectLink>(*c, *hop->first, hop->second);
    } else {
      auto routed = std::make_unique<StoreAndForward>(*c, hops_along(*this, c->path));
      routed_[std::size_t(c->id)] = routed.get();
      c->transport = std::move(routed);
      for (std::size_t i = 0; i + 1 < c->path.size(); ++i)
        routed_hop[{c->path[i], c->path[i + 1]}] = true;
    }
  }
  for (const auto& [hop, routed] : routed_hop) {
    auto link = link_between(hop.second, hop.first);
    start_router(hop.second, hop.first, *link->first, link->second);
  }
  finalised_ = true;
}

// A software router (store-and-forward): takes each message off its link and passes it on as its
// channel's header says (StoreAndForward::pass_on). High priority, as occam routers ran.
void Machine::start_router(int node, int from, t800::Link& link, int end) {
  const std::string name = "router@" + node_name(node) + "<-" + node_name(from);
  Process& router =
      spawn(node, name, t800::Priority::high, [this, node, &link, end](Process& self) {
        for (;;) {
          self.set_status("router waiting");
          t800::Message m = link_in(self, link, end);
          StoreAndForward& channel = *routed_.at(std::size_t(m.route.channel));
          channel.pass_on(self, node, std::move(m));
        }
      });
  router.set_daemon();
}

// Each processor's footprint from what its processes run (memory_map.hpp): their workspaces (the
// largest frame of the PROCs each runs, plus the words below a process's workspace pointer the
// scheduler uses), their arrays, the code of every PROC and library routine once.
void Machine::place_memory() {
  constexpr int kSchedulerWords = 5;         // Iptr, link, state, timer link and time below Wptr
  constexpr int kUndeclaredFrameWords = 16;  // a process whose code was not declared (U)
  for (int node = 0; node < processors(); ++node) {
    t800::MemoryDemand demand;
    std::map<std::string, int> frame_words;         // per process: its largest frame
    std::map<std::string, std::size_t> code_index;  // a PROC's entry in demand.code
    std::map<std::string, int> array_bytes;
    std::vector<const t800::codegen::CodeUnit*> routines;
    const t800::ComputeModel& model = compute_models_[std::size_t(node)];
    for (const DeclaredCode& d : declared_code_) {
      if (d.node != node) continue;
      const t800::codegen::CodeUnit& unit = model.code(d.kernel);
      int frame = unit.workspace_words;
      for (const t800::codegen::CodeUnit* r : unit.routines) {
        frame = std::max(frame, unit.workspace_words + r->workspace_words);
        if (std::find(routines.begin(), routines.end(), r) == routines.end()) {
          routines.push_back(r);
          demand.library_bytes += r->code_bytes + r->constant_bytes;
        }
      }
      frame_words[d.process] = std::max(frame_words[d.process], frame);
      // Each PROC once, where it was first declared, as long as its longest recording: a recording
      // holds the paths its run took, the PROC every path (a ray tracer's lines take different
      // ones).
      const int bytes = unit.code_bytes + unit.constant_bytes;
      const auto [entry, first] = code_index.emplace(unit.name, demand.code.size());
      if (first)
        demand.code.push_back({unit.name, bytes});
      else
        demand.code[entry->second].bytes = std::max(demand.code[entry->second].bytes, bytes);
      // Arrays a PROC reaches through a pointer are its process's buffers (the message it
      // received, the results it sends): one of each name per process, as long as the longest.
      for (const t800::codegen::ArrayDecl& a : unit.arrays)
        if (a.storage == t800::codegen::ArrayStorage::pointer) {
          int& bytes = array_bytes[d.process + "/" + a.name];
          bytes = std::max(bytes, int(a.length) * t800::codegen::element_bytes(a, unit.real64));
        }
    }
    for (const auto& [name, bytes] : array_bytes) demand.data_bytes += bytes;
    for (const auto& p : processes_) {
      if (p->node() != node) continue;
      auto frame = frame_words.find(p->name());
      const int words = frame != frame_words.end() ? frame->second : kUndeclaredFrameWords;
      demand.workspace_bytes += 4 * (kSchedulerWords + words);
    }
    const ProcessorSpec& spec = topology_.processors[std::size_t(node)];
    try {
      compute_models_[std::size_t(node)].set_memory(
          t800::MemoryMap(t800::processor_model(spec.config.type), spec.config.memory, demand));
    } catch (const t800::PlacementError& e) {
      throw ConfigError(spec.where, "processor " + spec.name + ": " + e.what());
    }
  }
}

Process& Machine::spawn(int node, const std::string& name, t800::Priority priority,
                        Process::Body body) {
  processes_.push_back(std::make_unique<Process>(*this, node, name, priority));
  Process& p = *processes_.back();
  p.set_spawned(++spawned_);
  start(p, std::move(body));
  return p;
}

void Machine::spawn_again(Process& record, t800::Priority priority, Process::Body body) {
  record.begin_again(priority, ++spawned_);
  start(record, std::move(body));
}

// A new SystemC thread is refused past the stated limit rather than left to fail in SystemC
// (E518) or exhaust the host; threads that finished are reused, so the limit counts processes
// alive at once.
void Machine::check_thread_limit(const Process& p) const {
  const std::int64_t threads = std::int64_t(handles_.size() + pending_.size());
  if (threads >= kMaxProcesses)
    throw std::runtime_error(fmt::format(
        "process {}: {} processes would be alive at once, more than the {} one simulation holds "
        "(each is a SystemC thread with its own stack; network/limits.hpp)",
        p.name(), threads + 1, kMaxProcesses));
}

void Machine::start(Process& p, Process::Body body) {
  if (!sc_core::sc_is_running()) {
    check_thread_limit(p);
    pending_.emplace_back(&p, std::move(body));
    return;
  }
  if (idle_threads_.empty()) {
    check_thread_limit(p);
    threads_.push_back(std::make_unique<PooledThread>());
    PooledThread* t = threads_.back().get();
    t->process = &p;
    t->body = std::move(body);
    handles_.push_back(
        sc_core::sc_spawn([this, t] { pooled_thread(*t); }, sc_core::sc_gen_unique_name("proc")));
    return;
  }
  PooledThread* t = idle_threads_.back();
  idle_threads_.pop_back();
  t->process = &p;
  t->body = std::move(body);
  t->assigned.notify();  // runnable now, as a newly spawned thread would be
}

std::vector<const Process*> Machine::processes_in_start_order() const {
  std::vector<const Process*> order;
  order.reserve(processes_.size());
  for (const auto& p : processes_) order.push_back(p.get());
  std::sort(order.begin(), order.end(),
            [](const Process* a, const Process* b) { return a->spawned() < b->spawned(); });
  return order;
}

void Machine::pooled_thread(PooledThread& t) {
  for (;;) {
    while (!t.process) sc_core::wait(t.assigned);
    run_body(t.process, t.body);
    t.process = nullptr;
    t.body = nullptr;
    idle_threads_.push_back(&t);
  }
}

void Machine::declare_code(int node, const std::string& process,
                           std::shared_ptr<const t800::codegen::Recording> kernel) {
  if (finalised_)
    throw std::logic_error("code for " + process + " declared after the simulation started");
  if (node == kHost) return;  // the host PC's memory is not modelled
  declared_code_.push_back({node, process, std::move(kernel)});
}

void Machine::prepare() {
  if (prepared_) return;
  finalise_channels();
  place_memory();
  prepared_ = true;
}

std::vector<BlockedProcess> Machine::run() {
  prepare();
  for (auto& pending : pending_)  // not a structured binding: clang 14 cannot capture those
    handles_.push_back(
        sc_core::sc_spawn([p = pending.first, body = pending.second] { run_body(p, body); },
                          sc_core::sc_gen_unique_name("proc")));
  pending_.clear();
  elaboration_s_ =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - created_).count();
  heartbeats_.started = std::chrono::steady_clock::now();
  if (limited())
    run_with_limits();
  else
    sc_core::sc_start();
  events_ = sc_core::sc_delta_count();
  end_us_ = t800::sim_now().to_seconds() * 1e6;
  for (auto& t : transputers_) t->activity().close(t800::sim_now());

  std::vector<BlockedProcess> blocked;
  if (limit_ != Limit::none)
    for (const Process* p : processes_in_start_order())
      if (!p->ended() && !p->daemon())
        running_at_stop_.push_back({p->name(), node_name(p->node()), p->status(), ""});
  if (limit_ == Limit::none) {
    const WaitGraph waits(*this);
    for (const Process* p : waits.in_start_order())
      if (!p->ended() && !p->daemon())
        blocked.push_back({p->name(), node_name(p->node()), p->status(), waits.waits_for(*p)});
    if (!blocked.empty()) wait_cycle_ = waits.cycle();
  }
  if (tears_down()) end_threads();
  return blocked;
}

// The simulation in slices of simulated time, the wall clock read between them; a slice is doubled
// while it takes under 20 ms of wall time and halved above 200 ms, so the clock is read a few times
// a second whatever the model's speed. A slice runs every event up to and at its end, and reaches
// at least the next pending event, so the slices run the same events in the same order as one
// sc_start.
void Machine::run_with_limits() {
  using sc_core::sc_time;
  const auto wall_start = std::chrono::steady_clock::now();
  const auto wall_s = [&] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
  };
  const sc_time sim_limit = options_.max_sim_s > 0 ? sc_time(options_.max_sim_s, sc_core::SC_SEC)
                                                   : sc_core::sc_max_time();
  // Slices that adapt to the wall clock where something is read between them.
  const bool watch = options_.max_wall_s > 0 || stop_signals_caught() ||
                     (options_.keep_intervals && options_.max_trace_intervals > 0);
  sc_time slice = watch ? sc_time(1, sc_core::SC_US) : sim_limit;
  // Before the first sc_start nothing is pending yet: the processes start in its initialisation.
  for (bool first = true; first || sc_core::sc_pending_activity(); first = false) {
    const sc_time now = t800::sim_now();
    const sc_time next = first ? sc_core::SC_ZERO_TIME : sc_core::sc_time_to_pending_activity();
    if (next > sim_limit - now) {
      limit_ = Limit::sim_time;  // the next event lies beyond the limit
      return;
    }
    const std::uint64_t deltas = sc_core::sc_delta_count();
    const double before = wall_s();
    sc_core::sc_start(std::min(std::max(slice, next), sim_limit - now),
                      sc_core::SC_EXIT_ON_STARVATION);
    if (limit_ != Limit::none) return;  // the trace's forecast passed its limit
    if (t800::sim_now() == now && sc_core::sc_delta_count() == deltas) return;  // nothing moved
    if (trace_over_limit()) {
      limit_ = Limit::trace_size;
      return;
    }
    if (sc_core::sc_pending_activity() && should_stop_now(wall_s())) return;
    const double took = wall_s() - before;
    if (took < 0.02 && slice < sc_core::sc_max_time() / 2) slice = slice * 2;
    if (took > 0.2 && slice > sc_time(2, sc_core::SC_PS)) slice = slice / 2;
  }
}

const char* to_string(Limit limit) {
  switch (limit) {
    case Limit::sim_time:
      return "max_sim_time";
    case Limit::wall_time:
      return "max_wall_time";
    case Limit::trace_size:
      return "max_trace_intervals";
    case Limit::livelock:
      return "livelock";
    case Limit::interrupted:
      return "interrupted";
    case Limit::none:
      break;
  }
  return "";
}

bool Machine::limited() const {
  return options_.max_sim_s > 0 || options_.max_wall_s > 0 || stop_signals_caught() ||
         (options_.keep_intervals && options_.max_trace_intervals > 0);
}

std::int64_t Machine::kept_intervals() const {
  std::size_t n = 0;
  for (const auto& t : transputers_) n += t->activity().intervals().size();
  for (const auto& l : link_modules_)
    n += l->activity(0).intervals().size() + l->activity(1).intervals().size();
  return std::int64_t(n);
}

bool Machine::trace_over_limit() const {
  return options_.keep_intervals && options_.max_trace_intervals > 0 &&
         kept_intervals() > options_.max_trace_intervals;
}

// At the first progress report, the intervals kept so far scaled to the whole run; a forecast past
// the limit stops the run there (at the end of this delta cycle), before the trace has grown.
void Machine::forecast_trace(std::int64_t done, std::int64_t total) {
  if (forecast_.intervals >= 0 || done < 1 || total < done) return;
  const double scaled = double(kept_intervals()) * double(total) / double(done);
  forecast_ = {std::int64_t(std::min(scaled, 9e18)), done, total};
  if (options_.trace_forecast) options_.trace_forecast(forecast_);
  if (options_.max_trace_intervals > 0 && forecast_.intervals > options_.max_trace_intervals) {
    limit_ = Limit::trace_size;
    sc_core::sc_pause();
  }
}

// Threads still waiting when the run is over (the routers, idle pooled threads, the processes of a
// deadlock) are killed, so that each unwinds its stack and frees what it holds. SystemC 2.3.4
// cannot kill from sc_main (it dereferences the current process, which there is none of), so a
// thread spawned for the purpose does, in one more delta cycle at the same simulated time (after a
// limit, other events are pending: they are not run).
bool Machine::tears_down() const {
#if defined(__SANITIZE_ADDRESS__)
  return true;
#else
  return options_.tear_down;
#endif
}

void Machine::end_threads() {
  std::vector<sc_core::sc_process_handle> live;
  // Newest first: SystemC keeps its threads in a list it pushes at the front and searches from the
  // front to remove one, so killing them in creation order made the teardown quadratic.
  for (auto h = handles_.rbegin(); h != handles_.rend(); ++h)
    if (h->valid() && !h->terminated()) live.push_back(*h);
  handles_.clear();
  if (live.empty()) return;
  sc_core::sc_spawn(
      [live]() mutable {
        for (sc_core::sc_process_handle& h : live) h.kill();
      },
      sc_core::sc_gen_unique_name("end_threads"));
  sc_core::sc_start(sc_core::SC_ZERO_TIME);  // one delta cycle: nothing else is simulated
}

}  // namespace network
