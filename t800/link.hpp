// One physical link between two link ends: two wires, one each way. Direction d (0: end 0 -> end 1,
// 1: the reverse) sends its data packets on wire d and receives its acknowledges on wire 1-d, so
// each wire carries one direction's data interleaved with the other direction's acknowledges
// (docs/t800-timing.md section 6).
//
// Protocol, byte by byte: the sender's DMA engine sends an 11-bit data packet, then waits for the
// 2-bit acknowledge before sending the next. The receiver acknowledges a byte only while an input
// is waiting for it (flow control). A T800 receiver acknowledges as soon as a packet starts
// arriving (overlapped acknowledge), a T414 only after the whole packet. Both DMA engines run
// concurrently with the CPUs.
//
// Fidelity (t800/fidelity.hpp): at `packet` every packet is simulated at its own time; its end is
// an event only where another party can act on it (link_packets.cpp, send_data_packet), and a
// message that nothing can interleave with (the other direction silent, no fault, no deadline) is
// one run: every packet's time in closed form from one event, handed over to the per-packet steps
// at its last byte or at the instant anything changes (the other direction starts, a resetch). At
// `message` a message follows the closed form of LinkTiming -- a handful of events per message
// instead of several per byte -- which is exact while the other direction is silent. At `automatic`
// a message starts in closed form only when the other direction is silent, and when the other
// direction starts meanwhile, the message in flight is handed over to the packet level at that
// instant: its byte, packet and acknowledge state is worked out from the closed form (hand_over),
// so the result is the packet level's.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <systemc>

#include "t800/activity.hpp"
#include "t800/fidelity.hpp"
#include "t800/message.hpp"
#include "t800/processor_config.hpp"
#include "t800/sim_now.hpp"

namespace t800 {

class Link : public sc_core::sc_module {
 public:
  // `activity[e]` is the processor at end e (nullptr for the host PC, which is not accounted).
  Link(const sc_core::sc_module_name& name, const LinkConfig& config, ProcessorActivity* end0,
       ProcessorActivity* end1, LinkFidelity fidelity = LinkFidelity::automatic);

  // Called from the sending process's thread: moves the message out of end `from` and returns when
  // its last byte has been acknowledged. Several senders on one end are served in order.
  void transmit(int from, Message message);
  // Called from the receiving process's thread at end `to`: arms the input DMA and returns the next
  // message, or its next `at_most` bytes. Flow control is byte by byte, as on the chip: after
  // them the sender is held, its next byte unacknowledged, until the next input is armed. A
  // message taken by several inputs arrives as pieces, each a Message of its own byte count and
  // the sender's label; the first carries a copy of the payload and the others none, so a payload
  // read piece by piece is shared (a shared_ptr), which lets a fault on a later byte reach it.
  static constexpr std::int64_t kWholeMessage = INT64_MAX;
  Message receive(int to, std::int64_t at_most = kWholeMessage);

  // occam's OutputOrFail / InputOrFail (INMOS's reliable-link library): as transmit and receive,
  // but at `deadline` the link engine of that end is reset (resetch) and the message abandoned:
  // false / nullopt. For a link used by one channel (one message queued at a time).
  bool transmit(int from, Message message, const sc_core::sc_time& deadline);
  std::optional<Message> receive(int to, const sc_core::sc_time& deadline);
  // resetch on end `from`'s output from another process: the message under way is abandoned and
  // its transmit returns. False when nothing was under way.
  bool abandon_output(int from);

  // Faults (network/faults.hpp). Each is checked when the link would act, so an armed fault adds
  // no event; `hit` is called, with what it hit, each time it changes something. A link with a
  // fault runs at the packet level. Direction d's next data packet starting at or after `at`:
  // lost on the wire (the receiver never gets the byte, the sender never its acknowledge), or
  // arriving with its value XORed with `mask` (the message's payload changes,
  // t800/payload_bytes.hpp).
  using FaultHit = std::function<void(const std::string& what)>;
  void drop_byte(int d, const sc_core::sc_time& at, FaultHit hit);
  void corrupt_byte(int d, const sc_core::sc_time& at, std::uint8_t mask, FaultHit hit);
  // From `at` wire w starts nothing (neither its direction's data nor the other's acknowledges),
  // and a packet on it at `at` is lost.
  void stop_wire(int w, const sc_core::sc_time& at, FaultHit hit);
  // From `at` end e takes nothing in: its processor has halted.
  void deafen_end(int e, const sc_core::sc_time& at, FaultHit hit);
  // Any fault has taken effect on this link.
  bool faulted() const { return faulted_; }

