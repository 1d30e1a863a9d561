#include "workloads/dynamics/replay.hpp"

#include <algorithm>
#include <cstring>
#include <map>
#include <stdexcept>
#include <tuple>

#include "workloads/dynamics/evaluate.hpp"

namespace dynamics {

namespace {

enum class NodeKind : std::uint8_t { input, constant, add, sub, mul, neg };

// The kernel's dataflow as it is traced: node n's operands are nodes before n.
template <class T>
struct TraceGraph {
  struct Node {
    NodeKind kind;
    int a = -1, b = -1;  // operand nodes (b: -1 for neg)
    T value = T(0);      // a constant's value
  };
  std::vector<Node> nodes;
  std::map<std::uint64_t, int> constants;                    // by bit pattern: -0 is not 0
  std::map<std::tuple<NodeKind, int, int>, int> operations;  // operands in order, never swapped

  int input() {
    nodes.push_back({NodeKind::input});
    return int(nodes.size()) - 1;
  }
  int constant(T value) {
    std::uint64_t bits = 0;
    std::memcpy(&bits, &value, sizeof value);
    const auto [it, added] = constants.try_emplace(bits, int(nodes.size()));
    if (added) nodes.push_back({NodeKind::constant, -1, -1, value});
    return it->second;
  }
  int operation(NodeKind kind, int a, int b) {
    const auto [it, added] = operations.try_emplace({kind, a, b}, int(nodes.size()));
    if (added) nodes.push_back({kind, a, b});
    return it->second;
  }
};

// The scalar a kernel is traced with: a node of the graph, or a literal (a model constant, or a
// value computed from literals only, which the kernel's own scalar would compute the same way).
template <class T>
class Traced {
 public:
  Traced() = default;
  explicit Traced(T literal) : literal_(literal) {}
  Traced(TraceGraph<T>& graph, int node) : graph_(&graph), node_(node) {}

  bool is_literal() const { return graph_ == nullptr; }
  T literal() const { return literal_; }
  int node() const { return node_; }

  friend Traced operator+(const Traced& a, const Traced& b) {
    return binary(NodeKind::add, a, b, a.literal_ + b.literal_);
  }
  friend Traced operator-(const Traced& a, const Traced& b) {
    return binary(NodeKind::sub, a, b, a.literal_ - b.literal_);
  }
  friend Traced operator*(const Traced& a, const Traced& b) {
    return binary(NodeKind::mul, a, b, a.literal_ * b.literal_);
  }
  friend Traced operator-(const Traced& a) {
    if (a.is_literal()) return Traced(-a.literal_);
    return Traced(*a.graph_, a.graph_->operation(NodeKind::neg, a.node_, -1));
  }

 private:
  // `folded` is the result when both operands are literals (computed in T, as the kernel would).
  static Traced binary(NodeKind kind, const Traced& a, const Traced& b, T folded) {
    if (a.is_literal() && b.is_literal()) return Traced(folded);
    TraceGraph<T>& graph = a.is_literal() ? *b.graph_ : *a.graph_;
    return Traced(graph, graph.operation(kind, a.operand(graph), b.operand(graph)));
  }
  int operand(TraceGraph<T>& graph) const {
    return is_literal() ? graph.constant(literal_) : node_;
  }

  TraceGraph<T>* graph_ = nullptr;
  int node_ = -1;
  T literal_ = T(0);
};

}  // namespace

// Folded<Traced<T>>::constant rounds a model constant to T, as Folded<T> does.
template <class T>
struct plain_scalar<Traced<T>> {
  using type = T;
};

template <class T>
SubtaskReplay<T>::SubtaskReplay(const RobotModel& model, const Subtask& task) {
  TraceGraph<T> graph;
  WorkerInput<Traced<T>> traced;
  for (Traced<T>* field : message_fields(model, traced)) *field = Traced<T>(graph, graph.input());
  const Traced<T> result = evaluate_subtask(model, task, traced);

  WorkerInput<T> defaults;
  for (T* field : message_fields(model, defaults)) image_.push_back(*field);
  message_reals_ = image_.size();
  if (result.is_literal()) {
    literal_ = result.literal();
    return;
  }
  // Only what the result depends on; inputs keep their places (the message is copied in whole).
  using Node = typename TraceGraph<T>::Node;
  const std::vector<Node>& nodes = graph.nodes;
  std::vector<bool> live(nodes.size(), false);
  live[std::size_t(result.node())] = true;
  for (std::size_t n = nodes.size(); n-- > 0;) {
    if (!live[n]) continue;
    if (nodes[n].a >= 0) live[std::size_t(nodes[n].a)] = true;
    if (nodes[n].b >= 0) live[std::size_t(nodes[n].b)] = true;
  }
  std::vector<std::uint32_t> reg(nodes.size(), 0);
  for (std::size_t n = 0; n < nodes.size(); ++n) {
    if (nodes[n].kind == NodeKind::input) reg[n] = std::uint32_t(n);  // inputs come first
    if (nodes[n].kind != NodeKind::constant || !live[n]) continue;
    reg[n] = std::uint32_t(image_.size());
    image_.push_back(nodes[n].value);
  }
  for (std::size_t n = 0; n < nodes.size(); ++n) {
    const Node& node = nodes[n];
    if (!live[n] || node.kind == NodeKind::input || node.kind == NodeKind::constant) continue;
    reg[n] = std::uint32_t(image_.size() + steps_.size());
    const Op op = node.kind == NodeKind::add   ? Op::add
                  : node.kind == NodeKind::sub ? Op::sub
                  : node.kind == NodeKind::mul ? Op::mul
                                               : Op::neg;
    const std::uint32_t b = node.b >= 0 ? reg[std::size_t(node.b)] : 0;
    steps_.push_back({op, reg[std::size_t(node.a)], b});
  }
  result_ = reg[std::size_t(result.node())];
}

template <class T>
T SubtaskReplay<T>::apply(const Step& step, const T* r) {
  switch (step.op) {
    case Op::add:
      return r[step.a] + r[step.b];
    case Op::sub:
      return r[step.a] - r[step.b];
    case Op::mul:
      return r[step.a] * r[step.b];
    case Op::neg:
      break;
  }
  return -r[step.a];
}

template <class T>
T SubtaskReplay<T>::operator()(const std::vector<T>& message) const {
  if (result_ < 0) return literal_;
  // Scratch registers per thread: a replay runs to its end without yielding to another process.
  thread_local std::vector<T> registers;
  registers.resize(image_.size() + steps_.size());
  std::copy(image_.begin(), image_.end(), registers.begin());
  std::copy_n(message.begin(), std::min(message.size(), message_reals_), registers.begin());
  T* out = registers.data() + image_.size();
  for (const Step& step : steps_) *out++ = apply(step, registers.data());
  return registers[std::size_t(result_)];
}

template class SubtaskReplay<float>;
template class SubtaskReplay<double>;

}  // namespace dynamics
