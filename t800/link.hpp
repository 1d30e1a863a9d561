// One physical link between two link ends: two wires, one each way. Direction d (0: end 0 -> end 1, 1: the
// reverse) sends its data packets on wire d and receives its acknowledges on wire 1-d, so each wire carries one
// direction's data interleaved with the other direction's acknowledges (t800-timing.md section 6).
//
// Protocol, byte by byte: the sender's DMA engine sends an 11-bit data packet, then waits for the 2-bit
// acknowledge before sending the next. The receiver acknowledges a byte only while an input is waiting for it
// (flow control). A T800 receiver acknowledges as soon as a packet starts arriving (overlapped acknowledge), a
// T414 only after the whole packet. Both DMA engines run concurrently with the CPUs.
#pragma once

#include <cstdint>
#include <deque>
#include <string>

#include <systemc>

#include "t800/activity.hpp"
#include "t800/message.hpp"
#include "t800/processor_config.hpp"

namespace t800 {

class Link : public sc_core::sc_module {
 public:
  // `activity[e]` is the processor at end e (nullptr for the host PC, which is not accounted).
  Link(const sc_core::sc_module_name& name, const LinkConfig& config, ProcessorActivity* end0,
       ProcessorActivity* end1);

  // Called from the sending process's thread: moves the message out of end `from` and returns when its last
  // byte has been acknowledged. Several senders on one end are served in order.
  void transmit(int from, Message message);
  // Called from the receiving process's thread at end `to`: arms the input DMA and returns the next message.
  Message receive(int to);

  // Nothing queued, in flight or owed in either direction (an input may be armed, waiting): what happens on
  // the link from now on does not depend on its past.
  bool quiet() const;

  const LinkActivity& activity(int direction) const { return dir_[direction].activity; }
  LinkActivity& activity(int direction) { return dir_[direction].activity; }
  const LinkConfig& config() const { return config_; }
  // Time of one data-packet bit.
  sc_core::sc_time bit_time() const { return bit_; }

 private:
  struct Direction {
    // sending DMA
    std::deque<Message> queue;
    std::int64_t sent = 0, acked = 0;
    bool may_send = true;
    std::int64_t submitted = 0, completed = 0;  // message sequence numbers
    sc_core::sc_event sent_event;
    // receiving DMA
    bool armed = false;
    bool ack_owed = false;
    bool accepted_before_detect = false;
    bool receiving = false;
    bool receiver_counted = false;
    Message incoming;
    std::int64_t received = 0;
    std::deque<Message> delivered;
    sc_core::sc_event delivered_event;
    // wire of this direction's data, and its pending acknowledges for the other direction
    int acks_pending = 0;
    sc_core::sc_event wire_wake, detect_event, process_event;
    LinkActivity activity;
  };

  void wire_thread(int wire);
  void send_data_packet(int d);
  void send_ack_packet(int wire);
  void on_detect(int d);
  void on_ack_processed(int d);
  void on_byte_arrived(int d);
  void queue_ack(int d);
  void complete_receive(int d);
  void count_receiver(int d);
  ProcessorActivity* end(int e) { return end_[e]; }

  LinkConfig config_;
  sc_core::sc_time bit_, data_packet_, ack_packet_, detect_delay_, process_delay_;
  ProcessorActivity* end_[2];
  Direction dir_[2];
};

}  // namespace t800
