#include "workloads/dynamics/term_sweep.hpp"

#include <algorithm>
#include <array>

#include "workloads/dynamics/terms.hpp"

namespace dynamics {

namespace {

// differential[i][p]: frame p's differential for joint i (p >= i), from the chain A_i ... A_p that
// for_each_link builds for joint i whatever the other joints of the set.
using ChainTable = std::array<std::array<Differential<double>, kJoints>, kJoints>;

ChainTable differentials(const DhTable<double>& dh) {
  ChainTable table;
  for (int i = 0; i < kJoints; ++i) {
    const auto si = static_cast<std::size_t>(i);
    Frame<double> chain = identity_frame<double>();
    for (int p = i; p < kJoints; ++p) {
      chain = append(chain, dh[static_cast<std::size_t>(p)]);
      table[si][static_cast<std::size_t>(p)] = differential(chain, dh[si].type());
    }
  }
  return table;
}

// The sum over the links a term involves, in for_each_link's order.
template <class LinkTerm>
Folded<double> sum_over_links(int last_joint, LinkTerm link_term) {
  Folded<double> sum;
  for (int p = last_joint; p < kJoints; ++p) sum += link_term(p);
  return sum;
}

}  // namespace

std::vector<Folded<double>> evaluate_terms(const RobotModel& model,
                                           const std::vector<Subtask>& terms,
                                           const WorkerInput<double>& input) {
  const DhTable<double> dh = load_dh_entries(model, input, 0);
  const ChainTable chains = differentials(dh);
  std::array<LinkConstants, kJoints> constants;
  for (int p = 0; p < kJoints; ++p)
    constants[static_cast<std::size_t>(p)] = link_constants(model, p);
  auto at = [&chains](int joint, int p) -> const Differential<double>& {
    return chains[static_cast<std::size_t>(joint)][static_cast<std::size_t>(p)];
  };
  auto link = [&constants](int p) -> const LinkConstants& {
    return constants[static_cast<std::size_t>(p)];
  };
  std::vector<Folded<double>> values;
  values.reserve(terms.size());
  for (const Subtask& t : terms) {
    switch (t.kind) {
      case TermKind::inertia:
        values.push_back(sum_over_links(std::max(t.i, t.j), [&](int p) {
          return detail::inertia_link_term(link(p), at(t.i, p), at(t.j, p), t.i == t.j);
        }));
        break;
      case TermKind::coriolis:
        values.push_back(sum_over_links(std::max({t.i, t.j, t.k}), [&](int p) {
          return detail::coriolis_link_term(link(p), at(t.i, p), at(t.j, p), at(t.k, p));
        }));
        break;
      case TermKind::gravity:  // six terms, each with its own gravity vector: the kernel itself
        values.push_back(gravity_term(model, input, t.i));
        break;
    }
  }
  return values;
}

}  // namespace dynamics
