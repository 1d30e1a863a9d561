#include "workloads/pipeline/levels/level4.hpp"

#include <tuple>

namespace workloads::levels {

template <class T>
bool Level4<T>::round(t800sim::Process& p) {
  using C = typename M::C;
  using Packet = typename M::Packet;
  const t800sim::In<Packet> u_rows(ends_.from[0]);
  // Serving until finish, q̈ goes to the client; once, it stays here.
  const Slot reply = ends_.to.empty() ? nullptr : ends_.to[0];
  const t800sim::Out<Packet> answer(reply);
  PipelineOutcome& outcome = c_.report.outcome;
  elimination::Rows<C> upper;
  bool unstable = false;
  for (int k = 0; k < c_.n(); ++k) {
    const typename M::PacketValue u = p.in(u_rows);
    const std::int32_t flags = std::get<0>(u);
    if (flags & header::kStop) {
      if (flags & header::kFinish) return false;
      outcome.end_us = p.now_us();
      if (reply) p.out(answer, M::answer(false, {}), kFailLabel);
      return false;
    }
    unstable = unstable || (flags & header::kUnstable);
    upper.push_back(M::row_of(u));
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
  if (reply) p.out(answer, M::answer(true, qdd), "qdd");
  return true;
}

template class Level4<float>;
template class Level4<double>;

}  // namespace workloads::levels
