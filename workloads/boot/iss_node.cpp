#include "workloads/boot/iss_node.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "t800/timing_table.hpp"

namespace workloads::boot {

using t800::iss::StopReason;
using t800::iss::Word;

namespace {
constexpr std::int64_t kNever = std::numeric_limits<std::int64_t>::max();

t800::iss::CoreConfig core_config(const network::Machine& machine, int node,
                                  const IssNodeOptions& options) {
  const t800::ProcessorConfig& c = machine.transputer(node).config();
  return {&t800::processor_model(c.type), options.installed_bytes, options.policy,
          c.memory.wait_states};
}

}  // namespace

IssNode::IssNode(network::Machine& machine, int node, BootSession& session,
                 const IssNodeOptions& options)
    : machine_(machine),
      node_(node),
      session_(session),
      options_(options),
      core_(core_config(machine, node, options)),
      cycle_ns_(core_.processor().cycle_ns),
      tick_cycles_(sc_core::sc_get_time_resolution().to_seconds() * 1e9 / cycle_ns_) {
  core_.set_link_engine(this);
  session_.account(node).name = machine.node_name(node);
  machine.transputer(node).activity().count_transfers_as_busy(false);
  if (options_.profile) core_.set_profile(&profile_.instructions);
  if (const auto& host = machine.topology().host; host && host->processor == node)
    host_link_ = host->link;
}

std::vector<std::string> IssNode::awaited() const {
  std::vector<std::string> what;
  for (int l = 0; l < 4; ++l) {
    const std::string link =
        l == host_link_ ? fmt::format("link {} (host)", l) : fmt::format("link {}", l);
    if (input_busy_[l]) what.push_back(link + " input");
    if (output_busy_[l]) what.push_back(link + " output");
    if (watching_[l]) what.push_back(link + " ALT guard");
  }
  if (core_.next_timer_cycle()) what.push_back("timer");
  if (what.empty()) what.push_back("nothing (every process stopped)");
  return what;
}

// The first cycle boundary at or after now. A cycle's time is rounded to the kernel's resolution
// (1 ps: a T805-30's 33.33 ns cycle is not a whole number of them), so a time within one tick
// after a boundary is that boundary, not the next: else the core would be a cycle behind the
// clock it has just waited for.
std::int64_t IssNode::now_cycle() const {
  const double ns = t800::sim_now().to_seconds() * 1e9;
  return std::int64_t(std::ceil(ns / cycle_ns_ - tick_cycles_));
}

sc_core::sc_time IssNode::time_of(std::int64_t cycle) const {
  return sc_core::sc_time(double(cycle) * cycle_ns_, sc_core::SC_NS);
}

// The first cycle boundary at or after `t` (as now_cycle).
std::int64_t IssNode::cycle_of(const sc_core::sc_time& t) const {
  return std::int64_t(std::ceil(t.to_seconds() * 1e9 / cycle_ns_ - tick_cycles_));
}

// For deadlock reports: every waiting process, and for a link input how far it got.
std::string IssNode::describe_waiting() const {
  const auto waiting = core_.waiting();
  if (waiting.empty()) return "idle, no process waiting";
  std::string text;
  for (const auto& w : waiting) {
    if (!text.empty()) text += "; ";
    text += fmt::format("process Wdesc #{:08X} at Iptr #{:08X}: {}", w.wdesc, w.iptr, w.what);
    if (!w.channel) continue;
    text += fmt::format(" on channel #{:08X}", w.channel);
    if (!t800::iss::is_link_channel(w.channel)) continue;
    const int link = t800::iss::link_of(w.channel);
    if (!ports_[link]) {
      text += fmt::format(" (link {} is connected to nothing)", link);
    } else if (!t800::iss::is_link_output(w.channel) && ports_[link]->input_busy()) {
      text += fmt::format(" (link {}: {} of {} bytes have come)", link, ports_[link]->buffered(),
                          ports_[link]->input_wanted());
    }
  }
  return text;
}

std::string IssNode::describe_links() const {
  std::string text;
  for (int l = 0; l < 4; ++l) {
    std::string what;
    if (output_busy_[l]) what = "output in flight";
    if (input_busy_[l]) {
      if (!what.empty()) what += ", ";
      what += ports_[l] ? fmt::format("input, {} of {} bytes come", ports_[l]->buffered(),
                                      ports_[l]->input_wanted())
                        : std::string("input");
    }
    if (watching_[l]) what += what.empty() ? "ALT guard watching" : ", ALT guard watching";
    if (what.empty()) continue;
    text += fmt::format("{}link {}: {}{}", text.empty() ? "" : "; ", l, what,
                        ports_[l] ? "" : " (connected to nothing)");
  }
  return text;
}

std::string IssNode::state() const {
  std::string text;
  if (const auto& h = core_.halt_report())
    text = fmt::format("halted at Iptr #{:08X}: {}", h->iptr, h->reason);
  else if (!core_.idle())
    text = fmt::format("running at Iptr #{:08X}, Wdesc #{:08X}", core_.registers().iptr,
                       core_.registers().wdesc());
  else
    text = describe_waiting();
  const std::string links = describe_links();
  return links.empty() ? text : text + "; links in flight: " + links;
}

bool IssNode::outstanding() const {
  for (int l = 0; l < 4; ++l)
    if (output_busy_[l] || input_busy_[l] || watching_[l]) return true;
  return false;
}

// How far the core may run with what is outstanding: nothing coming in to an armed input or a
// watched guard can be seen before the first byte of a block a neighbour starts, one data packet
// after it starts; and a neighbour starts one only when it runs, at the next instant anything in
// the simulation is due at the earliest. A block already started is seen when its first byte
// arrives. A transfer in flight (an output, or an input whose bytes are coming) is timed by the
// link model's next event: none, the caller's bound.
std::optional<std::int64_t> IssNode::lookahead_bound(std::int64_t now) const {
  std::optional<std::int64_t> bound;
  std::optional<std::int64_t> next_due;  // the next instant anything else runs, asked for once
  for (int l = 0; l < 4; ++l) {
    if (output_busy_[l]) return std::nullopt;
    if (!(input_busy_[l] || watching_[l]) || !ports_[l]) continue;
    const LinkPort& port = *ports_[l];
    std::int64_t until = 0;
    if (port.nothing_coming()) {
      if (!next_due)
        next_due = now + std::int64_t(sc_core::sc_time_to_pending_activity().to_seconds() * 1e9 /
                                      cycle_ns_);
      until = *next_due + packet_cycles_[l];
    } else if (const auto ready = port.ready_after_now(); ready && !input_busy_[l]) {
      until = std::max(now + 1, cycle_of(*ready));
    } else {
      return std::nullopt;  // bytes are coming (or an arrival is due now): follow the link model
    }
    bound = bound ? std::min(*bound, until) : until;
  }
  return bound;
}

void IssNode::post(LinkEvent e) {
  inbox_.push_back(std::move(e));
  inbox_event_.notify(sc_core::SC_ZERO_TIME);
}

void IssNode::run(network::Process& p) {
  t800::Transputer& t = machine_.transputer(node_);
  for (int l = 0; l < 4; ++l)
    if (t.port(l).link)
      ports_[l] = std::make_unique<LinkPort>(
          *t.port(l).link, t.port(l).end, fmt::format("{}_link{}", machine_.node_name(node_), l));
  for (int l = 0; l < 4; ++l)
    if (ports_[l])
      packet_cycles_[l] = std::max<std::int64_t>(
          1, std::int64_t(ports_[l]->data_packet().to_seconds() * 1e9 / cycle_ns_));
  if (!boot(p)) return;
  execute(p);
}

// --- reset: poke, peek, or load and run -------------------------------------------------------

Bytes IssNode::read_boot_block(int link, std::int64_t count) {
  ProcessorAccount& a = session_.account(node_);
  a.waiting_link = link;
  a.block_expected = count;
  a.block_got = ports_[link]->buffered();
  Bytes got;
  bool done = false;
  ports_[link]->start_input(count, [&](Bytes b) {
    got = std::move(b);
    done = true;
    inbox_event_.notify(sc_core::SC_ZERO_TIME);
  });
  while (!done && !session_.over()) {
    a.block_got = ports_[link]->buffered();
    sc_core::wait(inbox_event_ | session_.ended_event());
  }
  a.block_got = done ? count : ports_[link]->buffered();
  if (done) a.waiting_link = -1;
  return done ? got : Bytes{};
}

bool IssNode::boot(network::Process& p) {
  ProcessorAccount& a = session_.account(node_);
  p.set_status_text("waiting at reset for a boot byte on any link");
  for (int l = 0; l < 4; ++l)
    if (ports_[l])
      ports_[l]->start_input(1, [this, l](Bytes b) {
        post({LinkEvent::Kind::input_done, l, std::move(b)});
      });
  for (;;) {
    while (inbox_.empty() && !session_.over()) sc_core::wait(inbox_event_ | session_.ended_event());
    if (session_.over()) return false;
    const LinkEvent first = inbox_.front();
    inbox_.erase(inbox_.begin());
    const int link = first.link;
    const std::uint8_t control = first.bytes.at(0);
    if (control == 0 || control == 1) {
      const Bytes address = read_boot_block(link, 4);
      if (address.empty()) return false;
      const Word at = Word(address[0]) | Word(address[1]) << 8 | Word(address[2]) << 16 |
                      Word(address[3]) << 24;
      if (control == 0) {
        const Bytes value = read_boot_block(link, 4);
        if (value.empty()) return false;
        core_.memory().write(at, value.data(), 4);
        ++a.pokes;
      } else {
        Bytes value(4);
        core_.memory().read(at, value.data(), 4);
        bool sent = false;
        ports_[link]->start_output(value, [&] {
          sent = true;
          inbox_event_.notify(sc_core::SC_ZERO_TIME);
        });
        while (!sent && !session_.over()) sc_core::wait(inbox_event_ | session_.ended_event());
        if (!sent) return false;
        ++a.peeks;
      }
      ports_[link]->start_input(1, [this, link](Bytes b) {
        post({LinkEvent::Kind::input_done, link, std::move(b)});
      });
      continue;
    }
    // Booting on `link`: the other links' inputs are withdrawn, and a byte one of them took
    // meanwhile is theirs to keep for the program.
    for (int l = 0; l < 4; ++l)
      if (ports_[l] && l != link) ports_[l]->reset_input();
    for (const LinkEvent& e : inbox_) ports_[e.link]->unread(e.bytes);
    inbox_.clear();
    const Bytes code = read_boot_block(link, control);
    if (code.empty()) return false;
    core_.memory().write(core_.mem_start(), code.data(), code.size());
    a.booted = true;
    a.boot_link = link;
    a.boot_bytes = control;
    core_.advance_to(now_cycle());
    core_.start_boot_program(Word(control), link);
    return true;
  }
}

// --- running ----------------------------------------------------------------------------------

void IssNode::start_output(int link, std::vector<std::uint8_t> bytes) {
  output_busy_[link] = true;
  core_.request_sync();
  if (!ports_[link]) return;  // an unconnected link: nothing ever acknowledges
  requested_.push_back([this, link, b = std::move(bytes)]() mutable {
    ports_[link]->start_output(std::move(b), [this, link] {
      post({LinkEvent::Kind::output_done, link, {}});
    });
  });
}

void IssNode::start_input(int link, Word count) {
  input_busy_[link] = true;
  core_.request_sync();
  if (!ports_[link]) return;
  requested_.push_back([this, link, count] {
    ports_[link]->start_input(count, [this, link](Bytes b) {
      post({LinkEvent::Kind::input_done, link, std::move(b)});
    });
  });
}

bool IssNode::input_pending(int link) const {
  // Asked at the instruction's cycle, which may be ahead of SystemC's clock: the bound the core
  // runs to (lookahead) holds back nothing that could arrive before it.
  return ports_[link] && ports_[link]->input_pending(time_of(core_.cycle()));
}

void IssNode::watch_input(int link, bool on) {
  watching_[link] = on;
  if (!ports_[link]) return;
  if (on) {
    core_.request_sync();
    requested_.push_back([this, link] {
      if (watching_[link])
        ports_[link]->watch([this, link] { post({LinkEvent::Kind::arrived, link, {}}); });
    });
  } else {
    defer([this, link] { ports_[link]->unwatch(); });
  }
}

void IssNode::reset(int link, bool output) {
  if (output) {
    output_busy_[link] = false;
    if (ports_[link]) defer([this, link] { ports_[link]->reset_output(); });
  } else {
    input_busy_[link] = false;
    watching_[link] = false;
    if (ports_[link]) defer([this, link] { ports_[link]->reset_input(); });
  }
}

// A change to a port made by the core: at once, or while running ahead once the run stands.
void IssNode::defer(std::function<void()> port_change) {
  if (ahead_)
    deferred_.push_back(std::move(port_change));
  else
    port_change();
}

void IssNode::deliver_link_events() {
  if (inbox_.empty()) return;
  if (core_.cycle() < now_cycle()) core_.advance_to(now_cycle());
  std::vector<LinkEvent> events;
  events.swap(inbox_);
  for (LinkEvent& e : events) {
    switch (e.kind) {
      case LinkEvent::Kind::output_done:
        if (!output_busy_[e.link]) break;  // reset meanwhile
        output_busy_[e.link] = false;
        core_.output_done(e.link);
        break;
      case LinkEvent::Kind::input_done:
        if (!input_busy_[e.link]) {
          ports_[e.link]->unread(e.bytes);
          break;
        }
        input_busy_[e.link] = false;
        core_.input_done(e.link, e.bytes);
        break;
      case LinkEvent::Kind::arrived:
        if (!watching_[e.link]) break;
        watching_[e.link] = false;
        core_.input_arrived(e.link);
        break;
    }
  }
}

// A watched guard whose first byte has arrived by now is seen now: the port's own notice may come
// later in this instant.
void IssNode::deliver_arrivals() {
  for (int l = 0; l < 4; ++l)
    if (watching_[l] && ports_[l] && ports_[l]->input_pending(t800::sim_now())) {
      if (core_.cycle() < now_cycle()) core_.advance_to(now_cycle());
      watching_[l] = false;
      ports_[l]->unwatch();
      core_.input_arrived(l);
    }
}

void IssNode::start_requested_transfers() {
  std::vector<std::function<void()>> now;
  now.swap(requested_);
  for (auto& start : now) start();
}

// Each byte a link engine moves takes a memory cycle from the CPU (docs/t800-timing.md 6): the
// bytes moved at this processor's ends since the last look delay the core by that many.
std::int64_t IssNode::dma_moved() const {
  std::int64_t moved = 0;
  for (const auto& port : ports_)
    if (port) moved += port->link().dma_bytes_including_now(port->end(), t800::sim_now());
  return moved;
}

void IssNode::charge_dma() {
  const std::int64_t moved = dma_moved();
  const std::int64_t fresh = moved - dma_seen_;
  dma_seen_ = moved;
  if (fresh <= 0 || core_.idle()) return;
  const std::int64_t cycles = fresh * t800::timing::kLinkDmaCyclesPerByte;
  core_.stall(cycles);
  session_.account(node_).dma_stall_cycles += cycles;
}

void IssNode::account() {
  ProcessorAccount& a = session_.account(node_);
  a.instructions = core_.instructions();
  a.cycles = core_.cycle();
  a.blocks = core_.block_counts();
}

std::int64_t IssNode::instruction_budget() const {
  if (options_.max_instructions > 0) return options_.max_instructions - core_.instructions();
  return kNever / 2;
}

// --- running ahead ----------------------------------------------------------------------------
//
// With its inputs and ALT guards waiting on links nothing is coming on, the core may run only one
// data packet past the next instant anything else is due (lookahead_bound): two busy neighbours
// then step each other on a packet at a time, a synchronisation every few instructions. But in
// that state only an arrival can change what the core does, and the core shows nothing of its own
// before it stops for a transfer it starts. So it runs on from a checkpoint to the end of the
// slice (or to that stop), and SystemC is left to catch up: if nothing has started towards any of
// its links by the run's end, and nothing else was delivered, the run stands, as the
// packet-by-packet one would have gone (but for where later DMA stalls fall, which depends on
// where cores synchronise: docs/iss.md, "Running ahead"); if something has, the core goes back to
// the checkpoint and runs again only to the instant it was found out, and on by the look-ahead.

bool IssNode::may_run_ahead() const {
  if (!options_.run_ahead || options_.profile || core_.idle() || !inbox_.empty() ||
      !requested_.empty())
    return false;
  for (int l = 0; l < 4; ++l) {
    if (output_busy_[l]) return false;
    if ((input_busy_[l] || watching_[l]) && ports_[l] && !ports_[l]->nothing_coming()) return false;
  }
  // A link engine's bytes not yet charged to the CPU would be charged at the run's end.
  return dma_moved() == dma_seen_;
}

StopReason IssNode::run_core(std::int64_t now, std::int64_t bound, std::int64_t slice_end) {
  if (!outstanding() || bound >= slice_end || !may_run_ahead())
    return core_.run(bound, instruction_budget());
  ProcessorAccount& a = session_.account(node_);
  ahead_from_.cycle = core_.cycle();
  ahead_from_.output_busy = output_busy_;
  ahead_from_.input_busy = input_busy_;
  ahead_from_.watching = watching_;
  for (int l = 0; l < 4; ++l)
    ahead_from_.block_waiting[l] = ports_[l] && ports_[l]->link().input_pending(ports_[l]->end());
  core_.checkpoint();
  ahead_ = true;
  ++a.runs_ahead;
  const StopReason why = core_.run(slice_end, instruction_budget());
  if (run_ahead_stands(core_.cycle())) {
    core_.commit();
    ahead_ = false;
    std::vector<std::function<void()>> changes;
    changes.swap(deferred_);
    for (auto& change : changes) change();
    return why;
  }
  ++a.runs_ahead_undone;
  a.cycles_undone += core_.cycle() - ahead_from_.cycle;
  undo_run_ahead();
  return core_.run(std::max(now_cycle(), now + 1), instruction_budget());
}

// Waits for SystemC to reach the run's end; false as soon as something the core could have seen
// came before it: a block started towards one of its links that arrives by then (its first byte
// one data packet after the start, which is when this wakes), a link event, the session's end.
bool IssNode::run_ahead_stands(std::int64_t end_cycle) {
  const sc_core::sc_time end = time_of(end_cycle);
  for (;;) {
    if (!inbox_.empty() || session_.over() || machine_.stopping()) return false;
    const sc_core::sc_time now = t800::sim_now();
    for (int l = 0; l < 4; ++l) {
      if (!ports_[l] || ahead_from_.block_waiting[l] ||
          !ports_[l]->link().input_pending(ports_[l]->end()))
        continue;
      // Its start is noted by the port in this instant, perhaps after this look.
      const sc_core::sc_time started = ports_[l]->pending_since().value_or(now);
      if (started + ports_[l]->data_packet() <= end) return false;
    }
    if (now >= end) return true;
    sc_core::sc_event_or_list woken = inbox_event_ | session_.ended_event();
    for (const auto& port : ports_)
      if (port) woken |= port->link().input_pending_event(port->end());
    sc_core::wait(end - now, woken);
  }
}

void IssNode::undo_run_ahead() {
  core_.rollback();
  ahead_ = false;
  output_busy_ = ahead_from_.output_busy;
  input_busy_ = ahead_from_.input_busy;
  watching_ = ahead_from_.watching;
  deferred_.clear();
  requested_.clear();
}

void IssNode::settle() {
  if (!ahead_) return;
  undo_run_ahead();
  core_.run(std::max(now_cycle(), ahead_from_.cycle + 1), instruction_budget());
  account();
}

void IssNode::wait_until_cycle(std::int64_t cycle) {
  const sc_core::sc_time target = time_of(cycle);
  const sc_core::sc_time now = t800::sim_now();
  if (target > now) sc_core::wait(target - now);
}

void IssNode::execute(network::Process& p) {
  ProcessorAccount& a = session_.account(node_);
  t800::ProcessorActivity& activity = machine_.transputer(node_).activity();
  const std::int64_t slice =
      std::max<std::int64_t>(1, std::int64_t(options_.slice_us * 1000 / cycle_ns_));
  bool busy = false;
  for (;;) {
    if (session_.over() || machine_.stopping()) break;
    deliver_link_events();
    deliver_arrivals();
    if (!busy && !core_.idle()) {
      activity.set_cpu(t800::ProcessorState::compute, {}, t800::sim_now());
      busy = true;
    }
    // At least a cycle ahead: with something else due within the cycle (another core's
    // notification, at no time at all) a bound of no cycles would run nothing, and two cores
    // would hand each other zero waits for ever. An event within the cycle is seen at the next
    // cycle's instruction boundary, as the chip sees it.
    const std::int64_t now = now_cycle();
    std::int64_t bound = now + slice;
    if (outstanding()) {
      if (const auto lookahead = lookahead_bound(now)) {
        bound = std::min(bound, *lookahead);
      } else {
        const sc_core::sc_time ahead = sc_core::sc_time_to_pending_activity();
        const double cycles = ahead.to_seconds() * 1e9 / cycle_ns_;
        if (cycles < double(slice)) bound = now + std::max<std::int64_t>(1, cycles);
      }
    }
    // Not past the run's simulated-time limit: what a stopped run reports ran before it.
    std::int64_t slice_end = now + slice;
    if (const double limit_s = machine_.options().max_sim_s; limit_s > 0) {
      const std::int64_t limit = std::max(now + 1, std::int64_t(limit_s * 1e9 / cycle_ns_));
      bound = std::min(bound, limit);
      slice_end = std::min(slice_end, limit);
    }
    const StopReason why = run_core(now, bound, slice_end);
    ++a.synchronisations;
    machine_.heartbeat();
    charge_dma();
    account();
    switch (why) {
      case StopReason::sync:
        wait_until_cycle(core_.cycle());
        start_requested_transfers();
        break;
      case StopReason::running:
        // Never a wait of no time: the next cycle at the least, so simulated time advances.
        wait_until_cycle(std::max(core_.cycle(), now + 1));
        break;
      case StopReason::limit:
        wait_until_cycle(core_.cycle());
        a.instruction_limit = true;
        session_.end(fmt::format("{} reached the instruction limit ({})", machine_.node_name(node_),
                                 options_.max_instructions));
        break;
      case StopReason::halted:
        wait_until_cycle(core_.cycle());
        a.halt = core_.halt_report();
        activity.set_cpu(t800::ProcessorState::idle, {}, t800::sim_now());
        return;
      case StopReason::idle: {
        wait_until_cycle(core_.cycle());
        start_requested_transfers();
        if (busy) activity.set_cpu(t800::ProcessorState::idle, {}, t800::sim_now());
        busy = false;
        const auto timer = core_.next_timer_cycle();
        if (!inbox_.empty()) break;
        if (!timer && !outstanding()) {
          a.waiting = core_.waiting();
          if (a.waiting.empty()) return;  // every process has ended: nothing can happen any more
        }
        p.set_status_text(describe_waiting());
        const sc_core::sc_time idle_from = t800::sim_now();
        const std::vector<std::string> awaited_now =
            options_.profile ? awaited() : std::vector<std::string>{};
        if (timer) {
          const sc_core::sc_time due = time_of(*timer), now = t800::sim_now();
          if (due > now) sc_core::wait(due - now, inbox_event_ | session_.ended_event());
          // Woken by the timer, by a link, or by the session's end.
          core_.advance_to(t800::sim_now() >= due ? std::max(*timer, now_cycle()) : now_cycle());
        } else {
          sc_core::wait(inbox_event_ | session_.ended_event());
        }
        if (options_.profile) {
          const double us = (t800::sim_now() - idle_from).to_seconds() * 1e6;
          profile_.idle_us += us;
          for (const std::string& w : awaited_now) profile_.waiting_us[w] += us;
        }
        a.waiting.clear();
        break;
      }
    }
  }
  if (busy) activity.set_cpu(t800::ProcessorState::idle, {}, t800::sim_now());
  account();
  a.waiting = core_.waiting();
}

}  // namespace workloads::boot