  // For ALT: a message for end `to` is on its way (its sender has started the output) and no input
  // has taken it yet; the event fires whenever a sender starts one (U: a T800 link channel becomes
  // ready when the first byte arrives, one data packet later).
  bool input_pending(int to) const;
  sc_core::sc_event& input_pending_event(int to) { return dir_[1 - to].submitted_event; }

  // Nothing queued, in flight or owed in either direction (an input may be armed, waiting): what
  // happens on the link from now on does not depend on its past.
  bool quiet() const;

  const LinkActivity& activity(int direction) const { return dir_[direction].activity; }
  LinkActivity& activity(int direction) { return dir_[direction].activity; }
  const LinkConfig& config() const { return config_; }
  // Time of one data-packet bit.
  sc_core::sc_time bit_time() const { return bit_; }
  // Bytes the DMA engines of end `e` have moved (read when sent, written on arrival), counting
  // those at this very instant or not: each takes a memory cycle from that end's CPU. A CPU charges
  // a compute block with the bytes moved after its start (a byte whose arrival woke the process was
  // written before it ran) and strictly before its end (the kernel may not have run that instant's
  // packet events yet).
  // `now` is the current simulated time (the caller's: a CPU asks for each of its links at once).
  std::int64_t dma_bytes(int e, const sc_core::sc_time& now, bool including_now) const;
  // dma_bytes(e, now, false) less the bytes counted at instant t0 after the last
  // dma_bytes(e, t0, true) (see DmaCount): what a block that started at t0 is charged, by now.
  std::int64_t dma_before_less_late(int e, const sc_core::sc_time& now,
                                    const sc_core::sc_time& t0) const;
  // Nothing is moving at end e: no closed form in either direction and no settled arrival pending,
  // so the bytes dma_bytes counts are the counts alone, and stay so until a count changes. A CPU
  // then knows a block was charged nothing at this end without asking dma_bytes again.
  bool dma_still(int e) const {
    return !dir_[e].closed_form.active && !dir_[1 - e].closed_form.active &&
           !dir_[1 - e].arrival_pending;
  }
  std::int64_t dma_counted(int e) const {
    return dir_[e].dma_sent.total + dir_[1 - e].dma_received.total;
  }
  // dma_bytes(e, now, true), without the general case's work where the end is still.
  std::int64_t dma_bytes_including_now(int e, const sc_core::sc_time& now) const {
    if (!dma_still(e)) return dma_bytes(e, now, true);
    dir_[e].dma_sent.query(now);
    dir_[1 - e].dma_received.query(now);
    return dma_counted(e);
  }
  // Messages that ran in closed form, and those handed over to the packet level mid-way.
  std::int64_t closed_form_messages() const { return closed_form_messages_; }
  std::int64_t handovers() const { return handovers_; }
  // At `packet`, a message whose packets nothing can interleave with is planned as one run (see
  // link_closed_form.cpp, closed_form_allowed); off, every packet is its own step: the reference
  // the runs are tested against.
  void plan_packet_runs(bool on) { packet_runs_ = on; }

