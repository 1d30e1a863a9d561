// The statements of a recorded kernel compiled onto the T800's three-deep FP stack: which
// intermediate results are local variables (workspace temporaries), the evaluation order of
// every expression, spills, operand loads and the combined load-and-operate forms
// (generator.hpp lists the rules).
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "t800/codegen/code_unit.hpp"
#include "t800/codegen/dataflow.hpp"
#include "t800/codegen/frame.hpp"
#include "t800/codegen/recording.hpp"

namespace t800::codegen {

struct Target;
class IntegerEmitter;

// Where the emitter's instructions go, and what it needs from the code around it.
class EmitSink {
 public:
  virtual ~EmitSink() = default;
  virtual void emit(isa::Instruction instruction) = 0;
  // A library routine runs here (its code executes inline in the unit's runs).
  virtual void call(const CodeUnit& routine) = 0;
  // The address of a recorded array element on the integer stack.
  virtual void address(int access) = 0;
  // For the indexed loads (fpldnlsni, fpldnldbi): an element with a computed subscript as that
  // subscript, checked, in B and its array's base in A, returning true; for an element with a
  // constant subscript, false, emitting nothing (address() is its address).
  virtual bool subscript_and_base(int access) = 0;
  // Registers an element's address takes on the integer stack (1 for a constant subscript, 2 for
  // the loop's index, as many as a subscript the kernel computed needs, at least 2), and an INT
  // element loaded to, or stored from, A.
  virtual int address_need(int access) = 0;
  virtual void load_word(int access) = 0;
  virtual void store_word(int access) = 0;
  // The store into an element whose address() is in A, the value in B.
  virtual void store_word_at_address(int access) = 0;
  // "u[k+3]": the element as the code subscripts it, for listings.
  virtual std::string element(int access) const = 0;
  virtual const Target& target() const = 0;
};

class ExpressionEmitter {
 public:
  ExpressionEmitter(const Recording& recording, EmitSink& sink, Frame& frame, Dataflow& flow);
  // The INT expressions a REAL one converts (REALn ROUND n) are the integer emitter's.
  void connect(IntegerEmitter& integers) { integers_ = &integers; }

  // At node's value event: a local variable's assignment, when the node is one.
  void define(int node, int event);
  // x[i] := value.
  void store(int node, int access, int event);
  // IF on a comparison; `outcome` is its value.
  void test(int comparison, bool outcome, int event);

  // n's value on the FP stack, negated where its sign says so (INT ROUND x's x).
  void true_value(int n);

  int constant_bytes() const;
  std::vector<double> constant_table() const;  // the values, by their place in the table
  bool uses_constants() const { return flow_.uses_real_constants(); }

 private:
  struct Plan;  // how a binary operation is evaluated
  bool temporary(int n) const { return flow_.temporary(n); }
  bool memory_operand(int n) const;
  int through(int n) const { return flow_.through(n); }
  bool same_value(int a, int b) const;
  int need(int n);
  int need_expanded(int n);
  bool sign(int n);
  bool sign_expanded(int n);
  Plan plan(int n);

  bool value(int n);         // leaves n's magnitude on the FP stack, returns its sign
  bool expand(int n);        // the same, computing n (not its temporary)
  void from_integer(int n);  // REALn ROUND a: a's address, fpi32tor32/fpi32tor64
  void binary(int n);
  void leaf_address(int n);  // the address of a memory operand, for fpldnl* forms
  void load(int n);
  void operation(isa::Op op, const std::string& note);
  void store_fp(isa::MemoryRef where, const std::string& note);
  void release_after(int event);
  // Without an FPU (generator.hpp: Target::fpu).
  void soft_push(int n, int slot);
  int soft_value(int n);
  int soft_compute(int n);
  void soft_call(NodeKind kind, int a, int b, int result);
  void soft_store(int n, int access);
  std::string describe(int n) const;

  const Recording& r_;
  EmitSink& sink_;
  Frame& frame_;
  Dataflow& flow_;
  IntegerEmitter* integers_ = nullptr;
  bool real64_;
  int words_;                        // of a REAL
  std::vector<int> need_;            // -1 = not worked out yet
  std::vector<signed char> sign_;    // -1 = not worked out yet
  std::map<double, int> constants_;  // value -> word offset in the constant table
};

}  // namespace t800::codegen
