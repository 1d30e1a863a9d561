#include "t800/codegen/integer_expression.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>

#include "t800/codegen/generator.hpp"

namespace t800::codegen {

using isa::Instruction;
using isa::MemoryRef;
using isa::Op;
using isa::Region;

namespace {

Op integer_instruction(NodeKind k) {
  switch (k) {
    case NodeKind::add:
      return Op::add;
    case NodeKind::sub:
      return Op::sub;
    case NodeKind::mul:
      return Op::mul;
    case NodeKind::div:
      return Op::div;
    case NodeKind::rem:
      return Op::rem;
    case NodeKind::bit_and:
      return Op::and_;
    case NodeKind::bit_or:
      return Op::or_;
    case NodeKind::bit_xor:
      return Op::xor_;
    case NodeKind::shift_left:
      return Op::shl;
    case NodeKind::shift_right:
      return Op::shr;
    case NodeKind::greater:
      return Op::gt;
    case NodeKind::equal:
      return Op::diff;  // then eqc 0
    default:
      break;
  }
  throw std::logic_error("integer_instruction: not a binary INT operation");
}

}  // namespace

// How a binary INT operation is compiled (occ21 be/gen4.c tdop, gen7.c trelop, bind2.c mapdop).
struct IntegerEmitter::Plan {
  enum class How {
    constant,        // left, then adc k (+ k, - k) or eqc k (= k)
    left_alone,      // a <> 0: the value itself is the condition
    doubled,         // a * 2: left, dup, add
    shift_constant,  // a << k, a >> k: the shapes of code1k.c genshiftimmediate
    left_first,
    right_first,  // then rev, for a non-commutative operation
    spill,        // right into a temporary, left, the temporary
  };
  How how = How::left_first;
  int left = -1, right = -1;  // the operands, a constant one of a product or = on the right
  std::int64_t k = 0;         // the constant operand's value
  int need = 1;
};

IntegerEmitter::IntegerEmitter(const Recording& recording, EmitSink& sink, Frame& frame,
                               Dataflow& flow, ExpressionEmitter& reals)
    : r_(recording), sink_(sink), frame_(frame), flow_(flow), reals_(reals) {}

void IntegerEmitter::emit(Op op, std::int64_t operand, const std::string& note,
                          std::int64_t param) {
  Instruction in;
  in.op = op;
  in.operand = operand;
  in.param = param;
  if (op == Op::ldl || op == Op::stl) in.data = {Region::workspace, -1};
  in.note = note;
  sink_.emit(in);
}

std::string IntegerEmitter::describe(int n) const {
  if (!sink_.target().notes) return {};
  const Node& node = r_.nodes()[std::size_t(n)];
  if (temporary(n)) return "t" + std::to_string(n);
  if (node.kind == NodeKind::load) return sink_.element(node.access);
  if (node.kind == NodeKind::constant) return std::to_string(std::int64_t(node.value));
  if (node.kind == NodeKind::loop_index) return loop_index_name(node.depth);
  return "(...)";
}

bool IntegerEmitter::constant(int n) const {
  return r_.nodes()[std::size_t(n)].kind == NodeKind::constant && !temporary(n);
}

// Loaded by one instruction from where it is (occ21's "addressable"): a variable, a temporary, a
// loop's index, an element with a constant subscript.
bool IntegerEmitter::addressable(int n) const {
  const Node& node = r_.nodes()[std::size_t(n)];
  return temporary(n) || node.kind == NodeKind::loop_index ||
         (node.kind == NodeKind::load && sink_.address_need(node.access) == 1);
}

// The registers an operand takes: a shift's count checked against 33 (ldc 33; csub0) takes one
// more.
int IntegerEmitter::operand_need(int n, bool checked_count) {
  return need(n) + (checked_count ? 1 : 0);
}

IntegerEmitter::Plan IntegerEmitter::plan(int n) {
  const Node& node = r_.nodes()[std::size_t(n)];
  Plan p;
  p.left = node.a;
  p.right = node.b;
  // The constant operand of a sum, a product or = goes on the right.
  if ((node.kind == NodeKind::add || node.kind == NodeKind::mul || node.kind == NodeKind::equal) &&
      constant(p.left) && !constant(p.right))
    std::swap(p.left, p.right);
  const bool k_right = constant(p.right);
  if (k_right) p.k = std::int64_t(r_.nodes()[std::size_t(p.right)].value);
  const bool shift = node.kind == NodeKind::shift_left || node.kind == NodeKind::shift_right;
  const bool mint = p.k == std::numeric_limits<std::int32_t>::min();
  if (k_right && (node.kind == NodeKind::add || (node.kind == NodeKind::sub && !mint) ||
                  (node.kind == NodeKind::equal && !node.inverted))) {
    p.how = Plan::How::constant;
    if (node.kind == NodeKind::sub) p.k = -p.k;
  } else if (k_right && node.kind == NodeKind::equal && node.inverted && p.k == 0) {
    p.how = Plan::How::left_alone;
  } else if (k_right && node.kind == NodeKind::mul && p.k == 2) {
    p.how = Plan::How::doubled;
    p.need = std::max(need(p.left), 2);
    return p;
  } else if (k_right && shift) {
    p.how = Plan::How::shift_constant;
    p.need = std::max(need(p.left), 2);
    return p;
  }
  if (p.how == Plan::How::constant || p.how == Plan::How::left_alone) {
    p.need = need(p.left);
    return p;
  }
  const bool checked_count = shift && sink_.target().checked;
  const int nl = need(p.left), nr = operand_need(p.right, checked_count);
  if (nl >= kStackDepth && nr >= kStackDepth) {
    p.how = Plan::How::spill;
    p.need = kStackDepth;
    return p;
  }
  // The left first when it needs the whole stack, or when neither does and the operation is not
  // commutative (no rev); the right first when it needs the whole stack, or, for a commutative
  // operation, when the left is loaded by one instruction and the right is not (tdop's tie-break:
  // the addressable operand last).
  const bool right_first =
      nl < kStackDepth && (nr >= kStackDepth || (is_commutative(node.kind) && addressable(p.left) &&
                                                 !addressable(p.right)));
  p.how = right_first ? Plan::How::right_first : Plan::How::left_first;
  p.need = right_first ? std::max(nr, nl + 1) : std::max(nl, nr + 1);
  return p;
}

int IntegerEmitter::need(int n) {
  const Node& node = r_.nodes()[std::size_t(n)];
  if (temporary(n) || node.kind == NodeKind::constant || node.kind == NodeKind::loop_index)
    return 1;
  if (node.kind == NodeKind::load) return sink_.address_need(node.access);
  if (node.kind == NodeKind::bit_not) return need(node.a);
  return plan(n).need;
}

void IntegerEmitter::value(int n) {
  if (temporary(n)) {
    emit(Op::ldl, flow_.slot(n), "load " + describe(n));
    return;
  }
  expand(n);
}

void IntegerEmitter::expand(int n) {
  const Node& node = r_.nodes()[std::size_t(n)];
  switch (node.kind) {
    case NodeKind::constant:
      emit(Op::ldc, std::int64_t(node.value), describe(n));
      return;
    case NodeKind::load:
      sink_.load_word(node.access);
      return;
    case NodeKind::loop_index:
      emit(Op::ldl, frame_.loop_index(node.depth), describe(n));
      return;
    case NodeKind::bit_not:
      value(node.a);
      emit(Op::not_, 0, "~ " + describe(node.a));
      return;
    default:
      binary(n);
      return;
  }
}

// A shift by a constant, as code1k.c genshiftimmediate has it: << 0 is nothing, << 1 dup; bsub,
// << 2 bcnt (A * 4), << 3 ldc 0; wsubdb (8 B), << 4 and << 6 two and three bcnts; others ldc k then
// shl or shr.
void IntegerEmitter::shift_by_constant(NodeKind kind, std::int64_t k, const std::string& note) {
  if (kind == NodeKind::shift_left) {
    switch (k) {
      case 0:
        return;
      case 1:
        emit(Op::dup, 0, note);
        emit(Op::bsub, 0, note);
        return;
      case 3:
        emit(Op::ldc, 0, note);
        emit(Op::wsubdb, 0, note);
        return;
      case 2:
      case 4:
      case 6:
        for (std::int64_t i = 0; i < k / 2; ++i) emit(Op::bcnt, 0, note);
        return;
      default:
        break;
    }
  }
  emit(Op::ldc, k, note);
  emit(kind == NodeKind::shift_left ? Op::shl : Op::shr, 0, note, k);
}

void IntegerEmitter::binary(int n) {
  const Node& node = r_.nodes()[std::size_t(n)];
  const Plan p = plan(n);
  const std::string note =
      describe(p.left) + " " + operator_symbol(node.kind) + " " + describe(p.right);
  const bool shift = node.kind == NodeKind::shift_left || node.kind == NodeKind::shift_right;
  switch (p.how) {
    case Plan::How::constant:
      value(p.left);
      if (p.k != 0 || node.kind == NodeKind::equal)  // adc 0 is left out
        emit(node.kind == NodeKind::equal ? Op::eqc : Op::adc, p.k, note);
      return;
    case Plan::How::left_alone:
      value(p.left);
      return;
    case Plan::How::doubled:
      value(p.left);
      emit(Op::dup, 0, note);
      emit(Op::add, 0, note);
      return;
    case Plan::How::shift_constant:
      value(p.left);
      shift_by_constant(node.kind, p.k, note);
      return;
    case Plan::How::left_first:
      value(p.left);
      value(p.right);
      break;
    case Plan::How::right_first:
      value(p.right);
      value(p.left);
      if (!is_commutative(node.kind)) emit(Op::rev, 0, "");
      break;
    case Plan::How::spill: {
      value(p.right);
      const int spill = frame_.allocate_temporary(1);
      emit(Op::stl, spill, "spill");
      value(p.left);
      emit(Op::ldl, spill, "spilled operand");
      frame_.release_temporary(spill, 1);
      break;
    }
  }
  if (shift && sink_.target().checked) {
    // occ21 checks a computed count (tran1.c: CSUB0 (n, 33)); the count is on top here only
    // when it went last.
    if (p.how == Plan::How::left_first) {
      emit(Op::ldc, 33, "places");
      emit(Op::csub0, 0, "0 <= places <= 32");
    }
  }
  // A shift's time is the places it shifts, a prod's the highest set bit of A: the values as the
  // run had them.
  const auto run_value = [&](int x) { return std::int64_t(r_.nodes()[std::size_t(x)].value); };
  const int top = p.how == Plan::How::right_first ? p.left : p.right;
  std::int64_t param = shift ? run_value(p.right) : 0;
  Op op = integer_instruction(node.kind);
  if (node.kind == NodeKind::mul && !sink_.target().checked) {
    op = Op::prod;  // no run-time checks: the unchecked product (occ21 tran1.c, tdop)
    const std::uint32_t a = std::uint32_t(std::int32_t(run_value(top)));
    param = a ? 31 - __builtin_clz(a) : 0;
  }
  emit(op, 0, note, param);
  // =: diff; eqc 0. The negated conditions (>=, <=: gt; eqc 0; <>: diff alone).
  const bool equality = node.kind == NodeKind::equal;
  if (equality != node.inverted) emit(Op::eqc, 0, node.inverted ? "NOT" : "= 0");
}

// INT ROUND x: fprtoi32 rounds FA to an integral value in the FPU's mode (nearest by default,
// zero after fpurz for TRUNC) and sets the FP error flag when it is not an INT; unchecked, fpint
// rounds alone. fpstnli32 stores it as an INT into the variable's word (occ21 gen11.c,
// tsimpleassign; bind2.c mapexp makes it a temporary inside an expression).
void IntegerEmitter::to_int(int n) {
  const Node& node = r_.nodes()[std::size_t(n)];
  reals_.true_value(node.a);
  const bool truncate = node.kind == NodeKind::int_trunc;
  if (truncate) emit(Op::fpurz, 0, "TRUNC: round towards zero");
  emit(sink_.target().checked ? Op::fprtoi32 : Op::fpint, 0, truncate ? "INT TRUNC" : "INT ROUND");
}

void IntegerEmitter::define(int n, int event) {
  if (!temporary(n)) return;
  const Node& node = r_.nodes()[std::size_t(n)];
  const std::string name = describe(n) + " :=";
  if (is_conversion_to_int(node.kind)) {
    to_int(n);
    flow_.release_after(event, frame_);
    flow_.assign(n, frame_);
    emit(Op::ldlp, flow_.slot(n), name);
    // fprtoi32 leaves the FP error flag to be checked before the store (occ21 gen11.c).
    if (sink_.target().checked) emit(Op::fpchkerror, 0, "check FP error");
    Instruction in;
    in.op = Op::fpstnli32;
    in.data = {Region::workspace, -1};
    in.note = name;
    sink_.emit(in);
    return;
  }
  expand(n);
  flow_.release_after(event, frame_);
  flow_.assign(n, frame_);
  emit(Op::stl, flow_.slot(n), name);
}

// The value, then the element's address onto it (stnl stores B at A). An address that needs the
// whole stack (a subscript the kernel computed) goes first and the value onto it, swapped by rev;
// a value that needs the whole stack too waits in a workspace word meanwhile.
void IntegerEmitter::store(int node, int access, int event) {
  if (sink_.address_need(access) < kStackDepth) {
    value(node);
    sink_.store_word(access);
  } else {
    int scratch = -1;
    if (need(node) >= kStackDepth) {
      value(node);
      scratch = frame_.allocate_temporary(1);
      emit(Op::stl, scratch, "hold " + describe(node));
    }
    sink_.address(access);
    if (scratch >= 0)
      emit(Op::ldl, scratch, "load " + describe(node));
    else
      value(node);
    emit(Op::rev, 0, "");
    sink_.store_word_at_address(access);
    if (scratch >= 0) frame_.release_temporary(scratch, 1);
  }
  flow_.release_after(event, frame_);
}

void IntegerEmitter::test(int comparison, bool outcome, int event) {
  if (!is_comparison(r_.nodes()[std::size_t(comparison)].kind))
    throw std::logic_error("IntegerEmitter::test: not a comparison");
  binary(comparison);
  // cj jumps when the condition is false.
  emit(Op::cj, 4, outcome ? "IF (true)" : "IF (false: jump)", outcome ? 0 : 1);
  flow_.release_after(event, frame_);
}

int IntegerEmitter::push_address(int n) {
  const Node& node = r_.nodes()[std::size_t(n)];
  if (temporary(n)) {
    emit(Op::ldlp, flow_.slot(n), describe(n));
    return -1;
  }
  if (node.kind == NodeKind::load) {
    sink_.address(node.access);
    return -1;
  }
  if (node.kind == NodeKind::loop_index) {
    emit(Op::ldlp, frame_.loop_index(node.depth), describe(n));
    return -1;
  }
  expand(n);
  const int scratch = frame_.allocate_temporary(1);
  emit(Op::stl, scratch, "INT to convert");
  emit(Op::ldlp, scratch, "INT to convert");
  return scratch;
}

MemoryRef IntegerEmitter::memory_of(int n) const {
  const Node& node = r_.nodes()[std::size_t(n)];
  if (temporary(n) || node.kind != NodeKind::load) return {Region::workspace, -1};
  const int array = r_.accesses()[std::size_t(node.access)].array;
  if (r_.arrays()[std::size_t(array)].storage == ArrayStorage::workspace)
    return {Region::workspace, -1};
  return {Region::array, array};
}

}  // namespace t800::codegen