 private:
  // Bytes a DMA engine moved, and how many of them at the latest instant (see dma_bytes).
  struct DmaCount {
    std::int64_t total = 0, latest = 0;
    sc_core::sc_time latest_at;
    // Bytes moved at the instant a compute block starts are never charged to it, whichever process
    // the kernel runs first at that instant (without this rule the charge depended on SystemC's
    // order of processes woken at one time -- the tie order of its event queue -- so any change
    // to the set of events could move a packet-level result; the closed form counts this way).
    // The bytes counted at the block's start after its baseline was read are "late";
    // Cpu::execute subtracts them.
    mutable bool queried = false;
    mutable sc_core::sc_time query_at;
    mutable std::int64_t late = 0;
    void query(const sc_core::sc_time& now) const {
      queried = true;
      query_at = now;
      late = 0;
    }
    std::int64_t late_at(const sc_core::sc_time& t0) const {
      return queried && query_at == t0 ? late : 0;
    }
    // `counted_first`: as if counted at the start of instant `at`, before any query then.
    void add(std::int64_t n, const sc_core::sc_time& at, bool counted_first = false);
    void add_increasing(std::int64_t n, const sc_core::sc_time& last);
    std::int64_t before(const sc_core::sc_time& now) const {
      return total - (latest_at == now ? latest : 0);
    }
  };
  // A message of one direction following the closed form: its schedule is a function of when it
  // started and when its receiver's input was armed.
  struct ClosedForm {
    explicit ClosedForm(int d);
    bool active = false;
    std::int64_t bytes = 0;
    sc_core::sc_time start;     // its first data packet starts
    bool armed = false;         // the receiver's input is armed, since
    sc_core::sc_time armed_at;  // (the start, if it was armed before)
    bool sender_done = false, delivered = false;
    sc_core::sc_event milestone;  // the next of: last acknowledge in, last byte delivered
  };
  // A packet a wire was carrying when its message was handed over to the packet level.
  struct InFlight {
    bool active = false;
    bool data = false;      // data of this wire's direction, or an acknowledge for the other
    bool recorded = false;  // already in the activity record (closed forms record whole messages)
    sc_core::sc_time start;
  };

  // A FIFO in a vector, which keeps its storage: a busy direction allocates nothing per message (a
  // list allocates a node each) and an idle one holds nothing (an empty std::deque already holds a
  // 512-byte block, and a 1024-transputer network has thousands of link directions, almost all of
  // them idle). A queue holds a message or two, so popping the front moves little.
  template <class T>
  class Fifo {
   public:
    bool empty() const { return items_.empty(); }
    T& front() { return items_.front(); }
    const T& front() const { return items_.front(); }
    void push_back(T item) { items_.push_back(std::move(item)); }
    void pop_front() { items_.erase(items_.begin()); }

   private:
    std::vector<T> items_;
  };
  // What an input takes: a message, or a piece of one (see receive).
  struct Piece {
    Message message;
    bool last = true;  // the message's last byte is in it
  };

  struct ByteFault {
    bool armed = false, corrupt = false;
    std::uint8_t mask = 0;
    sc_core::sc_time at;
    FaultHit hit;
  };
  struct Stop {
    bool armed = false;
    sc_core::sc_time at;
    FaultHit hit;
    bool now() const { return armed && sim_now() >= at; }
  };

  // What a wire is carrying; its process is woken when the packet ends, except for a packet whose
  // end was settled when it started (see send_data_packet, send_ack_packet).
  enum class WirePacket { none, data, data_settled, ack, ack_settled, in_flight };

  // Every event and process of a link is named after its role and direction: SystemC would
  // otherwise generate a unique name for each (a search per name), a sixth of the set-up of a
  // 1024-transputer network.
  struct Direction {
    explicit Direction(int d);
    // What a CPU reads at every compute block (Cpu::dma_at_start, dma_at_end) comes first, so that
    // it shares cache lines instead of being spread over this 1.8 KB record.
    // A data packet whose end was settled when it started: its byte arrives at `arrival_at`,
    // counted when the next packet starts (or now, by dma_bytes).
    bool arrival_pending = false;
    DmaCount dma_sent, dma_received;  // bytes counted so far (closed forms: once settled)
    ClosedForm closed_form;
    // sending DMA
    Fifo<Message> queue;
    std::int64_t sent = 0, acked = 0;
    bool may_send = true;
    std::int64_t submitted = 0, completed = 0;  // message sequence numbers
    std::int64_t taken = 0;                     // messages an input has taken
    sc_core::sc_event sent_event, submitted_event;
    // receiving DMA
    bool armed = false;
    bool ack_owed = false;
    bool accepted_before_detect = false;
    bool receiving = false;
    bool receiver_counted = false;
    Message incoming;
    bool payload_with_sender = false;  // incoming's payload is still the queue front's
    std::int64_t received = 0;
    std::int64_t want = kWholeMessage;  // bytes the armed input takes
    std::int64_t given = 0;             // bytes of the incoming message earlier inputs took
    bool taken_in_pieces = false;       // inputs here have asked for part of a message
    Fifo<Piece> delivered;
    sc_core::sc_event delivered_event;
    // wire of this direction's data, and its pending acknowledges for the other direction
    int acks_pending = 0;
    WirePacket carrying = WirePacket::none;  // until wire_busy_until
    sc_core::sc_time packet_start;
    sc_core::sc_event wire_wake, detect_event, process_event;
    sc_core::sc_time wire_busy_until;  // end of the packet this wire carries
    sc_core::sc_time arrival_at;       // of the pending arrival
    InFlight in_flight;
    LinkActivity activity;
    // faults: on this direction's next byte, on this direction's wire, at the end it arrives at
    ByteFault byte_fault;
    bool byte_lost = false;  // the data packet on the wire now was dropped
    Stop wire_stop, deaf;
  };

