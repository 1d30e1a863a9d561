#include "workloads/dynamics/replay.hpp"

#include <algorithm>
#include <cstring>
#include <map>
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

namespace {

// Marks the nodes the roots depend on (operands come before the nodes using them).
template <class T>
std::vector<bool> live_nodes(const TraceGraph<T>& graph, const std::vector<int>& roots) {
  std::vector<bool> live(graph.nodes.size(), false);
  for (int root : roots) live[std::size_t(root)] = true;
  for (std::size_t n = graph.nodes.size(); n-- > 0;) {
    if (!live[n]) continue;
    if (graph.nodes[n].a >= 0) live[std::size_t(graph.nodes[n].a)] = true;
    if (graph.nodes[n].b >= 0) live[std::size_t(graph.nodes[n].b)] = true;
  }
  return live;
}

}  // namespace

template <class T>
SubtaskReplay<T>::SubtaskReplay(const RobotModel& model, const std::vector<Subtask>& tasks) {
  // Every task's kernel on one graph: what the kernels compute alike is one node.
  TraceGraph<T> graph;
  WorkerInput<Traced<T>> traced;
  for (Traced<T>* field : message_fields(model, traced)) *field = Traced<T>(graph, graph.input());
  std::vector<int> roots;
  for (const Subtask& task : tasks) {
    const Traced<T> result = evaluate_subtask(model, task, traced);
    values_.push_back(result.literal());  // kept for a constant; replaced by a replayed value
    results_.push_back(result.is_literal() ? -1 : result.node());
    if (!result.is_literal()) roots.push_back(result.node());
  }
  WorkerInput<T> defaults;
  for (T* field : message_fields(model, defaults)) image_.push_back(*field);
  message_reals_ = image_.size();

  // Registers for the live nodes: inputs in place (the message is copied in whole), then the
  // constants, then the operations in trace order (operands before uses).
  using Node = typename TraceGraph<T>::Node;
  const std::vector<bool> live = live_nodes(graph, roots);
  std::vector<std::uint32_t> reg(graph.nodes.size(), 0);
  for (std::size_t n = 0; n < graph.nodes.size(); ++n) {
    const Node& node = graph.nodes[n];
    if (node.kind == NodeKind::input) reg[n] = std::uint32_t(n);
    if (node.kind != NodeKind::constant || !live[n]) continue;
    reg[n] = std::uint32_t(image_.size());
    image_.push_back(node.value);
  }
  for (std::size_t n = 0; n < graph.nodes.size(); ++n) {
    const Node& node = graph.nodes[n];
    if (!live[n] || node.kind == NodeKind::input || node.kind == NodeKind::constant) continue;
    reg[n] = std::uint32_t(image_.size() + steps_.size());
    const Op op = node.kind == NodeKind::add   ? Op::add
                  : node.kind == NodeKind::sub ? Op::sub
                  : node.kind == NodeKind::mul ? Op::mul
                                               : Op::neg;
    const std::uint32_t b = node.b >= 0 ? reg[std::size_t(node.b)] : 0;
    steps_.push_back({op, reg[std::size_t(node.a)], b});
  }
  for (std::int64_t& result : results_) {
    if (result >= 0) result = reg[std::size_t(result)];
  }
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
void SubtaskReplay<T>::run(const std::vector<T>& message) const {
  registers_.resize(image_.size() + steps_.size());
  std::copy(image_.begin(), image_.end(), registers_.begin());
  std::copy_n(message.begin(), std::min(message.size(), message_reals_), registers_.begin());
  T* out = registers_.data() + image_.size();
  for (const Step& step : steps_) *out++ = apply(step, registers_.data());
  for (std::size_t t = 0; t < results_.size(); ++t) {
    if (results_[t] >= 0) values_[t] = registers_[std::size_t(results_[t])];
  }
}

template <class T>
const std::vector<T>& SubtaskReplay<T>::operator()(const std::vector<T>& message) const {
  // The same bits, not ==: a NaN, or a zero's sign, makes another message.
  const bool same = valid_ && message.size() == message_.size() &&
                    std::memcmp(message.data(), message_.data(), message.size() * sizeof(T)) == 0;
  if (same) return values_;
  run(message);
  message_ = message;
  valid_ = true;
  return values_;
}

template class SubtaskReplay<float>;
template class SubtaskReplay<double>;

}  // namespace dynamics
