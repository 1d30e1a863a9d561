// Per-processor and per-link accounting of time. A processor is, at each instant, computing (its
// CPU runs a compute block), communicating (its CPU runs communication instructions, or one of its
// link engines moves a message for one of its processes) or idle. Totals are always kept; intervals
// only when a trace asks for them (docs/architecture.md: "when no trace is asked for, nothing
// per-interval is stored").
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <systemc>

namespace t800 {

enum class ProcessorState { idle, compute, communicate };
const char* to_string(ProcessorState state);

struct Interval {
  double start_us = 0, end_us = 0;
  int state = 0;  // ProcessorState for processors, 1 = busy for link directions
  std::string label;
};

class ProcessorActivity {
 public:
  void set_cpu(ProcessorState cpu, const std::string& label = {});
  // The same, with the current simulated time given by the caller (a CPU knows it already).
  void set_cpu(ProcessorState cpu, const std::string& label, const sc_core::sc_time& now);
  void transfer_begin();
  void transfer_end();
  void keep_intervals(bool keep) { keep_intervals_ = keep; }
  // Whether a link transfer at this processor makes it busy (communicate), as the paper counts a
  // processor whose link engines work for it. A processor that executes real machine code is busy
  // only while its CPU executes: its link engines run beside it, and a process waiting for one
  // leaves the CPU idle (workloads/boot/iss_node.cpp).
  void count_transfers_as_busy(bool count) { transfers_busy_ = count; }
  void close(
      const sc_core::sc_time& end);  // settles the running state at the end of the simulation
  // Neither its CPU nor any of its link engines is working for it at this instant.
  bool idle() const { return state() == ProcessorState::idle; }
  // Adds the accounting of a stretch of work that was not simulated but is known to be identical to
  // one that was (a reused trajectory step): busy time by state, the span of work (a time < 0
  // leaves it as it is; the first busy time is only set when it is not yet), and, when intervals
  // are kept, the stretch's intervals, already placed in time. Call it while idle.
  void credit(double compute_us, double communicate_us, double first_busy_us, double last_busy_us,
              const std::vector<Interval>& intervals = {});

  double compute_us() const { return total_us_[int(ProcessorState::compute)]; }
  double communicate_us() const { return total_us_[int(ProcessorState::communicate)]; }
  double busy_us() const { return compute_us() + communicate_us(); }
  // Busy time so far, counting the state it is in up to the present simulated time (for windowed
  // measures).
  double busy_us_now() const;
  // When it first and last left the idle state (the span of its work), in microseconds.
  double first_busy_us() const { return first_busy_us_; }
  double last_busy_us() const { return last_busy_us_; }
  const std::vector<Interval>& intervals() const { return intervals_; }

 private:
  ProcessorState state() const;
  void settle(double now_us, const std::string& next_label);
  const std::string& cpu_label() const;
  const std::string& current_label() const;
  double us(const sc_core::sc_time& t);
  ProcessorState cpu_ = ProcessorState::idle;
  int transfers_ = 0;
  bool transfers_busy_ = true;
  ProcessorState current_ = ProcessorState::idle;
  // The current interval's label is `label_` while `labelled_`, else empty: a CPU alternates
  // between a block's label and none (idle between two blocks), so the string is only copied when
  // the label differs from the last one.
  std::string label_;
  bool labelled_ = false;
  // The last instant converted to microseconds (a block's end and the next one's start are one).
  sc_core::sc_time us_at_ = sc_core::SC_ZERO_TIME;
  double us_ = 0;
  double since_us_ = 0;
  double total_us_[3] = {0, 0, 0};
  double first_busy_us_ = -1, last_busy_us_ = 0;
  bool keep_intervals_ = false;
  std::vector<Interval> intervals_;
};

// One direction of a link, as the wire carrying its data sees it.
class LinkActivity {
 public:
  void packet(const sc_core::sc_time& start, const sc_core::sc_time& duration, bool data);
  // `count` packets of one duration, where no intervals are kept (so their times do not matter):
  // the busy time of `count` calls of packet(), to the bit, at the cost of one (a closed-form
  // message, t800/link.hpp).
  void packets(std::int64_t count, const sc_core::sc_time& duration);
  // Kept intervals with this message's data (since the previous message) take its label, for
  // traces.
  void message_done(std::int64_t bytes, const std::string& label);
  void keep_intervals(bool keep) { keep_intervals_ = keep; }
  bool keeps_intervals() const { return keep_intervals_; }
  // Kept intervals join packets less than `gap` apart, so a streaming message is one interval, not
  // one per packet (a long trajectory has tens of thousands of packets per step). A trace's link
  // intervals therefore span the short gaps between a message's packets; busy_us() counts the
  // packets alone.
  void merge_gaps_below(const sc_core::sc_time& gap) { merge_gap_us_ = gap.to_seconds() * 1e6; }
  // Adds the accounting of messages that were not simulated but are known to be identical to ones
  // that were (a reused trajectory step), with their intervals already placed in time when
  // intervals are kept.
  void credit(std::int64_t bytes, std::int64_t messages, double busy_us,
              const std::vector<Interval>& intervals = {});

  std::int64_t bytes() const { return bytes_; }
  std::int64_t messages() const { return messages_; }
  double busy_us() const {
    return busy_us_;
  }  // time its wire carries packets (data and acknowledges)
  const std::vector<Interval>& intervals() const { return intervals_; }

 private:
  std::int64_t bytes_ = 0, messages_ = 0;
  double busy_us_ = 0;
  bool keep_intervals_ = false;
  std::vector<Interval> intervals_;
  std::size_t unlabelled_ = 0;  // first interval not yet named after its message
  double merge_gap_us_ = 1e-9;
};

}  // namespace t800
