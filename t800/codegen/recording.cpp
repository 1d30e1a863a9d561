#include "t800/codegen/recording.hpp"

#include <atomic>
#include <mutex>
#include <stdexcept>
#include <unordered_map>

namespace t800::codegen {

namespace {
std::uint32_t next_serial() {
  static std::atomic<std::uint32_t> serial{0};
  return ++serial;
}
// Every recording's name by its serial, for the error a value carried from one to another gets.
std::mutex names_lock;
std::unordered_map<std::uint32_t, std::string>& names() {
  static std::unordered_map<std::uint32_t, std::string> by_serial;
  return by_serial;
}
}  // namespace

bool is_comparison(NodeKind kind) {
  return kind == NodeKind::greater || kind == NodeKind::equal;
}
bool is_routine(NodeKind kind) {
  return kind == NodeKind::sine || kind == NodeKind::cosine;
}
bool is_conversion_to_int(NodeKind kind) {
  return kind == NodeKind::int_round || kind == NodeKind::int_trunc;
}

bool is_leaf(NodeKind kind) {
  return kind == NodeKind::constant || kind == NodeKind::load || kind == NodeKind::loop_index;
}

bool is_commutative(NodeKind kind) {
  return kind == NodeKind::add || kind == NodeKind::mul || kind == NodeKind::bit_and ||
         kind == NodeKind::bit_or || kind == NodeKind::bit_xor || kind == NodeKind::equal;
}

const char* operator_symbol(NodeKind kind) {
  switch (kind) {
    case NodeKind::add:
      return "+";
    case NodeKind::sub:
      return "-";
    case NodeKind::mul:
      return "*";
    case NodeKind::div:
      return "/";
    case NodeKind::rem:
      return "\\";
    case NodeKind::bit_and:
      return "/\\";
    case NodeKind::bit_or:
      return "\\/";
    case NodeKind::bit_xor:
      return "><";
    case NodeKind::shift_left:
      return "<<";
    case NodeKind::shift_right:
      return ">>";
    case NodeKind::greater:
      return ">";
    case NodeKind::equal:
      return "=";
    default:
      return "?";
  }
}

int element_bytes(const ArrayDecl& array, bool real64) {
  return array.element == ElementType::int32 || !real64 ? 4 : 8;
}

Recording::Recording(std::string name, bool real64)
    : name_(std::move(name)), real64_(real64), serial_(next_serial()) {
  const std::lock_guard<std::mutex> hold(names_lock);
  names()[serial_] = name_;
}

std::string Recording::name_of(std::uint32_t serial) {
  const std::lock_guard<std::mutex> hold(names_lock);
  const auto at = names().find(serial);
  return at == names().end() ? std::string() : at->second;
}

void Recording::foreign_value(std::uint32_t serial, const std::string& type,
                              const std::string& array) const {
  const std::string whose =
      serial == kOutside
          ? " value made before the kernel was recorded (neither declared nor computed in it)"
          : " value of kernel \"" + name_of(serial) + "\"'s recording";
  throw KernelError("kernel \"" + name_ + "\" " +
                    (array.empty() ? "reads" : "stores into " + array) + " a " + type + whose +
                    ", which its code cannot load; declare it in this kernel (t800sim::declare, "
                    "declare_variable) as data the PROC is given, or compute it here");
}

RecordingScope::RecordingScope(Recording& recording) : outer_(Recording::active()) {
  Recording::active() = &recording;
}

RecordingScope::~RecordingScope() {
  Recording::active() = outer_;
}

int Recording::declare_array(std::string name, std::int64_t length, ArrayStorage storage,
                             ElementType element) {
  arrays_.push_back({std::move(name), length, storage, element});
  return int(arrays_.size()) - 1;
}

int Recording::access(int array, std::int64_t index) {
  if (array < 0 || array >= int(arrays_.size()))
    throw std::logic_error("Recording::access: undeclared array");
  return add_access({array, index});
}

int Recording::subscripted(int array, int subscript, std::int64_t index) {
  if (array < 0 || array >= int(arrays_.size()))
    throw std::logic_error("Recording::subscripted: undeclared array");
  if (subscript < 0 || subscript >= int(nodes_.size()) || !nodes_[std::size_t(subscript)].integer)
    throw std::logic_error("Recording::subscripted: a subscript is an INT of this recording");
  return add_access({array, index, subscript});
}

int Recording::add_access(const Access& access) {
  accesses_.push_back(access);
  return int(accesses_.size()) - 1;
}

// The block operations land in: the open iteration, or the enclosing block between iterations.
int Recording::block() const {
  for (auto b = open_blocks_.rbegin(); b != open_blocks_.rend(); ++b)
    if (*b >= 0) return *b;
  return 0;
}

void Recording::add_event(Event e) {
  e.block = block();
  events_.push_back(e);
}

int Recording::add_node(Node node) {
  node.block = block();
  nodes_.push_back(node);
  const int id = int(nodes_.size()) - 1;
  Event e;
  e.kind = EventKind::value;
  e.node = id;
  add_event(e);
  return id;
}

int Recording::constant(double value) {
  Node n;
  n.kind = NodeKind::constant;
  n.value = value;
  return add_node(n);
}

int Recording::integer_constant(std::int32_t value) {
  Node n;
  n.kind = NodeKind::constant;
  n.integer = true;
  n.value = value;
  return add_node(n);
}

// Every load and store gets an access of its own (a copy of the element's), so that each can be
// subscripted as the loop it happens in has it: the element u[7] is u[k+1] when k = 6 and u[k+3]
// when k = 4.
int Recording::load(int access, double value) {
  Node n;
  n.kind = NodeKind::load;
  n.access = add_access(accesses_.at(std::size_t(access)));
  n.integer =
      arrays_[std::size_t(accesses_[std::size_t(n.access)].array)].element == ElementType::int32;
  if (n.integer) n.value = value;
  return add_node(n);
}

// An operation is of its first operand's type, but for the conversions, which change it. A
// conversion of a constant is a constant of the other type, as the compiler folds it.
int Recording::operation(NodeKind kind, int a, int b, double value) {
  const Node& first = nodes_.at(std::size_t(a));
  if (first.kind == NodeKind::constant && kind == NodeKind::to_real)
    return constant(real64_ ? first.value : double(float(first.value)));
  if (first.kind == NodeKind::constant && is_conversion_to_int(kind))
    return integer_constant(std::int32_t(value));
  Node n;
  n.kind = kind;
  n.a = a;
  n.b = b;
  if (kind == NodeKind::to_real)
    n.integer = false;
  else if (is_conversion_to_int(kind))
    n.integer = true;
  else
    n.integer = first.integer;
  if (n.integer) n.value = value;
  if (b >= 0 && !is_conversion_to_int(kind) && kind != NodeKind::to_real &&
      nodes_.at(std::size_t(b)).integer != n.integer)
    throw std::logic_error("Recording::operation: an INT and a REAL operand");
  return add_node(n);
}

void Recording::store(int access, int node) {
  Event e;
  e.kind = EventKind::store;
  e.access = add_access(accesses_.at(std::size_t(access)));
  e.node = node;
  add_event(e);
}

int Recording::comparison(NodeKind kind, int a, int b, bool inverted) {
  const int n = operation(kind, a, b);
  nodes_[std::size_t(n)].inverted = inverted;
  return n;
}

void Recording::test(int comparison, bool outcome) {
  Event e;
  e.kind = EventKind::test;
  e.node = comparison;
  e.taken = outcome;
  add_event(e);
}

void Recording::integer(IntegerStatement statement, std::int64_t count) {
  if (count <= 0) return;
  Event e;
  e.kind = EventKind::integer;
  e.integer = statement;
  e.count = count;
  add_event(e);
}

// A loop's iterations are blocks of their own; the loop itself sits in the enclosing block.
void Recording::loop_begin(LoopBounds bounds) {
  Event e;
  e.kind = EventKind::loop_begin;
  e.index = std::int64_t(loop_bounds_.size());
  loop_bounds_.push_back(bounds);
  add_event(e);
  open_blocks_.push_back(-1);  // no iteration open yet
  loop_indices_.push_back(0);
}

void Recording::iteration(std::int64_t index) {
  if (open_blocks_.size() < 2) throw std::logic_error("Recording::iteration outside a loop");
  open_blocks_.back() = next_block_++;
  loop_indices_.back() = index;
  Event e;
  e.kind = EventKind::iteration;
  e.index = index;
  add_event(e);
}

void Recording::loop_end() {
  if (open_blocks_.size() < 2) throw std::logic_error("Recording::loop_end outside a loop");
  open_blocks_.pop_back();
  loop_indices_.pop_back();
  Event e;
  e.kind = EventKind::loop_end;
  add_event(e);
}

int Recording::loop_index(int depth) {
  if (depth < 0 || depth >= loop_depth())
    throw std::logic_error("Recording::loop_index: no SEQ open at that depth");
  Node n;
  n.kind = NodeKind::loop_index;
  n.integer = true;
  n.depth = depth;
  n.value = double(loop_indices_[std::size_t(depth)]);
  return add_node(n);
}

}  // namespace t800::codegen
