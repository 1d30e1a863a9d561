#include "workloads/boot/link_port.hpp"

#include <stdexcept>
#include <typeindex>

#include "t800/payload_bytes.hpp"
#include "t800/sim_now.hpp"

namespace workloads::boot {

void register_byte_payload() {
  t800::register_payload_bytes(
      typeid(SharedBytes), [](std::any& payload, std::int64_t byte, std::uint8_t mask) {
        auto* bytes = std::any_cast<SharedBytes>(&payload);
        if (!bytes || !*bytes || byte < 0 || byte >= std::int64_t((*bytes)->size())) return false;
        (**bytes)[std::size_t(byte)] ^= mask;
        return true;
      });
}

LinkPort::LinkPort(t800::Link& link, int end, const std::string& name)
    : link_(link), end_(end), name_(name), packet_(link.bit_time() * 11.0) {
  sc_core::sc_spawn([this] { output_thread(); }, (name + "_out").c_str());
  sc_core::sc_spawn([this] { input_thread(); }, (name + "_in").c_str());
  sc_core::sc_spawn([this] { pending_thread(); }, (name + "_pending").c_str());
}

// Notes when a sender starts a block towards this end, at that instant: a block's first byte
// arrives one data packet later.
void LinkPort::pending_thread() {
  for (;;) {
    sc_core::wait(link_.input_pending_event(end_));
    if (!pending_since_ && link_.input_pending(end_)) pending_since_ = t800::sim_now();
  }
}

void LinkPort::start_output(Bytes bytes, std::function<void()> done) {
  output_ = std::move(bytes);
  output_done_ = std::move(done);
  output_started_.notify(sc_core::SC_ZERO_TIME);
}

void LinkPort::start_input(std::int64_t count, std::function<void(Bytes)> done) {
  wanted_ = count;
  input_done_ = std::move(done);
  input_changed_.notify(sc_core::SC_ZERO_TIME);
}

// A block taken in part whose sender gave up on the rest (resetch, or the host dropping a reply
// the program left unread) is no longer at the link: its remainder is not coming. (Until the
// sender's next block, which is then taken for that remainder: ready a data packet early, and only
// after such an abandon.)
bool LinkPort::partly_taken() const {
  return incoming_ && link_.input_pending(end_);
}

bool LinkPort::input_pending(const sc_core::sc_time& at) const {
  if (!buffer_.empty() || partly_taken()) return true;  // a byte is here, or held at the sender
  if (!link_.input_pending(end_)) return false;
  return !pending_since_ || at >= *pending_since_ + packet_;
}

std::optional<sc_core::sc_time> LinkPort::ready_after_now() const {
  if (!buffer_.empty() || partly_taken() || !link_.input_pending(end_) || !pending_since_)
    return std::nullopt;
  const sc_core::sc_time ready = *pending_since_ + packet_;
  if (ready <= t800::sim_now()) return std::nullopt;
  return ready;
}

bool LinkPort::nothing_coming() const {
  return buffer_.empty() && !link_.input_pending(end_);
}

void LinkPort::watch(std::function<void()> arrived) {
  arrived_ = std::move(arrived);
  input_changed_.notify(sc_core::SC_ZERO_TIME);
}

void LinkPort::unwatch() {
  arrived_ = nullptr;
}

void LinkPort::reset_output() {
  output_done_ = nullptr;
}

void LinkPort::reset_input() {
  input_done_ = nullptr;
  wanted_ = 0;
}

void LinkPort::output_thread() {
  for (;;) {
    while (!output_done_) sc_core::wait(output_started_);
    t800::Message m;
    m.bytes = std::int64_t(output_.size());
    m.payload = std::make_shared<Bytes>(output_);
    link_.transmit(end_, std::move(m));
    // A reset meanwhile abandoned the transfer: nobody waits for it.
    if (auto done = std::move(output_done_)) {
      output_done_ = nullptr;
      done();
    }
  }
}

// Serves the input in hand from the bytes here, taking messages from the link while there are too
// few; with no input in hand, watches for a sender for an ALT.
void LinkPort::input_thread() {
  for (;;) {
    if (input_done_ && std::int64_t(buffer_.size()) < wanted_) {
      take(link_.receive(end_, wanted_ - std::int64_t(buffer_.size())));
      continue;
    }
    if (input_done_) {
      Bytes got(buffer_.begin(), buffer_.begin() + wanted_);
      buffer_.erase(buffer_.begin(), buffer_.begin() + wanted_);
      auto done = std::move(input_done_);
      input_done_ = nullptr;
      wanted_ = 0;
      done(std::move(got));
      continue;
    }
    if (arrived_ && input_pending(t800::sim_now())) {
      auto arrived = std::move(arrived_);
      arrived_ = nullptr;
      arrived();
      continue;
    }
    if (!arrived_)
      sc_core::wait(input_changed_);
    else if (const auto ready = ready_after_now())
      sc_core::wait(*ready - t800::sim_now(), input_changed_);
    else
      sc_core::wait(input_changed_ | link_.input_pending_event(end_));
  }
}

// A piece of a block: the first brings the block's shared bytes, each its count of them.
void LinkPort::take(const t800::Message& piece) {
  if (const auto* bytes = std::any_cast<SharedBytes>(&piece.payload)) {
    incoming_ = *bytes;
    taken_ = 0;
  } else if (piece.payload.has_value() || !incoming_) {
    // from an SDK process, which sends values: the wire's bytes are not modelled
    throw std::runtime_error(name_ + " received a message of " + std::to_string(piece.bytes) +
                             " bytes without its bytes (from a process of a C++ program, not a "
                             "booted one): a booted processor's links must lead to booted "
                             "processors or the host");
  }
  const auto first = incoming_->begin() + std::ptrdiff_t(taken_);
  buffer_.insert(buffer_.end(), first, first + std::ptrdiff_t(piece.bytes));
  taken_ += std::size_t(piece.bytes);
  if (taken_ == incoming_->size()) {
    incoming_.reset();
    // A block queued behind this one starts now, when this one's last byte is taken.
    pending_since_.reset();
    if (link_.input_pending(end_)) pending_since_ = t800::sim_now();
  }
}

}  // namespace workloads::boot
