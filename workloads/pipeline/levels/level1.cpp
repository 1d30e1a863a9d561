#include "workloads/pipeline/levels/level1.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>

namespace workloads::levels {

template <class T>
bool Level1<T>::round(Process& p) {
  const auto input = M::system_of(p.in(t800sim::In<typename M::System>(ends_.from[0])));
  if (!input) {
    send_stop(p, 0, true);
    return false;
  }
  const elimination::LinearSystem<C>& system = *input;
  c_.report.input_scale(elimination::largest_magnitude(elimination::augment(system.a, system.b)));
  c_.report.outcome.start_us = p.now_us();
  const auto& rule = c_.settings.rule;
  Rows m = c_.run_piece(
      p, "augment", [](auto& a, auto& b) { return elimination::augment(a, b); },
      named("A", system.a), named("b", system.b));
  const C scale =
      rule.needs_scale()
          ? c_.run_piece(
                p, "scale", [](auto& a) { return elimination::matrix_scale(a); }, named("m", m))
          : C(0);
  const C limit = c_.run_piece(
      p, "limit", [&](auto& s) { return elimination::pivot_limit(s, rule); },
      named("scale", scale));
  if (!c_.settings.overlap) return steps(p, std::move(m), scale, limit);
  // Overlap: a receiver stores the rows L3 streams back while the steps go on.
  bool go = true;
  p.par({[&](Process& q) { go = steps(q, std::move(m), scale, limit); },
         [this](Process& q) { receive_streamed(q); }});
  return go;
}

// The n steps of one system; false when the pipeline stops.
template <class T>
bool Level1<T>::steps(Process& p, Rows first, C scale, C limit) {
  const auto& rule = c_.settings.rule;
  const bool recovery = c_.settings.recovery;
  PipelineOutcome& outcome = c_.report.outcome;
  const int n = c_.n();
  matrices_.assign(std::size_t(n), Rows());
  for (int k = 1; k < n; ++k) matrices_[std::size_t(k)].resize(std::size_t(n - k));
  arrived_.assign(std::size_t(n), 0);
  handed_ = 0;
  stopped_ = false;
  matrices_[0] = std::move(first);
  arrived_[0] = n;
  std::vector<int> order(static_cast<std::size_t>(n));
  std::iota(order.begin(), order.end(), 0);
  for (int k = 0; k < n; ++k) {
    Rows& m = matrices_[std::size_t(k)];
    if (k > 0 && !(recovery ? next_matrix_checked(p, k) : next_matrix(p, k, limit)))
      return stop(p, k);
    outcome.step_start_us.push_back(p.now_us());
    auto step = c_.run_piece(
        p, "pivot",
        [&](auto& rows, auto& rows_order, auto& l) {
          return elimination::pivot_step(rows, rows_order, rule, l);
        },
        named("m", m), named("order", order), named("limit", limit));
    if (!step.found) {
      c_.report.fail(k, elimination::pivot_failure(m),
                     "level 1: no usable pivot at step " + std::to_string(k));
      return stop(p, k);
    }
    outcome.pivot_rows.push_back(order[0]);
    if (step.interchanged) ++outcome.interchanges;
    const C step_scale = k == 0 ? scale : C(0);
    if (recovery) {
      // The scale only where it travels (step 0, for L3's growth check).
      pivot_ = typename M::CheckedPivot{k, false, false, std::move(step.normalised),
                                        rule.growth_check() ? step_scale : C(0)};
      std::vector<std::size_t> all(std::size_t(n - k));  // the pivot row (0) and rows 1 .. n-1-k
      std::iota(all.begin(), all.end(), std::size_t(0));
      hand_out_checked(p, k, all, {});
    } else {
      typename M::Pivot pivot{true, false, false, std::move(step.normalised), step_scale};
      pivot.with_scale = k == 0 && rule.growth_check();  // L3's growth check needs it
      hand_out(p, k, pivot, m);
    }
    ++handed_;
    shared_.notify();
    order.erase(order.begin());
  }
  if (recovery) {
    if (!next_matrix_checked(p, n)) return stop(p, n);  // resends of the last step
    stop_level2(p);
  }
  return true;
}

template <class T>
bool Level1<T>::stop(Process& p, int k) {
  stopped_ = true;
  shared_.notify();
  if (c_.settings.recovery) {
    stop_level2(p);
    return false;
  }
  return send_stop(p, k, false);
}

// Step k's matrix: strict, all of it from L3; overlap, the rows the pivot choice reads (simple
// interchange with a usable first pivot: that row only; otherwise every row).
template <class T>
bool Level1<T>::next_matrix(Process& p, int k, C limit) {
  Rows& m = matrices_[std::size_t(k)];
  if (!c_.settings.overlap) return receive_reduced(p, std::size_t(c_.n() - k), m);
  const int rows = c_.n() - k;
  shared_.wait_until(p, [&] { return !m[0].empty(); });
  if (c_.settings.rule.pivoting == elimination::Pivoting::partial || !usable(m[0][0], limit))
    shared_.wait_until(p, [&] { return arrived_[std::size_t(k)] == rows; });
  return true;
}

// The simple-interchange test of elimination::first_usable_pivot, on values (no work counted:
// pivot_step repeats it and is charged for it).
template <class T>
bool Level1<T>::usable(const C& lead, const C& limit) const {
  const long double v = elimination::value_of(lead);
  return c_.settings.rule.threshold > 0 ? std::abs(v) > elimination::value_of(limit) : v != 0;
}

// Overlap: the receiver. Step s's rows come back once step s - 1 was handed out, in any order.
template <class T>
void Level1<T>::receive_streamed(Process& p) {
  for (int s = 1; s < c_.n(); ++s) {
    shared_.wait_until(p, [&] { return handed_ >= s || stopped_; });
    if (handed_ < s) return;
    Rows& m = matrices_[std::size_t(s)];
    for (int r = 0; r < c_.n() - s; ++r) {
      auto row = M::returned_row_of(c_.receive(p, ends_.back));
      if (row.index >= m.size())
        p.stop("row number " + std::to_string(row.index) + " out of range");
      m[row.index] = std::move(row.values);
      ++arrived_[std::size_t(s)];
      shared_.notify();
    }
  }
}

// Overlap: step k's row i is in L1's memory (strict: always).
template <class T>
void Level1<T>::await_row(Process& p, int k, std::size_t i) {
  if (c_.settings.overlap)
    shared_.wait_until(p, [&] { return !matrices_[std::size_t(k)][i].empty(); });
}

// The n - k rows of the reduced matrix from L3 (the first tells whether the step failed).
template <class T>
bool Level1<T>::receive_reduced(Process& p, std::size_t rows, Rows& m) {
  Rows reduced;
  for (std::size_t i = 0; i < rows; ++i) {
    auto row = M::returned_row_of(c_.receive(p, ends_.back));
    if (!row.ok) return false;  // strict: rows come in order
    reduced.push_back(std::move(row.values));
  }
  m = std::move(reduced);
  return true;
}

// Every level-2 processor waiting in step k gets a stop (failed) pivot message; E1 passes it on,
// so L3 and L4 stop too and nobody is left blocked. Serving system after system, the processors
// with no rows left in step k already wait for the next system's step 0: they get one too.
// Returns false: L1 stops.
template <class T>
bool Level1<T>::send_stop(Process& p, int k, bool finish) {
  std::vector<Process::Body> branches;
  const bool next_round_waits = c_.serve == Serve::until_finish && k > 0;
  for (const Port& port : ends_.to_ports)
    if (!c_.shape.takers(port.served, k).empty() || next_round_waits)
      branches.push_back([this, k, &port, finish](Process& q) {
        c_.send(q, port.channel, M::to_packet(k, M::Pivot::stop(finish)), kFailLabel);
      });
  par(p, branches);
  return false;
}

// The pivot row and the rows of step k down every channel at once (one branch per channel).
template <class T>
void Level1<T>::hand_out(Process& p, int k, const typename M::Pivot& pivot, const Rows& m) {
  std::vector<Process::Body> branches;
  for (const Port& port : ends_.to_ports) {
    if (c_.shape.takers(port.served, k).empty()) continue;
    branches.push_back([this, k, &port, &pivot, &m](Process& q) {
      c_.send(q, port.channel, M::to_packet(k, pivot), "pivot row");
      for (std::size_t i : c_.shape.rows_of(port.served, k)) {
        await_row(q, k, i);
        c_.send(q, port.channel, M::to_packet(typename M::RowMessage{i, m[i]}), "row");
      }
    });
  }
  par(p, branches);
}

// ---- recovery ----

// Step k's `rows` (of matrices_[k]; 0 = the pivot row, for L3) through the level-2 processors it
// still uses, avoiding `avoid` if it can. First handing-out: the round-robin of the shape while no
// processor has failed; a resend, or after a failure: round-robin over the others. The pivot row
// goes to each that gets rows, and to the first, which forwards it to L3.
template <class T>
void Level1<T>::hand_out_checked(Process& p, int k, std::vector<std::size_t> rows,
                                 const std::vector<int>& avoid) {
  const PipelineShape& shape = c_.shape;
  std::vector<int> live, preferred;
  for (int e = 0; e < shape.m; ++e)
    if (!unused_[std::size_t(e)]) live.push_back(e);
  for (int e : live)
    if (std::find(avoid.begin(), avoid.end(), e) == avoid.end()) preferred.push_back(e);
  if (!preferred.empty()) live = preferred;
  if (live.empty()) return;  // nobody left: level 3 gives up
  const bool forward = std::find(rows.begin(), rows.end(), 0) != rows.end();
  rows.erase(std::remove(rows.begin(), rows.end(), 0), rows.end());
  const bool as_shaped =
      avoid.empty() && std::find(unused_.begin(), unused_.end(), true) == unused_.end();
  std::vector<std::vector<std::size_t>> given(std::size_t(shape.m));
  for (std::size_t j = 0; j < rows.size(); ++j)
    given[std::size_t(as_shaped ? shape.owner(rows[j]) : live[j % live.size()])].push_back(rows[j]);
  pivot_.step = k;
  pivot_.checksum = pivot_.sum();
  c_.charge_checksum(p, pivot_.row.size() + 1);
  const bool growth_check = c_.settings.rule.growth_check();
  std::vector<Process::Body> branches;
  for (int e : live) {
    const bool forwarder = forward && e == live.front();
    if (given[std::size_t(e)].empty() && !forwarder) continue;
    branches.push_back([this, e, k, forwarder, growth_check, &given](Process& q) {
      typename M::CheckedPivot pivot = pivot_;
      pivot.forward = forwarder;
      const auto c = c_.checked_out(ends_.to[std::size_t(e)]);
      if (!q.out_or_fail(c, M::to_checked(pivot, growth_check), deadline(q), "pivot row")) {
        unused_[std::size_t(e)] = true;
        return;
      }
      for (std::size_t i : given[std::size_t(e)]) {
        typename M::CheckedRow row{k, i, false, matrices_[std::size_t(k)][i], 0};
        row.checksum = row.sum();
        c_.charge_checksum(q, row.values.size());
        if (!q.out_or_fail(c, M::to_checked(row), deadline(q), "row")) {
          unused_[std::size_t(e)] = true;
          return;
        }
      }
    });
  }
  par(p, branches);
}

// Step k's matrix from L3, serving L3's requests to resend step k - 1's rows first.
template <class T>
bool Level1<T>::next_matrix_checked(Process& p, int k) {
  using ReturnedRow = typename M::ReturnedRow;
  const auto back = c_.checked_in(ends_.back);
  for (;;) {
    const typename M::CheckedValue m = p.in(back);
    if (M::is_resend(m)) {
      const typename M::Resend request = M::resend_of(m);
      for (int e : request.lost)
        if (e >= 0 && e < c_.shape.m) unused_[std::size_t(e)] = true;
      std::vector<std::size_t> rows;
      for (std::size_t i : request.rows)
        if (i < std::size_t(c_.n() - (k - 1))) rows.push_back(i);
      hand_out_checked(p, k - 1, rows, request.avoid);
      continue;
    }
    ReturnedRow first = M::returned_row_of(m);
    if (!first.ok) return false;
    if (k == c_.n()) return true;  // L3's word that the last step is complete
    Rows& reduced = matrices_[std::size_t(k)];
    reduced = {std::move(first.values)};
    for (int i = 1; i < c_.n() - k; ++i) {
      ReturnedRow row = M::returned_row_of(p.in(back));
      if (!row.ok) return false;
      reduced.push_back(std::move(row.values));
    }
    return true;
  }
}

// Every level-2 processor ends, also one L1 gave up (it may only have been slow). One that does not
// take its stop is unreachable: a fault nothing depended on any more.
template <class T>
void Level1<T>::stop_level2(Process& p) {
  std::vector<Process::Body> branches;
  for (int e = 0; e < c_.shape.m; ++e)
    branches.push_back([this, e](Process& q) {
      typename M::CheckedPivot stop;
      stop.stop = true;
      if (q.out_or_fail(c_.checked_out(ends_.to[std::size_t(e)]), M::to_checked(stop, false),
                        deadline(q), "stop"))
        return;
      const std::vector<std::string> path = Context<T>::path(true, e, false);
      if (q.fault_detected(path, "level 1 (its stop was not taken)") > 0)
        q.fault_recovered(path, "none needed: the solve no longer depended on it");
    });
  par(p, branches);
}

template class Level1<float>;
template class Level1<double>;

}  // namespace workloads::levels