  // A wire is a method process (no stack of its own, no context switch per packet), woken by its
  // wire_wake or by the end of the packet it carries.
  void on_wire(int wire);
  // Starts the wire's next packet at this very delta instead of waking its method for the next
  // one, where nothing else can change what it starts (see link_packets.cpp); false: woken as
  // usual.
  bool start_at_once(int wire);
  void finish_packet(int wire);
  bool start_packet(int wire);  // false: no wake needed (nothing sent, or its end settled)
  void carry(int wire, WirePacket packet, const sc_core::sc_time& start,
             const sc_core::sc_time& length);
  bool send_data_packet(int d);  // false: its end needs no wake
  bool data_end_settled_now(int d) const;
  void settle_arrival(int d);
  void finish_data_packet(int d, const sc_core::sc_time& start);
  bool send_ack_packet(int wire);  // false: its end needs no wake
  bool ack_end_settled_now(int wire) const;
  void finish_ack_packet(int wire, const sc_core::sc_time& start);
  void finish_in_flight(int wire);
  void release_sender(int d);
  // closed form
  bool closed_form_allowed(int d) const;
  void start_closed_form(int d);
  void on_closed_form(int d);
  void closed_form_sender_done(int d);
  void hand_over(int d);
  std::int64_t bytes_done_by(const ClosedForm& cf, const sc_core::sc_time& now) const;
  sc_core::sc_time byte_start(const ClosedForm& cf, std::int64_t k) const;  // k >= 1
  sc_core::sc_time ack_start(const ClosedForm& cf, std::int64_t k) const;   // needs cf.armed
  sc_core::sc_time sender_done_time(int d) const;
  sc_core::sc_time delivery_time(int d) const;
  std::int64_t bytes_started_by(const ClosedForm& cf, std::int64_t bytes,
                                const sc_core::sc_time& t) const;
  void record_closed_form_packets(int d, std::int64_t data_packets, std::int64_t ack_packets);
  void on_detect(int d);
  void on_ack_processed(int d);
  void on_byte_arrived(int d);
  void queue_ack(int d);
  void begin_incoming(int d);
  void take_payload(int d);
  bool input_satisfied(int d) const;
  void complete_receive(int d);
  Message take_delivered(int d);
  void count_receiver(int d);
  ProcessorActivity* end(int e) { return end_[e]; }
  std::int64_t submit(int from, Message message);  // queues it; its ticket
  void arm_input(int d, std::int64_t at_most);
  // faults and resets
  void arm_fault();
  bool lost_on_wire(int w, const sc_core::sc_time& start, const sc_core::sc_time& length);
  bool deaf_at(int arriving_direction);
  void apply_byte_fault(int d);
  void reset_output(int d);
  void reset_input(int d);
  bool faulted_ = false;
  bool packet_runs_ = true;
  int deadline_waits_ = 0;  // OutputOrFail / InputOrFail waiting on this link

  LinkConfig config_;
  LinkFidelity fidelity_;
  sc_core::sc_time bit_, data_packet_, ack_packet_, detect_delay_, process_delay_, byte_period_;
  sc_core::sc_time tick_;  // the kernel's time resolution
  std::int64_t closed_form_messages_ = 0, handovers_ = 0;
  ProcessorActivity* end_[2];
  Direction dir_[2]{Direction(0), Direction(1)};
};

}  // namespace t800
