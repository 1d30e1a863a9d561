#include "workloads/boot/link_port.hpp"

#include <stdexcept>
#include <typeindex>

#include "t800/payload_bytes.hpp"

namespace workloads::boot {

void register_byte_payload() {
  t800::register_payload_bytes(typeid(Bytes),
                               [](std::any& payload, std::int64_t byte, std::uint8_t mask) {
                                 auto* bytes = std::any_cast<Bytes>(&payload);
                                 if (!bytes || byte < 0 || byte >= std::int64_t(bytes->size()))
                                   return false;
                                 (*bytes)[std::size_t(byte)] ^= mask;
                                 return true;
                               });
}

LinkPort::LinkPort(t800::Link& link, int end, const std::string& name)
    : link_(link), end_(end), name_(name) {
  sc_core::sc_spawn([this] { output_thread(); }, (name + "_out").c_str());
  sc_core::sc_spawn([this] { input_thread(); }, (name + "_in").c_str());
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

bool LinkPort::input_pending() const {
  return !buffer_.empty() || link_.input_pending(end_);
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
    m.payload.value = output_;
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
      t800::Message m = link_.receive(end_);
      if (const auto* bytes = std::any_cast<Bytes>(&m.payload.value))
        buffer_.insert(buffer_.end(), bytes->begin(), bytes->end());
      else  // from an SDK process, which sends values: the wire's bytes are not modelled
        throw std::runtime_error(name_ + " received a message of " + std::to_string(m.bytes) +
                                 " bytes without its bytes (from a process of a C++ program, "
                                 "not a booted one): a booted processor's links must lead to "
                                 "booted processors or the host");
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
    if (arrived_ && input_pending()) {
      auto arrived = std::move(arrived_);
      arrived_ = nullptr;
      arrived();
      continue;
    }
    if (arrived_)
      sc_core::wait(input_changed_ | link_.input_pending_event(end_));
    else
      sc_core::wait(input_changed_);
  }
}

}  // namespace workloads::boot
