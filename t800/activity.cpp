#include "t800/activity.hpp"

#include <algorithm>
#include <stdexcept>

#include "t800/repeated_sum.hpp"
#include "t800/sim_now.hpp"

namespace t800 {

namespace {
const std::string kNoLabel;
double now_us() {
  return sim_now().to_seconds() * 1e6;
}
}  // namespace

const char* to_string(ProcessorState state) {
  switch (state) {
    case ProcessorState::idle:
      return "idle";
    case ProcessorState::compute:
      return "compute";
    case ProcessorState::communicate:
      return "communicate";
  }
  return "?";
}

ProcessorState ProcessorActivity::state() const {
  if (cpu_ == ProcessorState::compute) return ProcessorState::compute;
  if (cpu_ == ProcessorState::communicate || (transfers_busy_ && transfers_ > 0))
    return ProcessorState::communicate;
  return ProcessorState::idle;
}

const std::string& ProcessorActivity::current_label() const {
  return labelled_ ? label_ : kNoLabel;
}

double ProcessorActivity::us(const sc_core::sc_time& t) {
  if (t != us_at_) {
    us_at_ = t;
    us_ = t.to_seconds() * 1e6;
  }
  return us_;
}

// `next_label`: the CPU's label while it works (an interval is split where it changes), else empty.
void ProcessorActivity::settle(double t, const std::string& next_label) {
  const ProcessorState next = state();
  if (next == current_ && next_label == current_label()) return;
  const double elapsed = t - since_us_;
  if (current_ != ProcessorState::idle) {
    total_us_[int(current_)] += elapsed;
    last_busy_us_ = t;
    if (keep_intervals_ && elapsed > 0)
      intervals_.push_back({since_us_, t, int(current_), current_label()});
  }
  if (next != ProcessorState::idle && first_busy_us_ < 0) first_busy_us_ = t;
  current_ = next;
  labelled_ = !next_label.empty();
  if (labelled_ && label_ != next_label) label_ = next_label;
  since_us_ = t;
}

double ProcessorActivity::busy_us_now() const {
  return busy_us() + (current_ != ProcessorState::idle ? now_us() - since_us_ : 0.0);
}

void ProcessorActivity::set_cpu(ProcessorState cpu, const std::string& label) {
  set_cpu(cpu, label, sim_now());
}

void ProcessorActivity::set_cpu(ProcessorState cpu, const std::string& label,
                                const sc_core::sc_time& now) {
  cpu_ = cpu;
  settle(us(now), cpu == ProcessorState::idle ? kNoLabel : label);
}

// While the CPU works the current interval is its own, so its label is the CPU's.
const std::string& ProcessorActivity::cpu_label() const {
  return cpu_ == ProcessorState::idle ? kNoLabel : current_label();
}

void ProcessorActivity::transfer_begin() {
  ++transfers_;
  settle(us(sim_now()), cpu_label());
}

void ProcessorActivity::transfer_end() {
  --transfers_;
  settle(us(sim_now()), cpu_label());
}

void ProcessorActivity::close(const sc_core::sc_time& end) {
  cpu_ = ProcessorState::idle;
  transfers_ = 0;
  settle(end.to_seconds() * 1e6, kNoLabel);
}

void ProcessorActivity::credit(double compute_us, double communicate_us, double first_busy_us,
                               double last_busy_us, const std::vector<Interval>& intervals) {
  total_us_[int(ProcessorState::compute)] += compute_us;
  total_us_[int(ProcessorState::communicate)] += communicate_us;
  if (first_busy_us >= 0 && first_busy_us_ < 0) first_busy_us_ = first_busy_us;
  if (last_busy_us >= 0 && last_busy_us > last_busy_us_) last_busy_us_ = last_busy_us;
  if (keep_intervals_) intervals_.insert(intervals_.end(), intervals.begin(), intervals.end());
}

void LinkActivity::packet(const sc_core::sc_time& start, const sc_core::sc_time& duration,
                          bool data) {
  const double d = duration.to_seconds() * 1e6;
  busy_us_ += d;
  if (keep_intervals_) {
    const double s = start.to_seconds() * 1e6;
    // Packets closer than the merge gap join one interval (merge_gaps_below).
    if (!intervals_.empty() && intervals_.back().end_us >= s - merge_gap_us_ &&
        s + d >= intervals_.back().start_us - merge_gap_us_) {
      intervals_.back().start_us = std::min(intervals_.back().start_us, s);
      intervals_.back().end_us = std::max(intervals_.back().end_us, s + d);
      if (data && intervals_.back().label == "ack") intervals_.back().label = "data";
    } else {
      intervals_.push_back({s, s + d, 1, data ? "data" : "ack"});
    }
  }
}

void LinkActivity::packets(std::int64_t count, const sc_core::sc_time& duration) {
  if (keep_intervals_)
    throw std::logic_error(
        "LinkActivity::packets: intervals are kept, so every packet needs its time");
  busy_us_ = add_repeatedly(busy_us_, duration.to_seconds() * 1e6, count);
}

void LinkActivity::message_done(std::int64_t bytes, const std::string& label) {
  bytes_ += bytes;
  ++messages_;
  if (!keep_intervals_) return;
  // Only now is the message known: its data packets have all been sent once its last ack is in.
  for (std::size_t i = unlabelled_; i < intervals_.size(); ++i)
    if (intervals_[i].label == "data" && !label.empty()) intervals_[i].label = label;
  unlabelled_ = intervals_.size();
}

void LinkActivity::credit(std::int64_t bytes, std::int64_t messages, double busy_us,
                          const std::vector<Interval>& intervals) {
  bytes_ += bytes;
  messages_ += messages;
  busy_us_ += busy_us;
  if (!keep_intervals_) return;
  intervals_.insert(intervals_.end(), intervals.begin(), intervals.end());
  unlabelled_ = intervals_.size();
}

}  // namespace t800
