// Gaussian elimination of D q̈ = τ − (C + h) on the augmented matrix [A | b], written as the pieces
// the four levels of the paper's pipeline (Fig. 7) run, so that the pipeline and the sequential
// solver execute the same operations in the same order and agree to the last bit:
//   level 1  augment, matrix_scale, pivot_step (check the pivot, interchange, normalise the row)
//   level 2  eliminate (one row: J_k <- J_k - J_k1 J_1, J_1 already normalised)
//   level 3  check_step (every row arrived and is finite; pivot growth against a limit)
//   level 4  back_substitute
// Templated on the scalar: float and double are REAL32 and REAL64, long double is the reference,
// dynamics::Counted<T> counts the work (work.hpp). Generic n; the paper's system is 6 x 6.
//
// A reduced system at step k is kept as n - k rows of n + 1 - k values: the leading column (the
// one being eliminated), the rest of the matrix, and the right-hand side last. The normalised pivot
// row drops its leading 1 (n - k values); it is row k of the unit upper-triangular U that level 4
// back-substitutes.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "workloads/elimination/work.hpp"

namespace elimination {

enum class Pivoting {
  simple,   // the paper: take the first row whose leading entry is usable (non-zero)
  partial,  // the largest leading entry in magnitude
};
const char* to_string(Pivoting pivoting);
std::optional<Pivoting> parse_pivoting(std::string_view text);  // "simple" | "partial"

struct PivotRule {
  Pivoting pivoting = Pivoting::simple;
  // A pivot p is unusable when |p| <= threshold * scale, scale = max |a_ij| of the input matrix.
  // 0 is the paper's rule: interchange only when the pivot is exactly zero. A positive threshold
  // makes simple interchange skip tiny non-zero pivots too (and makes both strategies declare a
  // column whose best entry is that small singular).
  double threshold = 0;
  // Level 3 flags the result as unstable when the pivot growth max_k max_ij |a(k)_ij| / scale
  // exceeds this; 0 turns the check off. The error of elimination grows with this factor
  // (Wilkinson), so it is the signal that a non-zero but tiny pivot has ruined the result.
  double growth_limit = 0;

