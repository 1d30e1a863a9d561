// What a kernel does, recorded as it runs: the dataflow of its REAL arithmetic and the occam
// structure around it (replicated SEQs, stores into arrays, tests), so that a code generator can
// emit the T800 code an occam compiler would (generator.hpp).
//
// A recording scalar (dynamics::Counted) reports every operation to the Recording active on its
// thread. Values that come from memory are loads of array elements the kernel or its caller
// declared (Recording::declare_array); literals and model constants are constants (a REAL in the
// code's constant table); intermediate results are nodes. Assigning to a declared element is a
// store. Control structure comes from markers the kernel places where occam has it (seq(),
// integer statements); a comparison is a test whose outcome the recording keeps, so data-dependent
// paths are recorded as they ran.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace t800::codegen {

enum class NodeKind : std::uint8_t {
  constant,  // a REAL literal or model constant
  load,      // an element of a declared array (or a declared scalar variable)
  add,
  sub,
  mul,
  div,
  neg,
  abs,
  sqrt,
  greater,  // a > b, the result goes to the integer stack (fpgt)
  equal,    // a = b (fpeq)
  sine,     // calls of the occam library's SIN and COS routines
  cosine,
  // INT only (Node::integer): the remainder, bitwise operations and shifts.
  rem,          // a \ b
  bit_and,      // a /\ b
  bit_or,       // a \/ b
  bit_xor,      // a >< b
  bit_not,      // ~ a
  shift_left,   // a << b
  shift_right,  // a >> b (logical)
  // Conversions between INT and REAL: REALn ROUND a (an INT node a, a REAL result), INT ROUND a
  // and INT TRUNC a (a REAL node a, an INT result).
  to_real,
  int_round,
  int_trunc,
  // The index of an enclosing replicated SEQ (Node::depth says which), an INT: its value is the
  // iteration's, its code the same in every iteration (ldl of the loop's control block).
  loop_index,
};
bool is_comparison(NodeKind kind);
// A constant, a load or a loop's index: a value that is not computed.
bool is_leaf(NodeKind kind);
bool is_routine(NodeKind kind);
// The value is an INT computed by the REAL arithmetic (INT ROUND/TRUNC): a local variable always,
// as the conversion goes through the workspace (fpstnli32).
bool is_conversion_to_int(NodeKind kind);
// a op b = b op a (for REAL and INT alike).
bool is_commutative(NodeKind kind);
// The operator as occam writes it, for listings ("?" for what is not a binary operator).
const char* operator_symbol(NodeKind kind);

// An element of a declared array, as recorded. `index` is the concrete one. With no `subscript`,
// the generator works out from the loop it is in whether the code subscripts it by the loop's
// index; with one (t800sim::at), the code computes the subscript as the kernel did.
struct Access {
  int array = -1;
  std::int64_t index = 0;
  int subscript = -1;  // an INT node: the subscript as the kernel computed it
};

struct Node {
  NodeKind kind = NodeKind::constant;
  // An INT (32-bit, on the integer stack) rather than a REAL of the recording's precision; for a
  // comparison, an INT comparison (gt, diff on the integer stack).
  bool integer = false;
  // An INT comparison whose condition is the instruction's result negated: a >= b is NOT (b > a)
  // (gt; eqc 0), a <> b is a - b non-zero (diff alone).
  bool inverted = false;
  int a = -1, b = -1;  // operands
  int access = -1;     // load: index into Recording::accesses()
  double value = 0;    // a constant's; an INT node's value as the run computed it
  int block = 0;       // the block (straight-line code or one loop iteration) it was computed in
  int depth = -1;      // loop_index: the nesting depth of its SEQ (0 = outermost)
};

// How an array is held (compiler writer's guide, "vectors"): through a pointer in a workspace word
// (a parameter, or an array in vector space) or inside the workspace itself.
enum class ArrayStorage : std::uint8_t { pointer, workspace };

// What an array holds: REALs of the recording's precision, or INTs (a word each).
enum class ElementType : std::uint8_t { real, int32 };

struct ArrayDecl {
  std::string name;
  std::int64_t length = 0;
  ArrayStorage storage = ArrayStorage::pointer;
  ElementType element = ElementType::real;
};
// An element's size in bytes and in workspace words.
int element_bytes(const ArrayDecl& array, bool real64);
inline int element_words(const ArrayDecl& array, bool real64) {
  return element_bytes(array, real64) / 4;
}

// Integer work a kernel states where occam would have it (elimination's pivot bookkeeping, the
// FPU error flag test): the code generator emits the instructions each one compiles to.
enum class IntegerStatement : std::uint8_t {
  test,         // IF on an integer condition: load it, conditional jump
  move,         // an integer assignment: load, store
  error_check,  // test the FPU's error flag once (fptesterror, conditional jump)
};

