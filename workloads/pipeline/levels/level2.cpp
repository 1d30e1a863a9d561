#include "workloads/pipeline/levels/level2.hpp"

namespace workloads::levels {

template <class T>
bool Level2<T>::round(t800sim::Process& p) {
  using RowMessage = typename M::RowMessage;
  const int e = e_;
  for (int k = 0; k < c_.n(); ++k) {
    if (!c_.shape.participates(k, e)) continue;
    const PacketValue pivot_packet = p.in(input());
    const typename M::Pivot pivot = M::pivot_of(pivot_packet);
    const std::vector<std::size_t> rows = c_.shape.rows_for(k, e);
    if (!pivot.ok) {
      // E1 tells L3; one behind the fan-in tells the fan-in, which waits for its rows.
      if (e == 0 || ends_.behind_fan_in) p.out(output(), pivot_packet, kFailLabel);
      return false;
    }
    c_.report.level2(p.now_us(), true);
    if (c_.settings.buffered) {
      eliminate_buffered(p, pivot_packet, rows);
      continue;
    }
    PacketValue first;
    if (e == 0) {
      // E1 forwards the pivot row to L3 while it takes its first row.
      std::vector<t800sim::Process::Body> branches{
          [&](t800sim::Process& q) { q.out(output(), pivot_packet, "pivot row"); }};
      if (!rows.empty()) branches.push_back([&](t800sim::Process& q) { first = q.in(input()); });
      par(p, branches);
    }
    for (std::size_t r = 0; r < rows.size(); ++r) {
      const RowMessage row =
          M::row_message_of((r == 0 && e == 0) ? std::move(first) : p.in(input()));
      elimination::Row<typename M::C> done = c_.run_piece(
          p, "eliminate", [](auto& x, auto& j1) { return elimination::eliminate(x, j1); },
          named("row", row.values), named("pivot", pivot.row));
      p.out(output(), M::to_packet(RowMessage{row.index, std::move(done)}), "row");
      c_.report.level2(p.now_us(), false);
    }
  }
  return true;
}

// One step: input, eliminator and output in PAR, joined by one-row buffers. The input process
// takes row r once the eliminator has started on row r - 1 (it then holds one row), and the
// eliminator hands row r on once the output process has taken row r - 1; the buffers are the
// processes' own variables, so handing a row on costs nothing here (as Shared).
template <class T>
void Level2<T>::eliminate_buffered(t800sim::Process& p, const PacketValue& pivot_packet,
                                   const std::vector<std::size_t>& rows) {
  using RowMessage = typename M::RowMessage;
  const typename M::Pivot pivot = M::pivot_of(pivot_packet);
  Shared& buffer = buffer_;
  const std::size_t count = rows.size();
  std::vector<PacketValue> taken(count);
  std::vector<RowMessage> done(count);
  std::size_t received = 0, started = 0, finished = 0, sent = 0;
  std::vector<t800sim::Process::Body> branches;
  if (count > 0) {
    branches.push_back([&](t800sim::Process& q) {  // input
      for (std::size_t r = 0; r < count; ++r) {
        buffer.wait_until(q, [&] { return started >= r; });
        taken[r] = q.in(input());
        ++received;
        buffer.notify();
      }
    });
    branches.push_back([&](t800sim::Process& q) {  // eliminator
      for (std::size_t r = 0; r < count; ++r) {
        buffer.wait_until(q, [&] { return received > r; });
        ++started;
        buffer.notify();
        const RowMessage row = M::row_message_of(taken[r]);
        elimination::Row<typename M::C> values = c_.run_piece(
            q, "eliminate", [](auto& x, auto& j1) { return elimination::eliminate(x, j1); },
            named("row", row.values), named("pivot", pivot.row));
        buffer.wait_until(q, [&] { return sent >= r; });
        done[r] = RowMessage{row.index, std::move(values)};
        ++finished;
        buffer.notify();
      }
    });
  }
  branches.push_back([&](t800sim::Process& q) {  // output; E1 forwards the pivot row first
    if (e_ == 0) q.out(output(), pivot_packet, "pivot row");
    for (std::size_t r = 0; r < count; ++r) {
      buffer.wait_until(q, [&] { return finished > r; });
      ++sent;
      buffer.notify();
      q.out(output(), M::to_packet(done[r]), "row");
      c_.report.level2(q.now_us(), false);
    }
  });
  par(p, branches);
}

// Recovery: checks each message's checksum, eliminates the intact rows with an intact pivot row,
// marks the others damaged, and sends every row on with its own checksum. An output level 3 does
// not take within the timeout is given up (level 3 asks for the row again), so the processor
// always comes back to take what L1 sends.
template <class T>
void Level2<T>::checked(t800sim::Process& p) {
  using CheckedRow = typename M::CheckedRow;
  const bool growth_check = c_.settings.rule.growth_check();
  auto send = [&](const typename M::CheckedValue& v, const std::string& label) {
    p.out_or_fail(c_.checked_out(ends_.to[0]), v, p.now_us() + c_.settings.timeout_us, label);
  };
  // L1 may give up a message half-way (this processor was slow, or a fault): each message says
  // what it is, so a pivot row may come where a row was due.
  typename M::CheckedPivot pivot;
  bool pivot_intact = false;
  for (;;) {
    const typename M::CheckedValue m = p.in(c_.checked_in(ends_.from[0]));
    if (M::is_pivot(m)) {
      pivot = M::checked_pivot_of(m, growth_check);
      if (pivot.stop) return;
      c_.report.level2(p.now_us(), true);
      c_.charge_checksum(p, pivot.row.size() + 1);
      pivot_intact = pivot.sum() == pivot.checksum;
      if (pivot.forward) send(M::to_checked(pivot, growth_check), "pivot row");
      continue;
    }
    const CheckedRow row = M::checked_row_of(m);
    c_.charge_checksum(p, row.values.size());
    CheckedRow done{row.step, row.index, true, {}, 0};
    if (pivot_intact && row.step == pivot.step && row.sum() == row.checksum) {
      done.bad = false;
      done.values = c_.run_piece(
          p, "eliminate", [](auto& x, auto& j1) { return elimination::eliminate(x, j1); },
          named("row", row.values), named("pivot", pivot.row));
      c_.charge_checksum(p, done.values.size());
    }
    done.checksum = done.sum();
    send(M::to_checked(done), "row");
    c_.report.level2(p.now_us(), false);
  }
}

template class Level2<float>;
template class Level2<double>;

}  // namespace workloads::levels
