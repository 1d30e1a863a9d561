// The run-time library routines, each as the instruction sequence of its usual path (a normal,
// finite argument), written from the routine's algorithm:
//   SIN, COS (REAL32) and DSIN, DCOS (REAL64), the INMOS maths library (D7205A toolset,
//   sinfl.occ / cosfl.occ / dsinfl.occ): Cody and Waite's method -- N = ROUND(X / pi), the
//   argument reduced in REAL64 (REAL32) or in two parts (REAL64), an odd polynomial in g = x*x of
//   4 (REAL32) or 8 (REAL64) coefficients by Horner's rule, the sign from N's parity;
//   REAL32OP / REAL64OP, the T414's software arithmetic (called as REAL32OPERR%CHK(a, op, b) by
//   the INMOS compiler): unpack both operands, align, operate on the fractions, normalise, round,
//   with the T414's floating-point support instructions.
// Their timing follows from the instruction tables like any generated code; docs/compute-model.md
// ("What is assumed") states what is assumed (U).
#include "t800/codegen/runtime_library.hpp"

#include <map>
#include <mutex>  // std::recursive_mutex: SQRT's code is built from the arithmetic routines
#include <stdexcept>
#include <tuple>

#include "t800/codegen/generator.hpp"

namespace t800::codegen {

namespace {

using isa::Instruction;
using isa::MemoryRef;
using isa::Op;
using isa::Region;

const MemoryRef kWorkspace{Region::workspace, -1};
const MemoryRef kLibrary{Region::library, -1};

// A routine's code, written line by line.
class Code {
 public:
  explicit Code(bool real64) : real64_(real64) {}
  Code& op(Op o, std::string note = {}, MemoryRef data = {}, std::int64_t param = 0) {
    code_.push_back({o, 0, param, real64_, data, std::move(note)});
    return *this;
  }
  Code& with(Op o, std::int64_t operand, std::string note = {}, MemoryRef data = {},
             std::int64_t param = 0) {
    code_.push_back({o, operand, param, real64_, data, std::move(note)});
    return *this;
  }
  // Local variable k: its value, its address, a store.
  Code& ldl(int k, std::string note = {}) { return with(Op::ldl, k, std::move(note), kWorkspace); }
  Code& stl(int k, std::string note = {}) { return with(Op::stl, k, std::move(note), kWorkspace); }
  Code& ldlp(int k, std::string note = {}) { return with(Op::ldlp, k, std::move(note)); }
  // A REAL from memory, the address on the stack: load, load-and-add, load-and-multiply, store.
  Code& fpload(MemoryRef where, std::string note = {}) {
    return op(real64_ ? Op::fpldnldb : Op::fpldnlsn, std::move(note), where);
  }
  Code& fpadd_from(MemoryRef where, std::string note = {}) {
    return op(real64_ ? Op::fpldnladddb : Op::fpldnladdsn, std::move(note), where);
  }
  Code& fpmul_from(MemoryRef where, std::string note = {}) {
    return op(real64_ ? Op::fpldnlmuldb : Op::fpldnlmulsn, std::move(note), where);
  }
  Code& fpstore(std::string note = {}) {
    return op(real64_ ? Op::fpstnldb : Op::fpstnlsn, std::move(note), kWorkspace);
  }
  // Constant k of the routine's table (its pointer in local 0).
  Code& constant(int k) {
    ldl(0, "constant table");
    if (k > 0) with(Op::ldnlp, k * (real64_ ? 2 : 1), "constant " + std::to_string(k));
    return *this;
  }
  // cj, taken or not on the usual path.
  Code& cj(bool taken, std::string note) { return with(Op::cj, 6, std::move(note), {}, taken); }
  isa::Sequence take() { return std::move(code_); }

