#include "t800sim/process.hpp"

#include <cstdint>
#include <stdexcept>
#include <string>
#include <typeindex>

#include <systemc>

#include "network/channel.hpp"
#include "network/machine.hpp"
#include "network/process.hpp"
#include "network/transport/link_io.hpp"
#include "t800/link.hpp"
#include "t800/payload_bytes.hpp"
#include "t800sim/kernel.hpp"

namespace t800sim {

namespace {
// The most bytes one communication carries: a T800 message's count is one word, which the
// compiler's code loads as an INT (ldc), so 2^31 - 1.
constexpr std::int64_t kMaxMessageBytes = 2147483647;
}  // namespace

void detail::register_value_bytes(const std::type_info& type, FlipValueByte flip) {
  t800::register_payload_bytes(std::type_index(type), flip);
}

const std::string& Process::name() const {
  return impl_.name();
}

std::string Process::processor() const {
  return impl_.machine().node_name(impl_.node());
}

double Process::now_us() const {
  return impl_.now_us();
}

Process::Instant Process::instant() const {
  return {t800::sim_now().value()};
}

double Process::us_between(Instant from, Instant to) {
  return (sc_core::sc_time::from_value(to.ticks) - sc_core::sc_time::from_value(from.ticks))
             .to_seconds() *
         1e6;
}

void Process::compute(std::int64_t cycles, const std::string& label) {
  impl_.compute(cycles, label);
}

void Process::compute(const Mix& mix, const std::string& label) {
  impl_.compute(mix, label);
}

void Process::compute(const Kernel& kernel, const std::string& label) {
  impl_.compute(kernel.work(), label.empty() ? kernel.name() : label);
}

std::int64_t Process::cycles(const Kernel& kernel) const {
  if (impl_.node() < 0)
    throw std::logic_error("process " + name() + " runs on the host, which runs no kernels");
  return impl_.machine().compute_model(impl_.node()).cycles(kernel.work());
}

std::int64_t Process::cycles(const Instructions& code) const {
  if (impl_.node() < 0)
    throw std::logic_error("process " + name() + " runs on the host, which runs no T800 code");
  return impl_.machine().compute_model(impl_.node()).process_cycles(code);
}

void Process::stop(const std::string& why) {
  impl_.stop(why);
}

std::vector<int> Process::nodes(const std::vector<std::string>& path) const {
  std::vector<int> out;
  for (const std::string& processor : path) {
    const int node = impl_.machine().topology().find(processor);
    if (node < 0)
      throw std::invalid_argument("process " + name() + ": a fault's path names processor " +
                                  processor + ", which the network does not have");
    out.push_back(node);
  }
  return out;
}

int Process::fault_detected(const std::vector<std::string>& path, const std::string& by) {
  network::Machine& m = impl_.machine();
  return m.faults().detected(m, nodes(path), by);
}

void Process::fault_recovered(const std::vector<std::string>& path, const std::string& how) {
  network::Machine& m = impl_.machine();
  m.faults().recovered(m, nodes(path), how);
}

void Process::Wire::send(std::int64_t bytes, std::any value) {
  if (failed_) return;
  if (bytes < 0 || bytes > kMaxMessageBytes)
    throw std::logic_error("process " + process_.name() + ": a message of " +
                           std::to_string(bytes) + " bytes on channel " + channel_.name +
                           ": a T800 message is 0 to " + std::to_string(kMaxMessageBytes) +
                           " bytes (its count is one word, loaded as an INT); send it in parts");
  t800::Message m{bytes, std::move(value), label_.empty() ? channel_.name : label_};
  if (deadline_us_ < 0)
    process_.out(channel_, std::move(m));
  else
    failed_ = !channel_.transport->send_or_fail(process_, std::move(m), deadline_us_);
}

std::any Process::Wire::receive() {
  if (failed_) return {};
  if (deadline_us_ < 0) return process_.in(channel_).payload;
  auto m = channel_.transport->receive_or_fail(process_, deadline_us_);
  failed_ = !m;
  return m ? std::move(m->payload) : std::any{};
}

void Process::check_end(const detail::ChannelSlot* slot, bool writing) const {
  if (!slot || !slot->impl)
    throw std::logic_error("process " + name() +
                           " used a channel that was not declared by the program's build");
  const network::Channel& c = *slot->impl;
  const int end = writing ? c.from : c.to;
  if (end != impl_.node())
    throw std::logic_error("process " + name() + " on " + processor() +
                           (writing ? " outputs to" : " inputs from") + " channel " + c.name +
                           ", whose " + (writing ? "writer" : "reader") + " is placed on " +
                           impl_.machine().node_name(end));
}

Process::Wire Process::open(const detail::ChannelSlot* slot, bool writing, double deadline_us,
                            const std::string& label) {
  check_end(slot, writing);
  return Wire(impl_, *slot->impl, deadline_us, label);
}

// The branches are referred to, not copied: PAR returns only when every branch has ended.
void Process::par(const std::vector<Body>& branches) {
  std::vector<network::Process::Body> bodies;
  for (const Body& b : branches)
    bodies.emplace_back([&b](network::Process& child) {
      Process p(child);
      b(p);
    });
  impl_.par(bodies);
}

void Process::par_for(int n, const IndexedBody& body) {
  std::vector<Body> branches;
  for (int i = 0; i < n; ++i) branches.emplace_back([&body, i](Process& p) { body(p, i); });
  par(branches);
}

void Process::pri_par(const Body& high, const std::vector<Body>& low) {
  auto wrap = [](const Body& b) {
    return network::Process::Body([&b](network::Process& child) {
      Process p(child);
      b(p);
    });
  };
  std::vector<network::Process::Body> lows;
  for (const Body& b : low) lows.push_back(wrap(b));
  impl_.pri_par(wrap(high), lows);
}

std::int64_t Process::timer() const {
  // TIMER ? t compiles to ldtimer; stl t.
  impl_.run_instructions(
      {{t800::isa::Op::ldtimer, 0, 0, false, {}, "TIMER ?"},
       {t800::isa::Op::stl, 1, 0, false, {t800::isa::Region::workspace, -1}, "t"}});
  return impl_.clock();
}

std::int64_t Process::clock() const {
  return impl_.clock();
}

double Process::tick_us() const {
  return impl_.tick_us();
}

void Process::wait_after(std::int64_t t) {
  impl_.wait_after(t);
}

namespace {
detail::ByteLinkSlot& joined(const ByteLink& link) {
  detail::ByteLinkSlot& s = *link.slot();
  if (!s.link)
    throw std::logic_error("byte link " + s.name + " is used before the program is realised");
  return s;
}
}  // namespace

void Process::out(const ByteLink& link, Bytes bytes) {
  detail::ByteLinkSlot& s = joined(link);
  if (bytes.empty()) throw std::invalid_argument("byte link " + s.name + ": no bytes to send");
  t800::Message m;
  m.bytes = std::int64_t(bytes.size());
  m.payload = std::make_shared<Bytes>(std::move(bytes));  // the booted end reads these bytes
  m.label = s.name;
  network::link_out(impl_, *s.link, s.end, std::move(m));
}

// The booted sender's output is one block, taken here in as many pieces as the reads ask for: the
// first piece brings the block's bytes, each piece its count of them.
Bytes Process::in(const ByteLink& link, std::size_t count) {
  detail::ByteLinkSlot& s = joined(link);
  Bytes got;
  while (got.size() < count) {
    impl_.communicate(0, false);
    impl_.deschedule();
    const t800::Message piece = s.link->receive(s.end, std::int64_t(count - got.size()));
    impl_.reschedule();
    if (const auto* bytes = std::any_cast<std::shared_ptr<Bytes>>(&piece.payload)) {
      s.incoming = *bytes;
      s.taken = 0;
    } else if (piece.payload.has_value() || !s.incoming) {
      throw std::runtime_error("byte link " + s.name + " received a message without bytes");
    }
    const auto first = s.incoming->begin() + std::ptrdiff_t(s.taken);
    got.insert(got.end(), first, first + std::ptrdiff_t(piece.bytes));
    s.taken += std::size_t(piece.bytes);
    if (s.taken == s.incoming->size()) s.incoming.reset();
  }
  return got;
}

}  // namespace t800sim