enum class EventKind : std::uint8_t {
  value,       // node `node` was computed
  store,       // `node` stored into access `access`
  test,        // IF on comparison `node`; `taken` tells which way it went
  integer,     // `count` integer statements of kind `integer`
  loop_begin,  // a replicated SEQ begins; `index` is its place in Recording::loop_bounds()
  iteration,   // an iteration begins, its index being `index`
  loop_end,
};

// A replicated SEQ's first index and count as the kernel gave them: INT nodes for values the PROC
// computes or holds in variables (SEQ j = k FOR n - k), -1 for a constant the compiler knows.
struct LoopBounds {
  int first = -1;
  int count = -1;
  bool variable() const { return first >= 0 || count >= 0; }
};

struct Event {
  EventKind kind = EventKind::value;
  int node = -1;
  int access = -1;
  bool taken = false;
  IntegerStatement integer = IntegerStatement::test;
  std::int64_t count = 0;
  std::int64_t index = 0;
  int block = 0;  // the block it happened in
};

// A kernel recorded wrongly (Recording::foreign_value), or whose body threw
// (t800sim::record_kernel): the message names the kernel.
struct KernelError : std::logic_error {
  using std::logic_error::logic_error;
};

// A recorded kernel: plain data, kept and compiled for each processor type that runs it.
class Recording {
 public:
  Recording(std::string name, bool real64);

  // The recording receiving operations on this thread (RecordingScope), or nullptr. Inline: every
  // recording scalar made asks.
  static Recording* current() { return active(); }
  // The serial of no recording: a value made while none was active.
  static constexpr std::uint32_t kOutside = 0;

  const std::string& name() const { return name_; }
  bool real64() const { return real64_; }
  // Unique among the recordings of this run: a value carries it with its node, so that a value
  // from another recording is not mistaken for one of this one's.
  std::uint32_t serial() const { return serial_; }
  // A value of `type` (the recording scalar's C++ type) that recording `serial` made, or no
  // recording (kOutside), is read or stored (into `array`, if one) here: the compiled code could
  // only take it for a constant, so it is an error naming the kernels (KernelError).
  [[noreturn]] void foreign_value(std::uint32_t serial, const std::string& type,
                                  const std::string& array = {}) const;
  // The name of the kernel recording `serial` made (empty if none did).
  static std::string name_of(std::uint32_t serial);

  // ---- Declarations (by kernels and their callers) ----
  int declare_array(std::string name, std::int64_t length,
                    ArrayStorage storage = ArrayStorage::pointer,
                    ElementType element = ElementType::real);
  int access(int array, std::int64_t index);
  // array[subscript], where INT node `subscript` (computed in this recording) had the value
  // `index` in the run.
  int subscripted(int array, int subscript, std::int64_t index);

  // ---- Called by the recording scalars ----
  int constant(double value);
  int integer_constant(std::int32_t value);
  // `value`: an INT's, as the run computed it (a shift's time depends on its count); a REAL's is
  // not kept.
  int load(int access, double value = 0);
  int operation(NodeKind kind, int a, int b = -1, double value = 0);
  void store(int access, int node);
  int comparison(NodeKind kind, int a, int b, bool inverted);
  void test(int comparison, bool outcome);

  // ---- Called by occam structure markers ----
  void integer(IntegerStatement statement, std::int64_t count);
  void loop_begin(LoopBounds bounds = {});
  void iteration(std::int64_t index);
  void loop_end();
  // The open SEQs, and the index of the one at `depth` as an INT node (its value this iteration).
  int loop_depth() const { return int(loop_indices_.size()); }
  int loop_index(int depth);

  const std::vector<Node>& nodes() const { return nodes_; }
  const std::vector<Event>& events() const { return events_; }
  const std::vector<Access>& accesses() const { return accesses_; }
  const std::vector<ArrayDecl>& arrays() const { return arrays_; }
  const std::vector<LoopBounds>& loop_bounds() const { return loop_bounds_; }
  int blocks() const { return next_block_; }

 private:
  friend class RecordingScope;
  static Recording*& active() {
    thread_local Recording* recording = nullptr;
    return recording;
  }
  int add_node(Node node);
  int add_access(const Access& access);
  void add_event(Event e);
  int block() const;
  std::string name_;
  bool real64_;
  std::uint32_t serial_;
  std::vector<Node> nodes_;
  std::vector<Event> events_;
  std::vector<Access> accesses_;
  std::vector<LoopBounds> loop_bounds_;  // each SEQ's, in the order they began
  std::vector<ArrayDecl> arrays_;
  std::vector<int> open_blocks_{0};         // the block being recorded, innermost last
  std::vector<std::int64_t> loop_indices_;  // each open SEQ's index this iteration, innermost last
  int next_block_ = 1;
};

// Makes a recording the one receiving operations on this thread while it is alive (scopes nest:
// an inner one hides the outer until it ends).
class RecordingScope {
 public:
  explicit RecordingScope(Recording& recording);
  ~RecordingScope();
  RecordingScope(const RecordingScope&) = delete;
  RecordingScope& operator=(const RecordingScope&) = delete;

 private:
  Recording* outer_;
};

}  // namespace t800::codegen
