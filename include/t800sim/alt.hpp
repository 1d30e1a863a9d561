// occam's ALT: wait for the first of several guards to be ready -- an input, a time (AFTER), a
// SKIP -- each with an optional boolean pre-condition, then run that guard's branch. Costed with
// the T800's instructions (alt/talt, enbc/enbt/enbs, altwt/taltwt, disc/dist/diss, altend).
//
//   Alt(p).input(request, [&](INT worker) { ... })
//          .after(deadline, [&] { ... }, waiting)   // the pre-condition `waiting`
//          .select();
//
// The T800 implements ALT as PRI ALT (the compiler writer's guide): when several guards are ready
// the first in the order given is taken. PriAlt says so where a program relies on it.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "t800sim/channel.hpp"
#include "t800sim/process.hpp"

namespace t800sim {

class Alt {
 public:
  explicit Alt(Process& p) : process_(p) {}

  // c ? v, then branch(v).
  template <class P, class F>
  Alt& input(const In<P>& c, F branch, bool when = true) {
    Process* p = &process_;
    add(Kind::input, c.slot(), 0, when, [p, c, branch] { branch(p->in(c)); });
    return *this;
  }
  template <class P, class F>
  Alt& input(const Chan<P>& c, F branch, bool when = true) {
    return input(c.in(), branch, when);
  }
  // ALT i = 0 FOR SIZE cs: cs[i] ? v, then branch(i, v).
  template <class P, class F>
  Alt& input(const std::vector<Chan<P>>& cs, F branch, bool when = true) {
    for (std::size_t i = 0; i < cs.size(); ++i)
      input(
          cs[i].in(), [branch, i](const value_of<P>& v) { branch(int(i), v); }, when);
    return *this;
  }
  // c ? v with InputOrFail.t (Process::in_or_fail): once the guard is chosen the input gives up
  // `within_us` later -- a message that has started arrives within its time on the wire unless a
  // fault stops it -- then branch(the value, or nullopt).
  template <class P, class F>
  Alt& input_or_fail(const In<P>& c, double within_us, F branch, bool when = true) {
    Process* p = &process_;
    add(Kind::input, c.slot(), 0, when,
        [p, c, within_us, branch] { branch(p->in_or_fail(c, p->now_us() + within_us)); });
    return *this;
  }
  // TIMER ? AFTER t
  Alt& after(std::int64_t t, std::function<void()> branch, bool when = true);
  Alt& skip(std::function<void()> branch, bool when = true);

  // Waits for a ready guard (for ever when none is enabled, as occam does), runs its branch and
  // returns its index in the order the guards were added.
  int select();

 private:
  enum class Kind { input, timer, skip };
  struct Guard {
    Kind kind;
    detail::ChannelSlot* slot;
    std::int64_t after;
    bool enabled;
    std::function<void()> branch;
  };
  void add(Kind kind, detail::ChannelSlot* slot, std::int64_t after, bool enabled,
           std::function<void()> branch);

  Process& process_;
  std::vector<Guard> guards_;
};

using PriAlt = Alt;

}  // namespace t800sim