  bool growth_check() const { return growth_limit > 0; }
  // The scale max |a_ij| is formed (on level 1) only when something uses it.
  bool needs_scale() const { return threshold > 0 || growth_check(); }
};

enum class Status {
  ok,          // solved
  unstable,    // solved, but the pivot growth exceeded PivotRule::growth_limit: treat as suspect
  no_pivot,    // a step found no usable pivot (singular to the threshold, or an exact zero column)
  non_finite,  // a NaN or infinity appeared
  lost,        // a row never arrived intact (the pipeline's recovery could not mend a fault)
};
const char* to_string(Status status);
inline bool solved(Status status) {
  return status == Status::ok || status == Status::unstable;
}

template <class S>
using Row = std::vector<S>;
template <class S>
using Rows = std::vector<Row<S>>;

// The value of a scalar as long double (exact for float, double and long double).
template <class S>
long double value_of(const S& x) {
  if constexpr (dynamics::is_counted_v<S>) {
    return static_cast<long double>(x.value());
  } else {
    return static_cast<long double>(x);
  }
}

template <class S>
bool is_finite(const S& x) {
  return std::isfinite(value_of(x));
}

// ---- Level 1 ----

// [A | b]: the host sends A and b; level 1 copies b into the last column of its rows.
template <class S>
Rows<S> augment(const Rows<S>& a, const Row<S>& b) {
  if (a.empty() || b.size() != a.size())
    throw std::invalid_argument("elimination: A must be n x n and b of length n, n >= 1");
  Rows<S> m = a;
  for (std::size_t i = 0; i < m.size(); ++i) {
    if (m[i].size() != a.size()) throw std::invalid_argument("elimination: A is not square");
    m[i].emplace_back();  // the column b goes into
    occam::declare(m[i], "row");
  }
  for (std::size_t i : occam::seq<S>(m.size())) m[i].back() = b[i];
  const long n = static_cast<long>(a.size());
  note_indexed<S>(2 * n);
  dynamics::note_loads<S>(n);
  dynamics::note_stores<S>(n);
  return m;
}

// max |a_ij| over the matrix part (not b): the scale of the threshold and of the growth check.
// The running maximum stays on the FPU stack, so the (data-dependent) updates cost nothing extra.
template <class S>
S matrix_scale(const Rows<S>& m) {
  S largest(0);
  const std::size_t columns = m.front().size() - 1;
  for (std::size_t i : occam::seq<S>(m.size())) {
    for (std::size_t j : occam::seq<S>(columns)) {
      const S v = magnitude(m[i][j]);
      if (v > largest) largest = v;
    }
  }
  const long elements = static_cast<long>(m.size() * columns);
  note_indexed<S>(elements);
  dynamics::note_loads<S>(elements);
  note_compared<S>(elements);
  return largest;
}

// threshold * scale, formed once on level 1 (nothing to form for the paper's rule, threshold 0).
template <class S>
S pivot_limit(const S& scale, const PivotRule& rule) {
  if (rule.threshold <= 0) return S(0);
  dynamics::note_loads<S>(1);
  return dynamics::as_scalar<S>(rule.threshold) * scale;
}

struct PivotChoice {
  bool found = false;
  std::size_t row = 0;  // index in the reduced system
};

// Simple interchange: the first row whose leading entry is usable. With the paper's rule (threshold
// 0) that is `p <> 0`, one comparison and no absolute value. The search stops at the first usable
// row, so its cost depends on the data (one row tested in the common case).
template <class S>
PivotChoice first_usable_pivot(const Rows<S>& m, const PivotRule& rule, const S& limit) {
  PivotChoice choice;
  long tested = 0;
  for (std::size_t i : occam::seq<S>(m.size())) {
    ++tested;
    const S& lead = m[i][0];
    const bool usable = rule.threshold > 0 ? magnitude(lead) > limit : lead != S(0);
    if (usable) {
      choice = {true, i};
      break;
    }
  }
  note_indexed<S>(tested);
  dynamics::note_loads<S>(tested);
  note_compared<S>(tested);
  return choice;
}

// Partial pivoting: the largest leading entry in magnitude (the first of equals); every row is
// tested, so the cost does not depend on the data (except the interchange that may follow).
template <class S>
PivotChoice largest_pivot(const Rows<S>& m, const S& limit) {
  std::size_t best = 0;
  S best_magnitude = magnitude(m[0][0]);
  for (std::size_t i : occam::seq<S>(1, m.size() - 1)) {
    const S v = magnitude(m[i][0]);
    if (v > best_magnitude) {
      best = i;
      best_magnitude = v;
    }
  }
  const long rows = static_cast<long>(m.size());
  note_indexed<S>(rows);
  dynamics::note_loads<S>(rows);
  note_compared<S>(rows);  // rows - 1 in the loop, and the usability test below
  return {best_magnitude > limit, best};
}

template <class S>
PivotChoice choose_pivot(const Rows<S>& m, const PivotRule& rule, const S& limit) {
  if (m.empty()) return {};
  return rule.pivoting == Pivoting::partial ? largest_pivot(m, limit)
                                            : first_usable_pivot(m, rule, limit);
}

// Level 1 keeps its rows behind an index vector (occam arrays cannot be swapped): an interchange
// swaps two indices, three integer moves. Costs nothing when the pivot is already in place.
template <class S>
void interchange(Rows<S>& m, std::vector<int>& order, std::size_t row) {
  if (row == 0) return;
  std::swap(m[0], m[row]);
  std::swap(order[0], order[row]);
  note_moves<S>(3);
  note_indexed<S>(2);
}

// The pivot row divided by its leading entry, "dividing the whole row by the first entry" (the
// paper); the leading 1 is not kept.
template <class S>
Row<S> normalise(const Row<S>& pivot) {
  const S p = pivot[0];
  Row<S> out(pivot.size() - 1);
  occam::declare(out, "out");
  // One PROC normalises the pivot row of every step: the row's length is a variable.
  const occam::CountVariable<S> length(out.size(), "n");
  for (std::size_t j : occam::seq<S>(1, length)) out[j - 1] = pivot[j] / p;
  const long n = static_cast<long>(out.size());
  note_indexed<S>(1 + 2 * n);
  dynamics::note_loads<S>(1 + 2 * n);  // p once, then row[j] and p (the FPU stack is 3 deep)
  dynamics::note_stores<S>(1 + n);
  return out;
}

// One step of level 1 on the reduced system `m` (whose original row numbers are `order`).
template <class S>
struct PivotStep {
  bool found = false;
  bool interchanged = false;
  long double pivot = 0;  // the pivot's value (diagnostic, not part of the computation)
  Row<S> normalised;      // row k of U (without its 1) and the transformed right-hand side
};

template <class S>
PivotStep<S> pivot_step(Rows<S>& m, std::vector<int>& order, const PivotRule& rule,
                        const S& limit) {
  PivotStep<S> step;
  const PivotChoice choice = choose_pivot(m, rule, limit);
  if (!choice.found) return step;
  step.found = true;
  step.interchanged = choice.row != 0;
  interchange(m, order, choice.row);
  step.pivot = value_of(m[0][0]);
  step.normalised = normalise(m[0]);
  return step;
}

// ---- Level 2 ----

// J_k <- J_k - J_k1 J_1 with J_1 normalised (M_k1 = J_k1 / J_11 = J_k1); the leading zero is not
// kept. The FPU's error flag is tested once at the end (level 3 sees it in the row's status word).
template <class S>
Row<S> eliminate(const Row<S>& row, const Row<S>& pivot) {
  if (row.size() != pivot.size() + 1)
    throw std::invalid_argument("elimination: row and pivot row lengths do not match");
  const S multiplier = row[0];
  Row<S> out(pivot.size());
  occam::declare(out, "out");
  // One PROC eliminates the rows of every step: the row's length is a variable.
  const occam::CountVariable<S> length(pivot.size(), "n");
  for (std::size_t j : occam::seq<S>(length)) out[j] = row[j + 1] - multiplier * pivot[j];
  const long n = static_cast<long>(out.size());
  note_indexed<S>(1 + 3 * n);
  dynamics::note_loads<S>(1 + 3 * n);  // the multiplier once, then row[j], multiplier, pivot[j]
  dynamics::note_stores<S>(1 + n);
  note_error_check<S>();
  return out;
}

// ---- Level 3 ----

template <class S>
struct StepCheck {
  Status status = Status::ok;  // ok, unstable (growth above the bound) or non_finite
  std::size_t row = 0;         // the first non-finite row
  S largest = S(0);            // max |a(k+1)_ij| over the matrix part of the reduced system
};

// Level 1 sends the scale with the first pivot row; level 3 forms the bound once.
template <class S>
S growth_bound(const S& scale, const PivotRule& rule) {
  if (!rule.growth_check()) return S(std::numeric_limits<double>::infinity());
  dynamics::note_loads<S>(1);
  return dynamics::as_scalar<S>(rule.growth_limit) * scale;
}

// Every row arrived with a clean status word (the FPU error flag of its eliminator), and, when the
// growth check is on, the largest entry of the new reduced matrix against the bound. Non-finite
// wins over unstable.
template <class S>
StepCheck<S> check_step(const Rows<S>& rows, const S& bound, const PivotRule& rule) {
  StepCheck<S> check;
  // Each row's status word (its eliminator's FPU error flag): one test per row.
  for (std::size_t i : occam::seq<S>(rows.size())) {
    note_tests<S>(1);
    bool clean = true;
    for (const S& x : rows[i]) clean = clean && is_finite(x);
    if (!clean && check.status == Status::ok) {
      check.status = Status::non_finite;
      check.row = i;
    }
  }
  if (!rule.growth_check()) return check;
  // No rows (the one step of a 1x1 system): nothing grew.
  const std::size_t columns = rows.empty() ? 0 : rows.front().size() - 1;
  for (std::size_t i : occam::seq<S>(rows.size())) {
    for (std::size_t j : occam::seq<S>(columns)) {
      const S v = magnitude(rows[i][j]);
      if (v > check.largest) check.largest = v;
    }
  }
  const long elements = static_cast<long>(rows.size() * columns);
  note_indexed<S>(elements);
  dynamics::note_loads<S>(elements);
  note_compared<S>(elements);
  note_tests<S>(1);  // the growth bound
  if (check.status == Status::ok && check.largest > bound) check.status = Status::unstable;
  return check;
}

// max |a_ij| over the matrix part of rows (not the right-hand side), for diagnostics: not part of
// any level's work, so not counted.
template <class S>
long double largest_magnitude(const Rows<S>& rows) {
  long double largest = 0;
  for (const Row<S>& row : rows)
    for (std::size_t j = 0; j + 1 < row.size(); ++j)
      largest = std::max(largest, std::fabs(value_of(row[j])));
  return largest;
}

// ---- Level 4 ----

// x from the unit upper-triangular rows U[k] = (u_k,k+1 ... u_k,n-1, c_k):
// x_k = c_k - sum_{j = k+1 .. n-1} u_kj x_j, j ascending.
template <class S>
Row<S> back_substitute(const Rows<S>& upper) {
  const std::size_t n = upper.size();
  Row<S> x(n);
  occam::declare(x, "x");
  for (std::size_t i : occam::seq<S>(n)) {  // k = n-1 .. 0
    const std::size_t k = n - 1 - i;
    const Row<S>& u = upper[k];
    S sum = u.back();
    for (std::size_t j : occam::seq<S>(k + 1, n - 1 - k)) sum = sum - u[j - k - 1] * x[j];
    x[k] = sum;
  }
  const long products = static_cast<long>(n * (n - 1) / 2);
  note_indexed<S>(2 * products + 2 * static_cast<long>(n));
  dynamics::note_loads<S>(2 * products + static_cast<long>(n));
  dynamics::note_stores<S>(static_cast<long>(n));
  note_error_check<S>();  // the FPU error flag, once
  return x;
}

// ---- The sequential solver: the same pieces, in the pipeline's order ----

template <class S>
struct Solution {
  Status status = Status::ok;
  int step = -1;                // the step that failed, or first exceeded the growth limit
  int row = -1;                 // the original row involved in a non-finite failure
  Row<S> x;                     // empty unless solved(status)
  std::vector<int> pivot_rows;  // the original row of each step's pivot
  int interchanges = 0;
  long double growth = 1;          // max_k max_ij |a(k)_ij| / max_ij |a_ij|
  long double smallest_pivot = 0;  // min_k |pivot_k| / scale
};

// Applies level 3's verdict on one step to the solution; returns false when the solve must stop.
template <class S>
bool record_check(Solution<S>& s, const StepCheck<S>& check, const std::vector<int>& order,
                  int step) {
  if (check.status == Status::non_finite) {
    s.status = Status::non_finite;
    s.step = step;
    s.row = order[check.row];
    return false;
  }
  if (check.status == Status::unstable && s.status == Status::ok) {
    s.status = Status::unstable;
    s.step = step;
  }
  return true;
}

template <class S>
void record_pivot(Solution<S>& s, const PivotStep<S>& p, int original_row, long double scale) {
  s.pivot_rows.push_back(original_row);
  if (p.interchanged) ++s.interchanges;
  const long double relative = scale > 0 ? std::fabs(p.pivot) / scale : 0;
  if (s.pivot_rows.size() == 1 || relative < s.smallest_pivot) s.smallest_pivot = relative;
}

// A failed pivot search: no usable pivot, unless the column holds a NaN or infinity.
template <class S>
Status pivot_failure(const Rows<S>& m) {
  for (const Row<S>& row : m)
    if (!is_finite(row[0])) return Status::non_finite;
  return Status::no_pivot;
}

// The solution's last check (level 4 tests the FPU error flag once, counted in back_substitute).
template <class S>
void check_solution(Solution<S>& s, int steps) {
  for (const S& v : s.x) {
    if (is_finite(v)) continue;
    s.status = Status::non_finite;  // overflow in level 4
    s.step = steps;
    s.x.clear();
    return;
  }
}

template <class S>
Solution<S> solve(const Rows<S>& a, const Row<S>& b, const PivotRule& rule) {
  Solution<S> s;
  Rows<S> m = augment(a, b);
  const S scale = rule.needs_scale() ? matrix_scale(m) : S(0);
  const S limit = pivot_limit(scale, rule);
  const S bound = growth_bound(scale, rule);
  const long double input_scale = largest_magnitude(m);
  long double largest = input_scale;
  std::vector<int> order(m.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = static_cast<int>(i);
  Rows<S> upper;
  for (int k = 0; !m.empty(); ++k) {
    PivotStep<S> p = pivot_step(m, order, rule, limit);
    if (!p.found) {
      s.status = pivot_failure(m);
      s.step = k;
      return s;
    }
    record_pivot(s, p, order[0], input_scale);
    Rows<S> next;
    for (std::size_t i = 1; i < m.size(); ++i) next.push_back(eliminate(m[i], p.normalised));
    upper.push_back(std::move(p.normalised));
    order.erase(order.begin());
    if (!next.empty()) {
      if (!record_check(s, check_step(next, bound, rule), order, k)) return s;
      largest = std::max(largest, largest_magnitude(next));
    }
    m = std::move(next);
  }
  s.x = back_substitute(upper);
  check_solution(s, static_cast<int>(upper.size()));
  s.growth = input_scale > 0 ? largest / input_scale : 1;
  return s;
}

}  // namespace elimination
