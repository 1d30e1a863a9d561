// One end of a link as a booted transputer's link engines see it: an output moves a block of bytes
// and ends when the last is acknowledged; an input takes the next n bytes, however the other end
// split them into outputs. Both run on the link model (t800/link.hpp), which times them: a block
// is one message, so its packets, acknowledges, closed form and faults are the link's own.
//
// Flow control is byte by byte, as on the chip: an input asks the link for just the bytes it
// takes, so a sender whose block is longer is held after them until the next input.
#pragma once

#include <cstdint>
#include <deque>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <systemc>

#include "t800/link.hpp"

namespace workloads::boot {

using Bytes = std::vector<std::uint8_t>;
// A block's bytes as they travel: shared by the pieces the inputs take it in (t800/link.hpp,
// Link::receive), so a fault on a byte not yet taken reaches what the receiver reads.
using SharedBytes = std::shared_ptr<Bytes>;

// The payload of a booted program's messages, registered for link faults (t800/payload_bytes.hpp):
// a corrupted byte changes what the receiver reads.
void register_byte_payload();

class LinkPort {
 public:
  // Spawns the port's two SystemC threads; call at or before the start of the simulation.
  LinkPort(t800::Link& link, int end, const std::string& name);

  // Each calls `done` from the port's thread at the simulated time the transfer ends. One transfer
  // per direction at a time.
  void start_output(Bytes bytes, std::function<void()> done);
  void start_input(std::int64_t count, std::function<void(Bytes)> done);
  // What an ALT's enabled link guard sees at `at` (now or later, the core's own cycle): a byte is
  // here, or one has arrived -- one data packet after its sender started the block, when the
  // chip's link channel becomes ready (the link model's input_pending is at the start).
  bool input_pending(const sc_core::sc_time& at) const;
  // A sender has started a block towards this end whose first byte arrives after now: when.
  std::optional<sc_core::sc_time> ready_after_now() const;
  // When the block now waiting at the link was started by its sender, once the port has seen it.
  const std::optional<sc_core::sc_time>& pending_since() const { return pending_since_; }
  // Nothing is on its way to this end: no byte here, no block started. Whatever a sender starts
  // from now on is seen here one data packet later at the earliest (data_packet()).
  bool nothing_coming() const;
  sc_core::sc_time data_packet() const { return packet_; }
  // `arrived` is called once, when input_pending() becomes true; replaces any earlier watch.
  void watch(std::function<void()> arrived);
  void unwatch();
  // resetch: the transfer in that direction is abandoned (its callback is never called). A block
  // already on the wire is still delivered to the link; the bytes an abandoned input was waiting
  // for stay here for the next input (U: the chip's engine would drop them).
  void reset_output();
  void reset_input();
  // Bytes taken that were not for the taker (a boot byte on a link that lost the race to boot):
  // the next input gets them first.
  void unread(const Bytes& bytes) { buffer_.insert(buffer_.begin(), bytes.begin(), bytes.end()); }

  bool output_busy() const { return bool(output_done_); }
  bool input_busy() const { return bool(input_done_); }
  std::int64_t input_wanted() const { return input_done_ ? wanted_ : 0; }
  std::int64_t buffered() const { return std::int64_t(buffer_.size()); }
  t800::Link& link() { return link_; }
  int end() const { return end_; }

 private:
  void output_thread();
  void input_thread();
  void pending_thread();
  void take(const t800::Message& piece);
  bool partly_taken() const;

  t800::Link& link_;
  int end_;
  std::string name_;
  Bytes output_;
  std::function<void()> output_done_;
  sc_core::sc_event output_started_;
  std::int64_t wanted_ = 0;
  std::function<void(Bytes)> input_done_;
  std::function<void()> arrived_;
  std::deque<std::uint8_t> buffer_;
  SharedBytes incoming_;  // the block coming in, and how much of it is taken
  std::size_t taken_ = 0;
  sc_core::sc_event input_changed_;
  // When the block now pending at the link started (its sender's output), while one is.
  std::optional<sc_core::sc_time> pending_since_;
  sc_core::sc_time packet_;  // one data packet on this link: 11 bit times
};

}  // namespace workloads::boot
