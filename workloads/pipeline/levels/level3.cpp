#include "workloads/pipeline/levels/level3.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "t800sim/alt.hpp"

namespace workloads::levels {

using elimination::Status;

template <class T>
bool Level3<T>::round(Process& p) {
  C bound = C(0);
  bool unstable = false;
  for (int k = 0; k < c_.n(); ++k) {
    Pivot pivot = M::pivot_of(c_.receive(p, ends_.from[0]));
    if (!pivot.ok) {
      to_l4(p, k, pivot, kFailLabel);
      return false;
    }
    if (k == 0 && c_.settings.rule.growth_check())
      bound = c_.run_piece(
          p, "bound", [&](auto& s) { return elimination::growth_bound(s, c_.settings.rule); },
          named("scale", pivot.scale));
    pivot.with_scale = false;  // L4 needs the row only
    const std::size_t r = static_cast<std::size_t>(c_.n() - 1 - k);
    if (c_.settings.overlap) {
      stream(p, k, pivot, bound, unstable);
      continue;
    }
    Rows rows(r);
    collect(p, k, pivot, unstable, rows);
    if (r == 0) continue;
    // A non-finite value: L1 now stops everybody; E1's failed pivot row ends this loop.
    return_reduced(p, k, rows, bound, unstable);
  }
  return true;
}

template <class T>
void Level3<T>::unstable_at(int k, bool& unstable) {
  if (unstable) return;
  unstable = true;
  c_.report.unstable_from(k);
}

// Step k's rows checked and, unless one is not finite (false: L1 is told to stop), sent back to L1
// as the next step's matrix.
template <class T>
bool Level3<T>::return_reduced(Process& p, int k, Rows& rows, C bound, bool& unstable) {
  const auto check = c_.run_piece(
      p, "check", [&](auto& r, auto& b) { return elimination::check_step(r, b, c_.settings.rule); },
      named("rows", rows), named("bound", bound));
  c_.report.rows_seen(elimination::largest_magnitude(rows));  // diagnostic only
  if (check.status == Status::non_finite) {
    c_.report.fail(k, Status::non_finite,
                   "level 3: a non-finite value in row " + std::to_string(check.row + 1) +
                       " of step " + std::to_string(k));
    send_back(p, typename M::ReturnedRow{false, {}}, kFailLabel);
    return false;
  }
  if (check.status == Status::unstable) unstable_at(k, unstable);
  for (std::size_t i = 0; i < rows.size(); ++i)
    send_back(p, typename M::ReturnedRow{true, std::move(rows[i]), i}, "reduced row");
  return true;
}

// One step's rows from every level-2 processor (their order on the wire is known), while the
// pivot row goes on to L4.
template <class T>
void Level3<T>::take_rows(std::vector<Process::Body>& branches, int k, Rows& rows,
                          std::function<void(std::size_t)> arrived) {
  using RowMessage = typename M::RowMessage;
  for (const Port& port : ends_.from_ports) {
    const std::vector<std::size_t> expected = c_.shape.rows_of(port.served, k);
    if (expected.empty()) continue;
    branches.push_back([this, &port, expected, &rows, arrived](Process& q) {
      for (std::size_t count = expected.size(); count > 0; --count) {
        RowMessage row = M::row_message_of(c_.receive(q, port.channel));
        if (row.index < 1 || row.index > rows.size())
          q.stop("row number " + std::to_string(row.index) + " out of range");
        rows[row.index - 1] = std::move(row.values);
        arrived(row.index - 1);
      }
    });
  }
}

template <class T>
void Level3<T>::collect(Process& p, int k, Pivot& pivot, bool unstable, Rows& rows) {
  pivot.unstable = unstable;
  std::vector<Process::Body> branches{[&](Process& q) { to_l4(q, k, pivot, "U row"); }};
  std::vector<int> arrived(rows.size(), 0);
  take_rows(branches, k, rows, [&arrived](std::size_t i) { ++arrived[i]; });
  par(p, branches);
  for (int a : arrived)
    if (a != 1) throw std::logic_error("elimination pipeline: a row did not arrive exactly once");
}

// Overlap: step k's rows go back to L1 one by one as they arrive, each checked on its own (the
// same check, row by row). A non-finite row is reported but still sent: the pipeline drains (L4
// then gives no q̈) instead of stopping level 2 mid-step.
template <class T>
void Level3<T>::stream(Process& p, int k, Pivot& pivot, C bound, bool& unstable) {
  const std::size_t r = static_cast<std::size_t>(c_.n() - 1 - k);
  Rows rows(r);
  std::vector<std::size_t> ready;  // indices in arrival order
  std::vector<Process::Body> branches{[&](Process& q) {
    pivot.unstable = unstable;
    to_l4(q, k, pivot, "U row");
  }};
  take_rows(branches, k, rows, [this, &ready](std::size_t i) {
    ready.push_back(i);
    shared_.notify();
  });
  if (r > 0)
    branches.push_back([&](Process& q) {
      for (std::size_t sent = 0; sent < r; ++sent) {
        shared_.wait_until(q, [&] { return ready.size() > sent; });
        forward(q, k, rows[ready[sent]], ready[sent], bound, unstable);
      }
    });
  par(p, branches);
}

template <class T>
void Level3<T>::forward(Process& p, int k, elimination::Row<C>& row, std::size_t i, C bound,
                        bool& unstable) {
  const Rows one{row};
  const auto check = c_.run_piece(
      p, "check", [&](auto& r, auto& b) { return elimination::check_step(r, b, c_.settings.rule); },
      named("rows", one), named("bound", bound));
  c_.report.rows_seen(elimination::largest_magnitude(one));  // diagnostic only
  if (check.status == Status::non_finite)
    c_.report.fail(k, Status::non_finite,
                   "level 3: a non-finite value in row " + std::to_string(i + 1) + " of step " +
                       std::to_string(k));
  if (check.status == Status::unstable) unstable_at(k, unstable);
  c_.send(p, ends_.back, M::to_packet(typename M::ReturnedRow{true, std::move(row), i}),
          "reduced row");
}

// ---- recovery ----

// Each step's pivot row and rows, checked, with resends of what is missing or damaged; then as in
// strict steps. A step it cannot complete ends the pipeline (Status::lost).
template <class T>
bool Level3<T>::checked(Process& p) {
  lost_.assign(std::size_t(c_.shape.m), false);
  C bound = C(0);
  bool unstable = false;
  for (int k = 0; k < c_.n(); ++k) {
    const std::size_t r = std::size_t(c_.n() - 1 - k);
    CheckedPivot pivot;
    Rows rows(r);
    if (!collect_checked(p, k, pivot, rows)) {
      c_.report.fail(
          k, Status::lost,
          "level 3: step " + std::to_string(k) + "'s rows did not all arrive intact after " +
              std::to_string(c_.shape.m + 1) +
              " requests in a row to resend them (a fault no other level-2 processor could get "
              "round, or workload.recovery_timeout_us shorter than the pipeline's own pauses)");
      send_back(p, typename M::ReturnedRow{false, {}}, kFailLabel);
      to_l4(p, k, Pivot::stop(false), kFailLabel);
      return false;
    }
    to_l4(p, k, Pivot{true, false, unstable, pivot.row, pivot.scale}, "U row");
    if (k == 0 && c_.settings.rule.growth_check())
      bound = c_.run_piece(
          p, "bound", [&](auto& s) { return elimination::growth_bound(s, c_.settings.rule); },
          named("scale", pivot.scale));
    if (r > 0 && !return_reduced(p, k, rows, bound, unstable)) {
      to_l4(p, k, Pivot::stop(false), kFailLabel);
      return false;
    }
  }
  send_back(p, typename M::ReturnedRow{true, {}, 0}, "done");  // no more resends
  return true;
}

// Step k's messages until every row (and the pivot row) is in intact, asking L1 to resend what is
// not; it gives up after m + 1 requests in a row that brought nothing.
template <class T>
bool Level3<T>::collect_checked(Process& p, int k, CheckedPivot& pivot, Rows& rows) {
  using Resend = typename M::Resend;
  const int m = c_.shape.m;
  std::vector<bool> have(rows.size() + 1, false);  // [0]: the pivot row
  int idle = 0;                                    // resend rounds in a row that brought nothing
  std::optional<Resend> request;
  for (int round = 0;; ++round) {
    std::vector<int> damaged;
    const auto before = std::count(have.begin(), have.end(), true);
    // The request goes to L1 while the rows still coming are taken: L1 may be waiting for a
    // level-2 processor that waits for level 3.
    // The first wait of a step is longer: L1 has a pivot to find before it sends anything.
    const double first_wait_us = (round == 0 ? 4 : 1) * c_.settings.timeout_us;
    auto receive = [&](Process& q) {
      receive_step(q, k, pivot, rows, have, damaged, first_wait_us);
    };
    if (request) {
      par(p, {[&](Process& q) {
                q.out(c_.checked_out(ends_.back), M::to_checked(*request), "resend");
              },
              receive});
    } else {
      receive(p);
    }
    idle = std::count(have.begin(), have.end(), true) > before ? 0 : idle + 1;
    std::vector<std::size_t> missing;
    for (std::size_t i = 0; i < have.size(); ++i)
      if (!have[i]) missing.push_back(i);
    if (missing.empty()) {
      if (round > 0)
        for (int e = 0; e < m; ++e)
          p.fault_recovered(path_through(e), "level 1 resent step " + std::to_string(k) +
                                                 "'s rows through other level-2 processors");
      return true;
    }
    const std::string what = std::to_string(missing.size()) + " of step " + std::to_string(k) +
                             "'s messages " + (damaged.empty() ? "missing" : "damaged or missing");
    for (int e = 0; e < m; ++e)
      p.fault_detected(path_through(e), "level 3 (" + what + ": checksum, ALT timeout)");
    if (idle > m) return false;
    request = Resend{missing, {}, damaged};
    for (int e = 0; e < m; ++e)
      if (lost_[std::size_t(e)]) request->lost.push_back(e);
  }
}

// Level 3's ALT (the SDK's) over the level-2 processors it still listens to, with a timer guard
// that ends the wait settings.timeout_us after the last message (first_wait_us after the start); a
// message that stops half-way (an InputOrFail guard) is given up with its processor.
template <class T>
void Level3<T>::receive_step(Process& p, int k, CheckedPivot& pivot, Rows& rows,
                             std::vector<bool>& have, std::vector<int>& damaged,
                             double first_wait_us) {
  using CheckedRow = typename M::CheckedRow;
  const auto& e_out = ends_.from;
  const int m = c_.shape.m;
  const auto ticks = std::int64_t(std::ceil(c_.settings.timeout_us / p.tick_us()));
  std::int64_t after = p.clock() + std::int64_t(std::ceil(first_wait_us / p.tick_us()));
  while (std::find(have.begin(), have.end(), false) != have.end()) {
    t800sim::Alt alt(p);
    std::optional<typename M::CheckedValue> received;
    for (int e = 0; e < m; ++e)
      alt.input_or_fail(
          c_.checked_in(e_out[std::size_t(e)]), longest_message_us_,
          [&received](std::optional<typename M::CheckedValue> v) { received = std::move(v); },
          !lost_[std::size_t(e)]);
    alt.after(after, [] {});
    const int g = alt.select();
    if (g == m) return;  // the timer: nothing more is coming
    if (!received) {
      lost_[std::size_t(g)] = true;
      continue;
    }
    after = p.clock() + ticks;
    if (M::is_pivot(*received)) {
      const CheckedPivot piv = M::checked_pivot_of(*received, c_.settings.rule.growth_check());
      if (piv.stop || piv.step != k) continue;  // a late message of an earlier step
      c_.charge_checksum(p, piv.row.size() + 1);
      if (piv.sum() != piv.checksum) {
        damaged.push_back(g);
        continue;
      }
      pivot = piv;
      have[0] = true;
      continue;
    }
    const CheckedRow row = M::checked_row_of(*received);
    if (row.step != k) continue;
    c_.charge_checksum(p, row.values.size());
    if (row.bad || row.sum() != row.checksum || row.index < 1 || row.index > rows.size()) {
      damaged.push_back(g);
      continue;
    }
    rows[row.index - 1] = row.values;
    have[row.index] = true;
  }
}

// A reduced row (or a failed step's word, or recovery's "done") to L1: a packet, or with recovery
// a checked packet (the channel also carries L3's resend requests).
template <class T>
void Level3<T>::send_back(Process& p, const typename M::ReturnedRow& row, const char* label) const {
  if (c_.settings.recovery)
    p.out(c_.checked_out(ends_.back), M::to_checked(row), label);
  else
    c_.send(p, ends_.back, M::to_packet(row), label);
}

template <class T>
void Level3<T>::to_l4(Process& p, int k, const Pivot& pivot, const char* label) const {
  c_.send(p, ends_.to[0], M::to_packet(k, pivot), label);
}

template <class T>
std::vector<std::string> Level3<T>::path_through(int e) const {
  return Context<T>::path(true, e, true);
}

template class Level3<float>;
template class Level3<double>;

}  // namespace workloads::levels
