#include "t800/codegen/dataflow.hpp"

namespace t800::codegen {

Dataflow::Dataflow(const Recording& recording) : r_(recording) {
  const std::vector<Node>& nodes = r_.nodes();
  const std::size_t n = nodes.size();
  live_.assign(n, false);
  temporary_.assign(n, false);
  uses_.assign(n, 0);
  last_use_.assign(n, -1);
  slot_.assign(n, -1);
  std::vector<bool> cross(n, false);
  std::vector<int> stack;
  auto use = [&](int x, int block) {
    x = through(x);
    ++uses_[std::size_t(x)];
    if (nodes[std::size_t(x)].block != block) cross[std::size_t(x)] = true;
    if (!live_[std::size_t(x)]) {
      live_[std::size_t(x)] = true;
      stack.push_back(x);
    }
  };
  for (const Event& e : r_.events()) {
    if (e.kind == EventKind::store || e.kind == EventKind::test) use(e.node, e.block);
    if (e.kind == EventKind::store && subscript(e.access) >= 0) use(subscript(e.access), e.block);
    for (int bound : loop_bounds(e))
      if (bound >= 0) use(bound, e.block);
  }
  while (!stack.empty()) {
    const Node& node = nodes[std::size_t(stack.back())];
    stack.pop_back();
    if (node.a >= 0) use(node.a, node.block);
    if (node.b >= 0 && through(node.b) != through(node.a))  // x * x reads x once
      use(node.b, node.block);
    if (node.kind == NodeKind::load && subscript(node.access) >= 0)
      use(subscript(node.access), node.block);
  }
  // A value used more than once, or in another block (a later iteration), is a local variable;
  // so is a library routine's result, and an INT converted from a REAL (through the workspace).
  for (std::size_t i = 0; i < n; ++i) {
    const NodeKind k = nodes[i].kind;
    temporary_[i] = live_[i] && !is_leaf(k) && !is_comparison(k) && k != NodeKind::neg &&
                    (uses_[i] > 1 || cross[i] || is_routine(k) || is_conversion_to_int(k));
    if (live_[i] && k == NodeKind::constant && !nodes[i].integer && nodes[i].value != 0.0)
      uses_real_constants_ = true;
  }
  // The last statement reading each temporary: walk every statement's expression down to the
  // temporaries (or leaves) it reads.
  for (std::size_t i = 0; i < r_.events().size(); ++i) {
    const Event& e = r_.events()[i];
    int root = -1, defining = -1;
    if (e.kind == EventKind::store || e.kind == EventKind::test) root = e.node;
    if (e.kind == EventKind::value && temporary(e.node)) root = defining = e.node;
    const std::array<int, 2> bounds = loop_bounds(e);
    if (root < 0 && bounds[0] < 0 && bounds[1] < 0) continue;
    std::vector<int> walk;
    auto visit = [&](int x) {
      if (x < 0) return;
      x = through(x);
      if (temporary(x) && x != defining) {
        last_use_[std::size_t(x)] = int(i);
        return;
      }
      walk.push_back(x);
    };
    visit(root);
    if (e.kind == EventKind::store) visit(subscript(e.access));
    for (int bound : bounds) visit(bound);
    while (!walk.empty()) {
      const Node& node = nodes[std::size_t(walk.back())];
      walk.pop_back();
      visit(node.a);
      if (node.b != node.a) visit(node.b);
      if (node.kind == NodeKind::load) visit(subscript(node.access));
    }
  }
  for (std::size_t i = 0; i < n; ++i)
    if (temporary_[i] && last_use_[i] >= 0) release_at_.insert({last_use_[i], int(i)});
}

int Dataflow::subscript(int access) const {
  return r_.accesses()[std::size_t(access)].subscript;
}

std::array<int, 2> Dataflow::loop_bounds(const Event& e) const {
  if (e.kind != EventKind::loop_begin) return {-1, -1};
  const LoopBounds& b = r_.loop_bounds()[std::size_t(e.index)];
  return {b.first, b.count};
}

int Dataflow::through(int n) const {
  while (n >= 0 && r_.nodes()[std::size_t(n)].kind == NodeKind::neg)
    n = r_.nodes()[std::size_t(n)].a;
  return n;
}

int Dataflow::words(int n) const {
  return r_.nodes()[std::size_t(n)].integer || !r_.real64() ? 1 : 2;
}

void Dataflow::assign(int n, Frame& frame) {
  slot_[std::size_t(n)] = frame.allocate_temporary(words(n));
}

void Dataflow::release_after(int event, Frame& frame) {
  auto [begin, end] = release_at_.equal_range(event);
  for (auto it = begin; it != end; ++it)
    frame.release_temporary(slot_[std::size_t(it->second)], words(it->second));
}

}  // namespace t800::codegen