 private:
  bool real64_;
  isa::Sequence code_;
};

CodeUnit unit(std::string name, bool real64, isa::Sequence code, int constants, int workspace) {
  CodeUnit u;
  u.name = std::move(name);
  u.real64 = real64;
  for (const Instruction& in : code) u.code_bytes += in.bytes();
  u.constant_bytes = constants * (real64 ? 8 : 4);
  u.workspace_words = workspace;
  u.runs.push_back({u.name, std::move(code), 1, true});
  return u;
}

// SIN and COS with an FPU. Frame: 0 constant table, 1 N, 2 XWork, 3 g, then the call linkage;
// the argument (REAL32 by value, REAL64 by address) is the first parameter, above the linkage.
CodeUnit sine_or_cosine(bool cosine, bool real64) {
  const int frame = real64 ? 20 : 5;
  const int argument = frame + 1;
  const int coefficients = real64 ? 8 : 4;
  const std::string name = std::string(real64 ? "D" : "") + (cosine ? "COS" : "SIN");
  Code c(real64);
  auto load_x = [&] {
    if (real64) {
      c.ldl(argument, "X (its address)").fpload(kWorkspace, "X");
    } else {
      c.ldlp(argument, "X").fpload(kWorkspace, "X");
    }
  };
  c.with(Op::ajw, -frame, "enter");
  c.with(Op::ldc, 40, "constant table").op(Op::ldpi).stl(0);
  load_x();
  c.op(Op::fpnotfinite, "X finite?").cj(true, "finite");
  c.constant(0).fpload(kLibrary, "SMax");
  load_x();
  c.op(Op::fpuabs, "ABS X").op(Op::fpgt, "ABS X < SMax").cj(false, "in range");
  // N := INT32 ROUND (X / pi), for COS of (ABS X + pi/2).
  load_x();
  if (cosine) c.op(Op::fpuabs).constant(1).fpadd_from(kLibrary, "+ pi/2");
  c.constant(2).fpmul_from(kLibrary, "* 1/pi");
  c.op(Op::fprtoi32, "ROUND").ldlp(1, "N").op(Op::fpstnli32, "N :=", kWorkspace);
  // XWork := X - N * pi (COS: (N - 1/2) * pi), in REAL64 for REAL32, in two parts for REAL64.
  load_x();
  if (cosine) c.op(Op::fpuabs);
  if (!real64) c.op(Op::fpur32tor64, "REAL64 X");
  c.ldlp(1, "N").op(Op::fpi32tor64, "REAL64 N", kWorkspace);
  if (cosine) c.constant(3).op(Op::fpldnlsn, "1/2", kLibrary).op(Op::fpsub, "N - 1/2");
  c.constant(4).op(Op::fpldnlmuldb, "* pi", kLibrary).op(Op::fpsub, "X - N pi");
  if (real64) {  // the second part of pi
    c.ldlp(1).op(Op::fpi32tor64, "REAL64 N", kWorkspace);
    c.constant(5).op(Op::fpldnlmuldb, "* pi (second part)", kLibrary).op(Op::fpsub);
  } else {
    c.op(Op::fpur64tor32, "REAL32 ROUND");
  }
  c.ldlp(2, "XWork").fpstore("XWork :=");
  // IF ABS XWork > nearly pi/2: the result is +-1 (not the usual path).
  c.constant(6).fpload(kLibrary, "nearly pi/2").ldlp(2).fpload(kWorkspace, "XWork");
  c.op(Op::fpuabs).op(Op::fpgt).cj(false, "ABS XWork < nearly pi/2");
  // g := XWork * XWork; R := (...((R0 g + R1) g + R2) ...) g.
  c.ldlp(2).fpload(kWorkspace, "XWork").op(Op::fpdup).op(Op::fpmul, "g").ldlp(3).fpstore("g :=");
  c.constant(7).fpload(kLibrary, "R0");
  for (int k = 1; k < coefficients; ++k) {
    c.ldlp(3).fpmul_from(kWorkspace, "* g");
    c.constant(7 + k).fpadd_from(kLibrary, "+ R" + std::to_string(k));
  }
  c.ldlp(3).fpmul_from(kWorkspace, "* g");
  // XWork + XWork * R, negated when N is odd.
  c.ldlp(2).fpmul_from(kWorkspace, "* XWork").ldlp(2).fpadd_from(kWorkspace, "+ XWork");
  c.ldl(1, "N").with(Op::ldc, 1).op(Op::and_, "N odd?").cj(true, "even: keep the sign");
  c.with(Op::ajw, frame, "leave").op(Op::ret);
  return unit(name, real64, c.take(), 7 + coefficients, frame + 4);
}

// SIN and COS without an FPU (the library's fixed-point versions, sinfx.occ): the fraction is
// unpacked, reduced by a two-part pi with long multiplies, and the polynomial evaluated in
// fixed point with fmul (FRACMUL); REAL64 fractions take two words, so each product takes four
// long multiplies.
CodeUnit fixed_point_sine_or_cosine(bool cosine, bool real64) {
  const int frame = real64 ? 60 : 50;
  const int coefficients = real64 ? 8 : 4;
  const std::string name =
      std::string(real64 ? "D" : "") + (cosine ? "COS" : "SIN") + " (fixed point)";
  Code c(false);
  c.with(Op::ajw, -frame, "enter");
  c.ldl(frame + 1, "X").op(Op::unpacksn, "unpack").stl(1, "exponent").stl(2, "fraction").stl(3);
  c.ldl(3, "type").cj(false, "a normal number");
  if (cosine) c.ldl(2).with(Op::ldc, 0x6487ED51).op(Op::add, "+ pi/2").stl(2);
  // N := ROUND (X / pi), then the two-part reduction X - N C1 - N C2.
  c.ldl(2)
      .with(Op::ldc, 0x517CC1B7, "1/pi")
      .op(Op::fmul, "X / pi")
      .ldl(1)
      .op(Op::shr, "scale", {}, 8);
  c.stl(4, "N");
  for (int part = 0; part < 2; ++part) {
    c.with(Op::ldc, 0).ldl(4).with(Op::ldc, 0x6487ED51, "pi part").op(Op::lmul, "N pi");
    c.ldl(2).op(Op::rev).op(Op::lsub, "reduce").stl(2);
  }
  const int products = real64 ? 4 : 1;  // partial products of a fixed-point multiply
  auto multiply = [&](int a, int b, const char* note) {
    for (int k = 0; k < products; ++k) c.ldl(a).ldl(b).op(k == 0 ? Op::fmul : Op::lmul, note);
    for (int k = 1; k < products; ++k) c.op(Op::ladd);
  };
  multiply(2, 2, "g := x * x");
  c.stl(5, "g");
  c.with(Op::ldc, 0x2B8, "R0").stl(6);
  for (int k = 1; k < coefficients; ++k) {
    multiply(6, 5, "* g");
    c.with(Op::adc, 0x1000, "+ R").stl(6);
  }
  multiply(6, 5, "* g");
  c.stl(6);
  multiply(6, 2, "* x");
  c.ldl(2).op(Op::add, "+ x").stl(2);
  c.ldl(1).ldl(2).with(Op::ldc, 0).op(Op::norm, "normalise", {}, 1);
  c.op(Op::postnormsn, "post-normalise").op(Op::roundsn, "round");
  c.ldl(4, "N").with(Op::ldc, 1).op(Op::and_, "N odd?").cj(true, "even: keep the sign");
  c.with(Op::ajw, frame, "leave").op(Op::ret);
  return unit(name, real64, c.take(), coefficients + 3, frame + 4);
}

// The T414's REALnOP: one routine for + - * /, dispatching on the operation. A REAL32 fraction
// fits a word (unpacksn), a REAL64 one takes two (shifts and masks, double-length arithmetic).
CodeUnit software_arithmetic(NodeKind kind, bool real64) {
  const std::string name = real64 ? "REAL64OP" : "REAL32OP";
  const int frame = real64 ? 16 : 8;
  Code c(false);  // integer code throughout
  c.with(Op::ajw, -frame, "enter");
  c.ldl(frame + 2, "op").with(Op::eqc, 0).cj(kind != NodeKind::add, "dispatch");
  c.ldl(frame + 2, "op").with(Op::eqc, 2).cj(kind != NodeKind::mul, "dispatch");
  // Unpack both operands: fraction, exponent, type.
  for (int operand = 0; operand < 2; ++operand) {
    const int at = 1 + 3 * operand;
    if (real64) {
      c.ldl(frame + 1 + 2 * operand, "operand (address)")
          .with(Op::ldnl, 1, "high word", kWorkspace);
      c.stl(at + 1).ldl(at + 1).with(Op::ldc, 20).op(Op::shr, "exponent", {}, 20);
      c.with(Op::ldc, 0x7FF).op(Op::and_).stl(at);
      c.ldl(at + 1).with(Op::ldc, 0xFFFFF).op(Op::and_, "fraction high").stl(at + 1);
      c.ldl(frame + 1 + 2 * operand).with(Op::ldnl, 0, "low word", kWorkspace).stl(at + 2);
      c.ldl(at + 1).ldl(at + 2).with(Op::ldc, 11).op(Op::lshl, "normalise fraction", {}, 11);
      c.stl(at + 1).stl(at + 2);
    } else {
      c.ldl(frame + 1 + 2 * operand, "operand")
          .op(Op::unpacksn, "unpack")
          .stl(at)
          .stl(at + 1)
          .stl(at + 2);
    }
    c.ldl(at + 2, "type").cj(false, "a normal number");
  }
  switch (kind) {
    case NodeKind::add:
    case NodeKind::sub:
      // Align the smaller operand, add or subtract the fractions.
      c.ldl(1).ldl(4).op(Op::gt).cj(false, "larger exponent first");
      c.ldl(1).ldl(4).op(Op::diff).stl(7, "shift");
      if (real64) {
        c.ldl(5).ldl(6).ldl(7).op(Op::lshr, "align", {}, 4).stl(5).stl(6);
        c.with(Op::ldc, 0).ldl(3).ldl(6).op(Op::lsum).stl(3).ldl(2).ldl(5).op(Op::lsum).stl(2);
      } else {
        c.ldl(5).ldl(7).op(Op::shr, "align", {}, 4).ldl(2).op(Op::add, "add fractions").stl(2);
      }
      break;
    case NodeKind::mul:
      c.ldl(1).ldl(4).op(Op::add, "add exponents").stl(1);
      c.with(Op::ldc, 0).ldl(2).ldl(5).op(Op::lmul, "multiply fractions").stl(2).stl(3);
      if (real64)  // three more partial products of the two-word fractions
        for (int k = 0; k < 3; ++k) c.ldl(3).ldl(2).ldl(6).op(Op::lmul).op(Op::ladd).stl(3).stl(2);
      break;
    default:  // div
      c.ldl(1).ldl(4).op(Op::diff, "subtract exponents").stl(1);
      c.ldl(3).ldl(2).ldl(5).op(Op::ldiv, "divide fractions").stl(2).stl(3);
      if (real64)  // the second quotient word and the correction
        c.ldl(3)
            .with(Op::ldc, 0)
            .ldl(5)
            .op(Op::ldiv)
            .stl(3)
            .ldl(3)
            .ldl(6)
            .op(Op::lmul)
            .op(Op::lsub)
            .stl(3);
      break;
  }
  // Normalise and round.
  c.ldl(3).ldl(2).ldl(1).op(Op::norm, "normalise", {}, 1).stl(1).stl(2).stl(3);
  if (real64) {
    c.ldl(2).ldl(3).with(Op::ldc, 11).op(Op::lshr, "position the fraction", {}, 11).stl(3).stl(2);
    c.ldl(1).with(Op::ldc, 20).op(Op::shl, "exponent in place", {}, 20).ldl(2).op(Op::or_).stl(2);
    c.ldl(frame + 3, "result (address)")
        .ldl(2)
        .op(Op::rev)
        .with(Op::stnl, 1, "high word", kWorkspace);
    c.ldl(frame + 3).ldl(3).op(Op::rev).with(Op::stnl, 0, "low word", kWorkspace);
  } else {
    c.ldl(1).ldl(2).ldl(3).op(Op::postnormsn, "post-normalise").op(Op::roundsn, "round");
  }
  c.op(Op::cflerr, "check the result");
  c.with(Op::ajw, frame, "leave").op(Op::ret);
  return unit(name, real64, c.take(), 0, frame + 4);
}

// The T414's comparisons, ABS and SQRT: comparisons on the integer encoding (sign and magnitude),
// ABS by masking the sign, SQRT by Newton's iteration over REALnOP divisions.
CodeUnit software_other(NodeKind kind, bool real64) {
  Code c(false);
  const int frame = 4;
  std::string name = real64 ? "REAL64" : "REAL32";
  c.with(Op::ajw, -frame, "enter");
  const int high = real64 ? 1 : 0;
  switch (kind) {
    case NodeKind::greater:
    case NodeKind::equal:
      name += kind == NodeKind::greater ? "GT" : "EQ";
      c.ldl(frame + 1).with(Op::ldnl, high, "a", kWorkspace).stl(0);
      c.ldl(frame + 2).with(Op::ldnl, high, "b", kWorkspace).stl(1);
      c.ldl(0).op(Op::mint).op(Op::and_, "signs").ldl(1).op(Op::mint).op(Op::and_).op(Op::diff);
      c.cj(false, "same sign");
      c.ldl(0).ldl(1).op(kind == NodeKind::greater ? Op::gt : Op::diff, "compare magnitudes");
      break;
    case NodeKind::abs:
      name += "ABS";
      c.ldl(frame + 1).with(Op::ldnl, high, "x", kWorkspace).op(Op::mint).op(Op::not_).op(Op::and_);
      c.ldl(frame + 1).op(Op::rev).with(Op::stnl, high, "ABS x", kWorkspace);
      break;
    default: {  // sqrt: a first guess from the exponent, then Newton steps x := (x + a/x) / 2
      name += "SQRT";
      c.ldl(frame + 1)
          .with(Op::ldnl, high, "a", kWorkspace)
          .with(Op::ldc, 1)
          .op(Op::shr, "guess", {}, 1);
      c.stl(0);
      const CodeUnit& div = library_routine(NodeKind::div, real64, Target{false, true});
      const CodeUnit& add = library_routine(NodeKind::add, real64, Target{false, true});
      // One Newton step's own code runs `steps` times, each calling the division and the
      // addition, whose code is theirs (only their execution is SQRT's).
      Code step(false);
      for (const CodeUnit* u : {&div, &add})
        step.ldl(0)
            .with(Op::ldc, 0)
            .ldl(frame + 1)
            .with(Op::call, 1024, u->name, kWorkspace)
            .stl(0);
      step.ldl(0).with(Op::ldc, 1).op(Op::shr, "/ 2", {}, 1).stl(0);  // exponent - 1
      c.with(Op::ajw, frame, "leave").op(Op::ret);
      CodeUnit u = unit(name, real64, c.take(), 0, frame + 4 + div.workspace_words);
      const isa::Sequence step_code = step.take();
      for (const Instruction& in : step_code) u.code_bytes += in.bytes();
      const int steps = real64 ? 5 : 3;
      u.runs.push_back({name + " Newton step", step_code, steps, true});
      for (const CodeUnit* r : {&div, &add})
        for (const CodeRun& run : r->runs)
          u.runs.push_back({run.label, run.code, run.times * steps, true});
      u.routines = {&div, &add};
      return u;
    }
  }
  c.with(Op::ajw, frame, "leave").op(Op::ret);
  return unit(name, real64, c.take(), 0, frame + 4);
}

}  // namespace

const CodeUnit& library_routine(NodeKind kind, bool real64, const Target& target) {
  static std::recursive_mutex mutex;
  static std::map<std::tuple<int, bool, bool>, CodeUnit> cache;
  const std::lock_guard<std::recursive_mutex> lock(mutex);
  const auto key = std::make_tuple(int(kind), real64, target.fpu);
  auto found = cache.find(key);
  if (found != cache.end()) return found->second;
  CodeUnit u;
  if (kind == NodeKind::sine || kind == NodeKind::cosine) {
    u = target.fpu ? sine_or_cosine(kind == NodeKind::cosine, real64)
                   : fixed_point_sine_or_cosine(kind == NodeKind::cosine, real64);
  } else if (target.fpu) {
    throw std::logic_error("library_routine: the FPU computes this itself");
  } else if (kind == NodeKind::add || kind == NodeKind::sub || kind == NodeKind::mul ||
             kind == NodeKind::div) {
    u = software_arithmetic(kind, real64);
  } else {
    u = software_other(kind, real64);
  }
  return cache.emplace(key, std::move(u)).first->second;
}

}  // namespace t800::codegen
