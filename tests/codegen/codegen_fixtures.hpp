// Helpers for the code generator's tests: record a small kernel written against the instrumented
// scalar, compile it, and read the generated instructions back as mnemonics.
#pragma once

#include <string>
#include <vector>

#include "t800/codegen/generator.hpp"
#include "t800/processors/sequence_timing.hpp"
#include "workloads/occam/structure.hpp"

namespace codegen_test {

using C = dynamics::Counted<float>;
using t800::codegen::CodeUnit;
using t800::codegen::Target;
using t800::isa::Op;

using Int = dynamics::CountedInt;

// Eight workspace variables a..h (values 1..8) and two arrays x and y of 8 elements (parameters),
// all of scalar S, then `body`, recorded and compiled.
template <class S, class Body>
CodeUnit compile_with(Body body, Target target) {
  t800::codegen::Recording r("K", false);
  {
    const t800::codegen::RecordingScope scope(r);
    S a(1), b(2), c(3), d(4), e(5), f(6), g(7), h(8);
    for (S* v : {&a, &b, &c, &d, &e, &f, &g, &h}) occam::declare_variable(*v, "v");
    std::vector<S> x(8, S(0)), y(8, S(1));
    occam::declare(x, "x");
    occam::declare(y, "y");
    body(a, b, c, d, e, f, g, h, x, y);
  }
  return t800::codegen::generate(r, target);
}

// REAL32 variables and arrays, compiled without run-time checks unless `target` says otherwise.
template <class Body>
CodeUnit compile(Body body, Target target = Target{true, false}) {
  return compile_with<C>(body, target);
}

// INT variables and arrays, compiled with occam's default run-time checks unless `target` says
// otherwise.
template <class Body>
CodeUnit compile_int(Body body, Target target = Target{true, true}) {
  return compile_with<Int>(body, target);
}

// The unit's code as executed, between entering the PROC (its ajw) and leaving it, as "op
// operand" texts for direct functions and mnemonics for the rest: the statements' code alone.
inline std::vector<std::string> body_code(const CodeUnit& unit) {
  std::vector<std::string> ops;
  bool inside = false;
  for (const auto& run : unit.runs)
    for (std::int64_t time = 0; time < run.times; ++time)
      for (const auto& in : run.code) {
        if (in.op == Op::ajw) {
          inside = !inside;
          continue;
        }
        if (!inside) continue;
        ops.push_back(t800::isa::assembly(in));
      }
  return ops;
}

// Only the FPU's instructions of the body, in order.
inline std::vector<std::string> fpu_code(const CodeUnit& unit) {
  std::vector<std::string> ops;
  for (const std::string& s : body_code(unit))
    if (s.rfind("fp", 0) == 0) ops.push_back(s);
  return ops;
}

// The FP register stack's depth through the code (loads push, stores and binary operations pop);
// returns the deepest it gets, or -1 if it ever underflows.
inline int deepest_fp_stack(const CodeUnit& unit) {
  int depth = 0, deepest = 0;
  for (const auto& run : unit.runs)
    for (const auto& in : run.code) {
      switch (in.op) {
        case Op::fpldnlsn:
        case Op::fpldnldb:
        case Op::fpldnlsni:
        case Op::fpldnldbi:
        case Op::fpldzerosn:
        case Op::fpldzerodb:
        case Op::fpdup:
        case Op::fpi32tor32:
        case Op::fpi32tor64:
          ++depth;
          break;
        case Op::fpldnladdsn:
        case Op::fpldnladddb:
        case Op::fpldnlmulsn:
        case Op::fpldnlmuldb:
          // Load and operate: the operand is pushed, then the operation pops it with the result
          // (CWG), so for that moment the stack holds one more.
          deepest = std::max(deepest, depth + 1);
          break;
        case Op::fpstnlsn:
        case Op::fpstnldb:
        case Op::fpadd:
        case Op::fpsub:
        case Op::fpmul:
        case Op::fpdiv:
        case Op::fpgt:
        case Op::fpeq:
          --depth;
          break;
        default:
          break;
      }
      if (depth < 0) return -1;
      deepest = std::max(deepest, depth);
    }
  return deepest;
}

inline int count(const std::vector<std::string>& code, const std::string& op) {
  int n = 0;
  for (const std::string& s : code) n += s == op;
  return n;
}

}  // namespace codegen_test
