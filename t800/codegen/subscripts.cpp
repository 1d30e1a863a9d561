#include "t800/codegen/subscripts.hpp"

#include <algorithm>

namespace t800::codegen {

namespace {

struct Use {
  int access;
  std::int64_t loop_index;  // the iteration's index when the access was recorded
};

struct Loop {
  int depth;
  std::int64_t index = 0;
  bool started = false;
  std::vector<Use> previous, current;
};

class Classifier {
 public:
  explicit Classifier(const Recording& r)
      : r_(r), result_(r.accesses().size()), set_(r.accesses().size()) {}

  std::vector<Subscript> run() {
    for (const Event& e : r_.events()) {
      switch (e.kind) {
        case EventKind::value:
          if (r_.nodes()[std::size_t(e.node)].kind == NodeKind::load)
            use(r_.nodes()[std::size_t(e.node)].access);
          break;
        case EventKind::store:
          use(e.access);
          break;
        case EventKind::loop_begin: {
          Loop loop;
          loop.depth = int(loops_.size());
          loops_.push_back(loop);
        } break;
        case EventKind::iteration:
          next_iteration(e.index);
          break;
        case EventKind::loop_end:
          next_iteration(0);
          settle(loops_.back().previous);
          loops_.pop_back();
          break;
        default:
          break;
      }
    }
    for (std::size_t a = 0; a < result_.size(); ++a)
      if (!set_[a]) result_[a] = {false, 0, r_.accesses()[a].index};
    return result_;
  }

 private:
  void use(int access) {
    if (loops_.empty()) {
      set(access, {false, 0, r_.accesses()[std::size_t(access)].index});
      return;
    }
    loops_.back().current.push_back({access, loops_.back().index});
  }

  // Compares the iteration just finished with the one before it, place by place.
  void next_iteration(std::int64_t index) {
    Loop& loop = loops_.back();
    if (loop.started) {
      const std::size_t n = std::min(loop.previous.size(), loop.current.size());
      for (std::size_t k = 0; k < n; ++k) {
        const Access& p = r_.accesses()[std::size_t(loop.previous[k].access)];
        const Access& c = r_.accesses()[std::size_t(loop.current[k].access)];
        if (p.array != c.array) continue;
        if (p.index == c.index) {
          set(loop.previous[k].access, {false, 0, p.index});
          set(loop.current[k].access, {false, 0, c.index});
        }
      }
      settle(loop.previous);
    }
    loop.previous = std::move(loop.current);
    loop.current.clear();
    loop.index = index;
    loop.started = true;
  }

  // Whatever no comparison showed constant is subscripted by the loop's index -- except an element
  // of a one-element array (a declared variable), whose subscript can only be constant: in a SEQ of
  // one iteration no second iteration shows it so.
  void settle(const std::vector<Use>& uses) {
    const int depth = int(loops_.size()) - 1;
    for (const Use& u : uses) {
      const Access& a = r_.accesses()[std::size_t(u.access)];
      if (r_.arrays()[std::size_t(a.array)].length == 1)
        set(u.access, {false, 0, a.index});
      else
        set(u.access, {true, depth, a.index - u.loop_index});
    }
  }

  void set(int access, Subscript s) {
    if (set_[std::size_t(access)]) return;
    result_[std::size_t(access)] = s;
    set_[std::size_t(access)] = true;
  }

  const Recording& r_;
  std::vector<Subscript> result_;
  std::vector<bool> set_;
  std::vector<Loop> loops_;
};

}  // namespace

std::vector<Subscript> classify_subscripts(const Recording& recording) {
  return Classifier(recording).run();
}

}  // namespace t800::codegen
