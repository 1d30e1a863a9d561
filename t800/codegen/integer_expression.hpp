// The INT statements of a recorded kernel compiled onto the T800's three-deep integer stack (A,
// B, C) in the shapes the INMOS occam compiler's back end gives them (occ21, as kept in
// concurrency/kroc tools/occ21: be/gen4.c tdop, gen7.c trelop, gen11.c, bind2.c mapdop, code1k.c
// genshiftimmediate): the left operand first unless the right needs the whole stack (then rev),
// a commutative operation's one-load operand last, a workspace temporary only when both need all
// three; adc and eqc for constant operands, a * 2 as dup; add, shifts by constants as bcnt and
// their kin; gt, diff, eqc 0 for the comparisons and cj for the IF; stores into elements and
// workspace variables; the conversions between INT and REAL through the workspace (fprtoi32,
// fpstnli32, fpi32tor32/fpi32tor64). docs/compute-model.md, "INT kernels", lists the rules.
#pragma once

#include <string>

#include "t800/codegen/dataflow.hpp"
#include "t800/codegen/expression.hpp"

namespace t800::codegen {

class IntegerEmitter {
 public:
  IntegerEmitter(const Recording& recording, EmitSink& sink, Frame& frame, Dataflow& flow,
                 ExpressionEmitter& reals);

  // At an INT node's value event: a local variable's assignment, when the node is one.
  void define(int node, int event);
  // x[i] := value, for an INT element.
  void store(int node, int access, int event);
  // IF on an INT comparison; `outcome` is its value.
  void test(int comparison, bool outcome, int event);

  // For REALn ROUND n: leaves the address of INT n's value on the integer stack, storing it in a
  // scratch word first when it is computed here; returns that word (to release after the load),
  // or -1.
  int push_address(int n);
  // INT n's value into A, and the registers that takes (a computed subscript, for the generator).
  void evaluate(int n) { value(n); }
  int evaluation_need(int n) { return need(n); }
  isa::MemoryRef memory_of(int n) const;  // where that address points
  std::string describe(int n) const;

 private:
  struct Plan;  // how a binary operation is evaluated
  bool temporary(int n) const { return flow_.temporary(n); }
  bool constant(int n) const;
  bool addressable(int n) const;
  int operand_need(int n, bool checked_count);
  int need(int n);
  Plan plan(int n);
  void value(int n);   // n's value into A (its temporary's, when it is one)
  void expand(int n);  // the same, computing n
  void binary(int n);
  void shift_by_constant(NodeKind kind, std::int64_t k, const std::string& note);
  void to_int(int n);  // INT ROUND x, INT TRUNC x: x on the FP stack, stored as an INT
  void emit(isa::Op op, std::int64_t operand, const std::string& note, std::int64_t param = 0);

  const Recording& r_;
  EmitSink& sink_;
  Frame& frame_;
  Dataflow& flow_;
  ExpressionEmitter& reals_;
};

}  // namespace t800::codegen
