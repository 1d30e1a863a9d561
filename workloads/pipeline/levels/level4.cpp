#include "workloads/pipeline/levels/level4.hpp"

#include <any>

#include "workloads/pipeline/relay.hpp"

namespace workloads::levels {

template <class T>
bool Level4<T>::round(Process& p) {
  using C = typename M::C;
  const Wiring& w = c_.wiring;
  PipelineOutcome& outcome = c_.report.outcome;
  elimination::Rows<C> upper;
  bool unstable = false;
  for (int k = 0; k < c_.n(); ++k) {
    auto pivot = std::any_cast<typename M::Pivot>(p.in(*w.to_l4).payload);
    if (!pivot.ok) {
      if (pivot.finish) return false;
      outcome.end_us = p.now_us();
      if (w.reply) p.out(*w.reply, {kHeaderBytes, {}, kFailLabel});
      return false;
    }
    unstable = unstable || pivot.unstable;
    upper.push_back(std::move(pivot.row));
  }
  outcome.eliminated_us = p.now_us();
  const elimination::Row<C> x = c_.run_piece(
      p, "back substitution", [](auto& u) { return elimination::back_substitute(u); },
      named("U", upper));
  outcome.end_us = p.now_us();
  bool finite = true;
  std::vector<double> values;
  for (const C& v : x) {
    finite = finite && elimination::is_finite(v);
    values.push_back(static_cast<double>(v.value()));
  }
  const std::vector<double>& qdd = c_.report.solved(values, finite, unstable, c_.n());
  if (w.reply) p.out(*w.reply, message(qdd, M::bytes(qdd), "qdd"));
  return true;
}

template class Level4<float>;
template class Level4<double>;

}  // namespace workloads::levels
