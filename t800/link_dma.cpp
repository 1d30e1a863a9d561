// The bytes a link's DMA engines move, counted for the CPUs they take memory cycles from
// (Link::dma_bytes; t800/link.hpp, DmaCount).
#include "t800/link.hpp"

#include <algorithm>
#include <string>

namespace t800 {

using sc_core::SC_NS;
using sc_core::sc_time;
using sc_core::SC_ZERO_TIME;

// n adds of one byte at strictly increasing times, the last at `last`, all but the last before the
// current instant: the earlier ones change only the total (the last sets the latest instant).
void Link::DmaCount::add_increasing(std::int64_t n, const sc_time& last) {
  total += n - 1;
  add(1, last);
}

void Link::DmaCount::add(std::int64_t n, const sc_time& at, bool counted_first) {
  if (!counted_first && queried && at == query_at && at == sim_now()) late += n;
  total += n;
  if (at > latest_at) {
    latest_at = at;
    latest = n;
  } else if (at == latest_at) {
    latest += n;
  }
}

std::int64_t Link::dma_bytes(int e, const sc_time& now, bool including_now) const {
  const Direction& out = dir_[e];     // its data leaves through end e
  const Direction& in = dir_[1 - e];  // its data arrives at end e
  if (including_now) {
    out.dma_sent.query(now);
    in.dma_received.query(now);
  }
  std::int64_t n = including_now ? out.dma_sent.total + in.dma_received.total
                                 : out.dma_sent.before(now) + in.dma_received.before(now);
  if (now == SC_ZERO_TIME && !including_now) return n;
  // Closed forms and a settled packet's byte: the bytes started (sent) or arrived (received) by
  // now, or strictly before now.
  const sc_time until = including_now ? now : now - tick_;
  if (in.arrival_pending && in.arrival_at <= until) ++n;
  if (out.closed_form.active && !out.closed_form.sender_done)
    n += bytes_started_by(out.closed_form, out.closed_form.bytes, until);
  if (in.closed_form.active && !in.closed_form.delivered && until >= data_packet_)
    n += bytes_started_by(in.closed_form, in.closed_form.bytes, until - data_packet_);
  return n;
}

std::int64_t Link::dma_before_less_late(int e, const sc_time& now, const sc_time& t0) const {
  return dma_bytes(e, now, false) - dir_[e].dma_sent.late_at(t0) -
         dir_[1 - e].dma_received.late_at(t0);
}

}  // namespace t800
