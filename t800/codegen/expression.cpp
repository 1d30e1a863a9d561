#include "t800/codegen/expression.hpp"

#include <algorithm>
#include <cstdio>
#include <stdexcept>

#include "t800/codegen/generator.hpp"
#include "t800/codegen/integer_expression.hpp"
#include "t800/codegen/runtime_library.hpp"

namespace t800::codegen {

using isa::Instruction;
using isa::MemoryRef;
using isa::Op;
using isa::Region;

namespace {

// A call into the run-time library: a relative address some kilobytes away, linked into a
// pfix slot (two prefix bytes).
constexpr std::int64_t kLibraryDistance = 1024;

bool binary_kind(NodeKind k) {
  return k == NodeKind::add || k == NodeKind::sub || k == NodeKind::mul || k == NodeKind::div ||
         is_comparison(k);
}
bool combinable(NodeKind k) {
  return k == NodeKind::add || k == NodeKind::mul;
}

// Where a memory operand lives: a temporary in the workspace, a constant in the code's table, an
// array element in its array.
MemoryRef leaf_memory(const Recording& r, const Node& node, bool temporary) {
  if (temporary) return {Region::workspace, -1};
  if (node.kind == NodeKind::constant) return {Region::code, -1};
  const int array = r.accesses()[std::size_t(node.access)].array;
  if (r.arrays()[std::size_t(array)].storage == ArrayStorage::workspace)
    return {Region::workspace, -1};
  return {Region::array, array};
}

}  // namespace

// How a binary operation is compiled: `left op right` (the operation's own operand order) after
// the operands' signs are folded into it, and in which order the operands reach the stack.
struct ExpressionEmitter::Plan {
  enum class How {
    square,         // x * x: x, fpdup, fpmul
    by_two,         // x * 2.0 or x / 2.0: fpumulby2 / fpudivby2
    combined,       // first, then fpldnladd/fpldnlmul of the memory operand
    memory_second,  // first, load second, op (fprev when second is the left operand)
    both,           // first, second, op (fprev when first is the right operand)
    spill,          // first, stored to a temporary; second; temporary as memory operand
  };
  NodeKind op = NodeKind::add;
  int left = -1, right = -1;
  bool negated = false;  // the node is -(left op right)
  How how = How::both;
  int first = -1, second = -1;
  int need = 1;
};

ExpressionEmitter::ExpressionEmitter(const Recording& recording, EmitSink& sink, Frame& frame,
                                     Dataflow& flow)
    : r_(recording),
      sink_(sink),
      frame_(frame),
      flow_(flow),
      real64_(recording.real64()),
      words_(recording.real64() ? 2 : 1) {
  need_.assign(r_.nodes().size(), -1);
  sign_.assign(r_.nodes().size(), -1);
}

// The same value: one node, or two reads of one element in one place (a variable read twice).
bool ExpressionEmitter::same_value(int a, int b) const {
  a = through(a);
  b = through(b);
  if (a == b) return true;
  const Node& x = r_.nodes()[std::size_t(a)];
  const Node& y = r_.nodes()[std::size_t(b)];
  if (x.kind != NodeKind::load || y.kind != NodeKind::load || x.block != y.block) return false;
  const Access& p = r_.accesses()[std::size_t(x.access)];
  const Access& q = r_.accesses()[std::size_t(y.access)];
  return p.array == q.array && p.index == q.index;
}

bool ExpressionEmitter::memory_operand(int n) const {
  n = through(n);
  const Node& node = r_.nodes()[std::size_t(n)];
  if (temporary(n)) return true;
  return node.kind == NodeKind::load || (node.kind == NodeKind::constant && node.value != 0.0);
}

// The sign a node's code leaves out: a sign change is folded into the additions, subtractions
// and products that consume it (a + -b is compiled as a - b), so a computed value may be the
// negative of the node's; this is the node's sign relative to what its code computes.
bool ExpressionEmitter::sign(int n) {
  if (sign_[std::size_t(n)] < 0) sign_[std::size_t(n)] = sign_expanded(n) ? 1 : 0;
  return sign_[std::size_t(n)] == 1;
}

bool ExpressionEmitter::sign_expanded(int n) {
  const Node& node = r_.nodes()[std::size_t(n)];
  switch (node.kind) {
    case NodeKind::neg:
      return !sign(node.a);
    case NodeKind::mul:
    case NodeKind::div:
      return sign(node.a) != sign(node.b);
    case NodeKind::add:
      return sign(node.a) && sign(node.b);  // -a + -b = -(a + b); mixed signs give a subtraction
    case NodeKind::sub:
      return sign(node.a) && !sign(node.b);  // -a - b = -(a + b)
    default:
      return false;
  }
}

ExpressionEmitter::Plan ExpressionEmitter::plan(int n) {
  const Node& node = r_.nodes()[std::size_t(n)];
  Plan p;
  p.op = node.kind;
  p.left = node.a;
  p.right = node.b;
  const bool sa = sign(node.a), sb = sign(node.b);
  if (node.kind == NodeKind::add && sa != sb) {  // a - b, or b - a
    p.op = NodeKind::sub;
    if (sa) std::swap(p.left, p.right);
  } else if (node.kind == NodeKind::sub && sa != sb) {  // a + b (negated when a was)
    p.op = NodeKind::add;
  } else if (node.kind == NodeKind::sub && sa && sb) {  // -a - -b = b - a
    std::swap(p.left, p.right);
  }
  p.negated = sign(n);

  auto two = [&](int x) {
    x = through(x);
    const Node& k = r_.nodes()[std::size_t(x)];
    return k.kind == NodeKind::constant && k.value == 2.0 && !temporary(x);
  };
  const int nl = need(p.left), nr = need(p.right);
  if (p.op == NodeKind::mul && same_value(p.left, p.right)) {
    p.how = Plan::How::square;
    p.first = p.left;
    p.need = std::max(nl, 2);
  } else if ((p.op == NodeKind::mul && (two(p.right) || two(p.left))) ||
             (p.op == NodeKind::div && two(p.right))) {
    p.how = Plan::How::by_two;
    p.first = two(p.right) ? p.left : p.right;
    p.need = need(p.first);
  } else if (combinable(p.op) && (memory_operand(p.right) || memory_operand(p.left))) {
    p.how = Plan::How::combined;
    p.second = memory_operand(p.right) ? p.right : p.left;
    p.first = p.second == p.right ? p.left : p.right;
    // fpldnladd/fpldnlmul push the memory operand and pop it with the result: FC is undefined
    // after them (CWG), so they need a second register even when the first operand needs one.
    p.need = std::max(need(p.first), 2);
  } else if (memory_operand(p.right)) {
    p.how = Plan::How::memory_second;
    p.first = p.left;
    p.second = p.right;
    p.need = std::max(nl, 2);
  } else if (memory_operand(p.left) && nr >= kStackDepth) {
    p.how = Plan::How::memory_second;  // the right operand first, then the left, fprev
    p.first = p.right;
    p.second = p.left;
    p.need = std::max(nr, 2);
  } else {
    // Both need registers (or a memory left operand that fits in front): the operand needing
    // more first when the order is free; left first when it is not, unless only the other
    // order fits.
    const bool right_first =
        is_commutative(p.op) ? nr > nl : (nr >= kStackDepth && nl < kStackDepth);
    p.first = right_first ? p.right : p.left;
    p.second = right_first ? p.left : p.right;
    const int nf = need(p.first), ns = need(p.second);
    if (ns < kStackDepth) {
      p.how = Plan::How::both;
      p.need = std::max(nf, ns + 1);
    } else {
      p.how = Plan::How::spill;
      p.need = std::max(nf, ns);
    }
  }
  return p;
}

int ExpressionEmitter::need(int n) {
  if (memory_operand(n)) return 1;
  if (need_[std::size_t(n)] < 0) need_[std::size_t(n)] = need_expanded(n);
  return need_[std::size_t(n)];
}

int ExpressionEmitter::need_expanded(int n) {
  const Node& node = r_.nodes()[std::size_t(n)];
  switch (node.kind) {
    case NodeKind::constant:
    case NodeKind::load:
      return 1;
    case NodeKind::neg:
    case NodeKind::abs:
      return need(node.a);
    case NodeKind::to_real:
      return 1;  // a load (fpi32tor32/fpi32tor64 push the converted value)
    case NodeKind::sqrt:
      return sign(node.a) ? std::min(kStackDepth, need(node.a) + 1) : need(node.a);
    default:
      break;
  }
  if (binary_kind(node.kind)) return plan(n).need;
  return 1;  // routines: always temporaries
}

// How a listing names an operand: an array element as subscripted, a constant by its value, a
// local variable by its node number, an inlined subexpression as (...).
std::string ExpressionEmitter::describe(int n) const {
  if (!sink_.target().notes) return {};
  n = through(n);
  const Node& node = r_.nodes()[std::size_t(n)];
  if (temporary(n)) return "t" + std::to_string(n);
  switch (node.kind) {
    case NodeKind::load:
      return sink_.element(node.access);
    case NodeKind::constant: {
      char text[32];
      std::snprintf(text, sizeof text, "%.6g", node.value);
      return text;
    }
    default:
      return "(...)";
  }
}

void ExpressionEmitter::operation(Op op, const std::string& note) {
  Instruction in;
  in.op = op;
  in.real64 = real64_;
  in.note = note;
  sink_.emit(in);
}

void ExpressionEmitter::leaf_address(int n) {
  n = through(n);
  const Node& node = r_.nodes()[std::size_t(n)];
  const std::string what = describe(n);
  if (temporary(n)) {
    sink_.emit({Op::ldlp, flow_.slot(n), 0, false, {}, what});
    return;
  }
  if (node.kind == NodeKind::load) {
    sink_.address(node.access);
    return;
  }
  // A REAL constant: the constant table's pointer (set up once by the PROC), then its word.
  const auto it = constants_.insert({node.value, int(constants_.size())}).first;
  const int words = real64_ ? 2 : 1;
  sink_.emit(
      {Op::ldl, frame_.constant_table(), 0, false, {Region::workspace, -1}, "constant table"});
  if (it->second > 0) sink_.emit({Op::ldnlp, std::int64_t(it->second) * words, 0, false, {}, what});
}

void ExpressionEmitter::load(int n) {
  n = through(n);
  const Node& node = r_.nodes()[std::size_t(n)];
  if (!temporary(n) && node.kind == NodeKind::constant && node.value == 0.0) {
    operation(real64_ ? Op::fpldzerodb : Op::fpldzerosn, "0.0");
    return;
  }
  Instruction in;
  in.data = leaf_memory(r_, node, temporary(n));
  in.note = "load " + describe(n);
  // An element with a computed subscript is loaded by the indexed load, which scales the
  // subscript itself (oc: ldl i; ldl x; fpldnldbi, where a load-and-operate takes wsubdb first).
  if (!temporary(n) && node.kind == NodeKind::load && sink_.subscript_and_base(node.access)) {
    in.op = real64_ ? Op::fpldnldbi : Op::fpldnlsni;
    sink_.emit(in);
    return;
  }
  leaf_address(n);
  in.op = real64_ ? Op::fpldnldb : Op::fpldnlsn;
  sink_.emit(in);
}

// Leaves the magnitude of n (as its code computes it) on the stack and returns n's sign.
bool ExpressionEmitter::value(int n) {
  const int core = through(n);
  if (memory_operand(core) || r_.nodes()[std::size_t(core)].kind == NodeKind::constant) {
    load(core);
    return sign(n);
  }
  return expand(n);
}

void ExpressionEmitter::true_value(int n) {
  if (!sign(n)) {
    value(n);
    return;
  }
  // -x: 0.0, x, fpsub; when x needs the whole stack, x first and the zero after it, fprev.
  if (need(n) < kStackDepth) {
    operation(real64_ ? Op::fpldzerodb : Op::fpldzerosn, "0.0 (negation)");
    value(n);
    operation(Op::fpsub, "negate");
  } else {
    value(n);
    operation(real64_ ? Op::fpldzerodb : Op::fpldzerosn, "0.0 (negation)");
    operation(Op::fprev, "");
    operation(Op::fpsub, "negate");
  }
}

bool ExpressionEmitter::expand(int n) {
  const Node& node = r_.nodes()[std::size_t(n)];
  switch (node.kind) {
    case NodeKind::neg:
      value(node.a);
      return sign(n);
    case NodeKind::abs:
      value(node.a);
      operation(Op::fpuabs, "ABS");
      return false;
    case NodeKind::to_real:
      from_integer(n);
      return false;
    case NodeKind::sqrt: {
      true_value(node.a);
      const int steps = real64_ ? 5 : 2;  // the FPU's square root: first, steps, last
      operation(Op::fpusqrtfirst, "SQRT");
      for (int s = 0; s < steps; ++s) operation(Op::fpusqrtstep, "SQRT");
      operation(Op::fpusqrtlast, "SQRT");
      return false;
    }
    default:
      break;
  }
  if (binary_kind(node.kind)) {
    binary(n);
    return sign(n);
  }
  throw std::logic_error("ExpressionEmitter: a library call outside a local variable");
}

namespace {
Op fp_instruction(NodeKind k) {
  switch (k) {
    case NodeKind::add:
      return Op::fpadd;
    case NodeKind::sub:
      return Op::fpsub;
    case NodeKind::mul:
      return Op::fpmul;
    case NodeKind::div:
      return Op::fpdiv;
    case NodeKind::greater:
      return Op::fpgt;
    case NodeKind::equal:
      return Op::fpeq;
    default:
      break;
  }
  throw std::logic_error("fp_instruction: not a binary operation");
}
}  // namespace

void ExpressionEmitter::binary(int n) {
  const Plan p = plan(n);
  const Op op = fp_instruction(p.op);
  const std::string note = describe(p.left) + " " + operator_symbol(p.op) + " " + describe(p.right);
  // The stack computes FB op FA: for a non-commutative operation the left operand must be in FB.
  auto finish = [&](bool left_on_top) {
    if (left_on_top && !is_commutative(p.op)) operation(Op::fprev, "");
    operation(op, note);
  };
  switch (p.how) {
    case Plan::How::square:
      value(p.first);
      operation(Op::fpdup, "");
      operation(Op::fpmul, note);
      return;
    case Plan::How::by_two:
      value(p.first);
      operation(p.op == NodeKind::mul ? Op::fpumulby2 : Op::fpudivby2, note);
      return;
    case Plan::How::combined: {
      value(p.first);
      leaf_address(p.second);
      Instruction in;
      in.op = p.op == NodeKind::add ? (real64_ ? Op::fpldnladddb : Op::fpldnladdsn)
                                    : (real64_ ? Op::fpldnlmuldb : Op::fpldnlmulsn);
      in.real64 = real64_;
      const int operand = through(p.second);
      in.data = leaf_memory(r_, r_.nodes()[std::size_t(operand)], temporary(operand));
      in.note = note;
      sink_.emit(in);
      return;
    }
    case Plan::How::memory_second:
      value(p.first);
      load(p.second);
      finish(p.second == p.left);
      return;
    case Plan::How::both:
      value(p.first);
      value(p.second);
      finish(p.first == p.right);
      return;
    case Plan::How::spill: {
      value(p.first);
      const int spill = frame_.allocate_temporary(words_);
      sink_.emit({Op::ldlp, spill, 0, false, {}, "spill"});
      store_fp({Region::workspace, -1}, "spill");
      value(p.second);
      sink_.emit({Op::ldlp, spill, 0, false, {}, "spilled operand"});
      if (combinable(p.op)) {
        Instruction in;
        in.op = p.op == NodeKind::add ? (real64_ ? Op::fpldnladddb : Op::fpldnladdsn)
                                      : (real64_ ? Op::fpldnlmuldb : Op::fpldnlmulsn);
        in.real64 = real64_;
        in.data = {Region::workspace, -1};
        in.note = note;
        sink_.emit(in);
      } else {
        Instruction in;
        in.op = real64_ ? Op::fpldnldb : Op::fpldnlsn;
        in.data = {Region::workspace, -1};
        in.note = "load spilled operand";
        sink_.emit(in);
        finish(p.first == p.left);  // the spilled (first) operand is on top now
      }
      frame_.release_temporary(spill, words_);
      return;
    }
  }
}

// The checked mode's FPU error check, then the store (the address is already on the stack).
void ExpressionEmitter::store_fp(MemoryRef where, const std::string& note) {
  if (sink_.target().checked) operation(Op::fpchkerror, "check FP error");
  Instruction in;
  in.op = real64_ ? Op::fpstnldb : Op::fpstnlsn;
  in.data = where;
  in.note = note;
  sink_.emit(in);
}

void ExpressionEmitter::release_after(int event) {
  flow_.release_after(event, frame_);
}

// REALn ROUND a loads the INT from memory: its workspace word, its element, or a word it is
// computed into here.
void ExpressionEmitter::from_integer(int n) {
  const int scratch = integers_->push_address(r_.nodes()[std::size_t(n)].a);
  Instruction in;
  in.op = real64_ ? Op::fpi32tor64 : Op::fpi32tor32;
  in.data = integers_->memory_of(r_.nodes()[std::size_t(n)].a);
  in.note = std::string(real64_ ? "REAL64" : "REAL32") + " ROUND " +
            integers_->describe(r_.nodes()[std::size_t(n)].a);
  sink_.emit(in);
  if (scratch >= 0) frame_.release_temporary(scratch);
}

void ExpressionEmitter::define(int n, int event) {
  if (!temporary(n)) return;
  if (!sink_.target().fpu) {
    const int value = soft_compute(n);
    release_after(event);
    flow_.adopt(n, value);
    return;
  }
  const Node& node = r_.nodes()[std::size_t(n)];
  const std::string name = describe(n);
  if (is_routine(node.kind)) {
    // A call destroys the FP stack: the argument goes through the workspace, by value (REAL32, in
    // an integer register) or by address (REAL64); the result comes back on the FP stack.
    true_value(node.a);
    const int argument = frame_.allocate_temporary(words_);
    sink_.emit({Op::ldlp, argument, 0, false, {}, "argument"});
    store_fp({Region::workspace, -1}, "argument");
    if (real64_)
      sink_.emit({Op::ldlp, argument, 0, false, {}, "argument's address"});
    else
      sink_.emit({Op::ldl, argument, 0, false, {Region::workspace, -1}, "argument"});
    const CodeUnit& routine = library_routine(node.kind, real64_, sink_.target());
    sink_.emit({Op::call, kLibraryDistance, 0, false, {Region::workspace, -1}, routine.name});
    sink_.call(routine);
    frame_.release_temporary(argument, words_);
  } else {
    expand(n);
  }
  release_after(event);
  flow_.assign(n, frame_);
  sink_.emit({Op::ldlp, flow_.slot(n), 0, false, {}, name + " :="});
  store_fp({Region::workspace, -1}, name + " :=");
}

void ExpressionEmitter::store(int node, int access, int event) {
  if (!sink_.target().fpu) {
    soft_store(node, access);
    release_after(event);
    return;
  }
  true_value(node);
  sink_.address(access);
  MemoryRef where{Region::array, r_.accesses()[std::size_t(access)].array};
  if (r_.arrays()[std::size_t(where.array)].storage == ArrayStorage::workspace)
    where = {Region::workspace, -1};
  store_fp(where, sink_.element(access) + " :=");
  release_after(event);
}

void ExpressionEmitter::test(int comparison, bool outcome, int event) {
  const Node& node = r_.nodes()[std::size_t(comparison)];
  if (!is_comparison(node.kind))
    throw std::logic_error("ExpressionEmitter::test: not a comparison");
  if (!sink_.target().fpu) {
    soft_call(node.kind, through(node.a), through(node.b), -1);
  } else if (sign(node.a) || sign(node.b)) {
    true_value(node.a);
    true_value(node.b);
    operation(fp_instruction(node.kind), "compare");
  } else {
    binary(comparison);
  }
  if (sink_.target().checked && sink_.target().fpu) operation(Op::fpchkerror, "check FP error");
  // cj jumps when the condition is false.
  sink_.emit({Op::cj, 4, outcome ? 0 : 1, false, {}, outcome ? "IF (true)" : "IF (false: jump)"});
  release_after(event);
}

int ExpressionEmitter::constant_bytes() const {
  return int(constants_.size()) * (real64_ ? 8 : 4);
}

std::vector<double> ExpressionEmitter::constant_table() const {
  std::vector<double> table(constants_.size());
  for (const auto& [value, place] : constants_) table[std::size_t(place)] = value;
  return table;
}

// ---- Without an FPU (a T414): every REAL operation a call of the run-time library ----
// The INMOS compiler calls REAL32OPERR%CHK(a, op, b) for each operation (its REAL64 twin with
// addresses): the operands' values (REAL32, a word each) or addresses (REAL64) go in the integer
// registers, `ldc op` between them, and the result comes back in A (REAL32) or through a pointer
// (REAL64), to be stored in the workspace: a call destroys the register stack, so every
// intermediate result is a workspace word.

// Pushes a REAL32 operand's value, or a REAL64 operand's address, onto the integer stack.
void ExpressionEmitter::soft_push(int n, int slot) {
  const MemoryRef ws{Region::workspace, -1};
  if (slot >= 0) {
    sink_.emit({real64_ ? Op::ldlp : Op::ldl, slot, 0, false, real64_ ? MemoryRef{} : ws, "t"});
    return;
  }
  const Node& node = r_.nodes()[std::size_t(n)];
  if (temporary(n)) {
    soft_push(n, flow_.slot(n));
    return;
  }
  if (node.kind == NodeKind::constant && node.value == 0.0 && !real64_) {
    sink_.emit({Op::ldc, 0, 0, false, {}, "0.0"});
    return;
  }
  leaf_address(n);
  if (!real64_) sink_.emit({Op::ldnl, 0, 0, false, leaf_memory(r_, node, false), describe(n)});
}

// The workspace word holding n's value (a new one for a computed node; -1 for a memory operand,
// which is pushed from where it is).
int ExpressionEmitter::soft_value(int n) {
  n = through(n);
  const Node& node = r_.nodes()[std::size_t(n)];
  if (temporary(n) || is_leaf(node.kind)) return -1;
  return soft_compute(n);
}

// Computes op node n into a fresh workspace word and returns it.
int ExpressionEmitter::soft_compute(int n) {
  const Node& node = r_.nodes()[std::size_t(n)];
  const int result = frame_.allocate_temporary(words_);
  switch (node.kind) {
    case NodeKind::neg: {  // the sign bit flipped
      const int a = soft_value(node.a);
      soft_push(through(node.a), a);
      if (real64_) {
        sink_.emit({Op::ldnl, 1, 0, false, {Region::workspace, -1}, "high word"});
      }
      sink_.emit({Op::mint, 0, 0, false, {}, "sign bit"});
      sink_.emit({Op::xor_, 0, 0, false, {}, "negate"});
      sink_.emit({Op::stl, result + (real64_ ? 1 : 0), 0, false, {Region::workspace, -1}, "t :="});
      if (a >= 0) frame_.release_temporary(a, words_);
      return result;
    }
    case NodeKind::abs:
    case NodeKind::sqrt:
    case NodeKind::sine:
    case NodeKind::cosine:
      soft_call(node.kind, through(node.a), -1, result);
      return result;
    default:
      break;
  }
  const Plan p = plan(n);  // the operation after the signs are folded in
  soft_call(p.op, through(p.left), through(p.right), result);
  if (p.negated) {
    sink_.emit({Op::ldl, result + (real64_ ? 1 : 0), 0, false, {Region::workspace, -1}, "t"});
    sink_.emit({Op::mint, 0, 0, false, {}, "sign bit"});
    sink_.emit({Op::xor_, 0, 0, false, {}, "negate"});
    sink_.emit({Op::stl, result + (real64_ ? 1 : 0), 0, false, {Region::workspace, -1}, "t :="});
  }
  return result;
}

// result := a op b (b < 0: a unary operation); a comparison leaves its result in A (result < 0).
void ExpressionEmitter::soft_call(NodeKind kind, int a, int b, int result) {
  const int va = soft_value(a);
  const int vb = b >= 0 ? soft_value(b) : -1;
  const CodeUnit& routine = library_routine(kind, real64_, sink_.target());
  if (real64_ && result >= 0) {
    sink_.emit({Op::ldlp, result, 0, false, {}, "result's address"});
    sink_.emit({Op::stl, 0, 0, false, {Region::workspace, -1}, "parameter"});
  }
  if (b >= 0) soft_push(b, vb);
  static const std::map<NodeKind, int> kOperation = {
      {NodeKind::add, 0}, {NodeKind::sub, 1}, {NodeKind::mul, 2}, {NodeKind::div, 3}};
  const auto code = kOperation.find(kind);
  if (code != kOperation.end()) sink_.emit({Op::ldc, code->second, 0, false, {}, "operation"});
  soft_push(a, va);
  sink_.emit({Op::call, kLibraryDistance, 0, false, {Region::workspace, -1}, routine.name});
  sink_.call(routine);
  if (!real64_ && result >= 0)
    sink_.emit({Op::stl, result, 0, false, {Region::workspace, -1}, "t :="});
  if (va >= 0) frame_.release_temporary(va, words_);
  if (vb >= 0) frame_.release_temporary(vb, words_);
}

// x[i] := value: the value's word(s) copied into the element.
void ExpressionEmitter::soft_store(int n, int access) {
  const int v = soft_value(n);
  const int core = through(n);
  int value = v;
  if (sign(n) && v < 0) {  // a negated memory operand: its sign flipped on the way
    value = frame_.allocate_temporary(words_);
    soft_push(core, -1);
    sink_.emit({Op::mint, 0, 0, false, {}, "sign bit"});
    sink_.emit({Op::xor_, 0, 0, false, {}, "negate"});
    sink_.emit({Op::stl, value, 0, false, {Region::workspace, -1}, "t :="});
  }
  const int words = real64_ ? 2 : 1;
  MemoryRef where{Region::array, r_.accesses()[std::size_t(access)].array};
  for (int w = 0; w < words; ++w) {
    if (value >= 0) {
      sink_.emit({Op::ldl, value + w, 0, false, {Region::workspace, -1}, "value"});
    } else {
      soft_push(core, -1);
      if (real64_)
        sink_.emit({Op::ldnl, w, 0, false,
                    leaf_memory(r_, r_.nodes()[std::size_t(core)], temporary(core)), "word"});
    }
    sink_.address(access);
    sink_.emit({Op::stnl, w, 0, false, where, sink_.element(access) + " :="});
  }
  if (value >= 0) frame_.release_temporary(value, words_);
}

}  // namespace t800::codegen
