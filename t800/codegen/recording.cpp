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

int Recording::declare_array(std::string name, std::int64_t length, ArrayStorage storage) {
  arrays_.push_back({std::move(name), length, storage});
  return int(arrays_.size()) - 1;
}

int Recording::access(int array, std::int64_t index) {
  if (array < 0 || array >= int(arrays_.size()))
    throw std::logic_error("Recording::access: undeclared array");
  accesses_.push_back({array, index});
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

// Every load and store gets an access of its own (a copy of the element's), so that each can be
// subscripted as the loop it happens in has it: the element u[7] is u[k+1] when k = 6 and u[k+3]
// when k = 4.
int Recording::load(int access) {
  Node n;
  n.kind = NodeKind::load;
  n.access = this->access(accesses_.at(std::size_t(access)).array,
                          accesses_.at(std::size_t(access)).index);
  return add_node(n);
}

int Recording::operation(NodeKind kind, int a, int b) {
  Node n;
  n.kind = kind;
  n.a = a;
  n.b = b;
  return add_node(n);
}

void Recording::store(int access, int node) {
  Event e;
  e.kind = EventKind::store;
  e.access = this->access(accesses_.at(std::size_t(access)).array,
                          accesses_.at(std::size_t(access)).index);
  e.node = node;
  add_event(e);
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
void Recording::loop_begin() {
  Event e;
  e.kind = EventKind::loop_begin;
  add_event(e);
  open_blocks_.push_back(-1);  // no iteration open yet
}

void Recording::iteration(std::int64_t index) {
  if (open_blocks_.size() < 2) throw std::logic_error("Recording::iteration outside a loop");
  open_blocks_.back() = next_block_++;
  Event e;
  e.kind = EventKind::iteration;
  e.index = index;
  add_event(e);
}

void Recording::loop_end() {
  if (open_blocks_.size() < 2) throw std::logic_error("Recording::loop_end outside a loop");
  open_blocks_.pop_back();
  Event e;
  e.kind = EventKind::loop_end;
  add_event(e);
}

}  // namespace t800::codegen
