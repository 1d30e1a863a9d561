#include "t800sim/alt.hpp"

#include "network/alt.hpp"

namespace t800sim {

Alt& Alt::after(std::int64_t t, std::function<void()> branch, bool when) {
  add(Kind::timer, nullptr, t, when, std::move(branch));
  return *this;
}

Alt& Alt::skip(std::function<void()> branch, bool when) {
  add(Kind::skip, nullptr, 0, when, std::move(branch));
  return *this;
}

void Alt::add(Kind kind, detail::ChannelSlot* slot, std::int64_t after, bool enabled,
              std::function<void()> branch) {
  if (kind == Kind::input) process_.check_end(slot, false);
  guards_.push_back({kind, slot, after, enabled, std::move(branch)});
}

int Alt::select() {
  std::vector<network::Guard> guards;
  for (const Guard& g : guards_) {
    network::Guard n;
    n.kind = g.kind == Kind::input   ? network::Guard::Kind::input
             : g.kind == Kind::timer ? network::Guard::Kind::timer
                                     : network::Guard::Kind::skip;
    n.channel = g.slot ? g.slot->impl : nullptr;
    n.after = g.after;
    n.enabled = g.enabled;
    guards.push_back(n);
  }
  const int chosen = network::alternate(process_.impl(), guards);
  if (guards_[std::size_t(chosen)].branch) guards_[std::size_t(chosen)].branch();
  return chosen;
}

}  // namespace t800sim
