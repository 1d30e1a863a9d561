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
#include "t800/codegen/frame.hpp"
#include "t800/codegen/recording.hpp"

namespace t800::codegen {

struct Target;

// Where the emitter's instructions go, and what it needs from the code around it.
class EmitSink {
 public:
  virtual ~EmitSink() = default;
  virtual void emit(isa::Instruction instruction) = 0;
  // A library routine runs here (its code executes inline in the unit's runs).
  virtual void call(const CodeUnit& routine) = 0;
  // The address of a recorded array element on the integer stack.
  virtual void address(int access) = 0;
  // "u[k+3]": the element as the code subscripts it, for listings.
  virtual std::string element(int access) const = 0;
  virtual const Target& target() const = 0;
};

class ExpressionEmitter {
 public:
  ExpressionEmitter(const Recording& recording, EmitSink& sink, Frame& frame);

  // At node's value event: a local variable's assignment, when the node is one.
  void define(int node, int event);
  // x[i] := value.
  void store(int node, int access, int event);
  // IF on a comparison; `outcome` is its value.
  void test(int comparison, bool outcome, int event);

  int constant_bytes() const;
  std::vector<double> constant_table() const;  // the values, by their place in the table
  bool uses_constants() const { return uses_constants_; }

 private:
  struct Plan;  // how a binary operation is evaluated
  bool temporary(int n) const { return temporary_[std::size_t(n)]; }
  bool memory_operand(int n) const;
  int through(int n) const;  // n without the sign changes around it
  bool same_value(int a, int b) const;
  int need(int n);
  int need_expanded(int n);
  bool sign(int n);
  bool sign_expanded(int n);
  Plan plan(int n);

  bool value(int n);       // leaves n's magnitude on the FP stack, returns its sign
  bool expand(int n);      // the same, computing n (not its temporary)
  void true_value(int n);  // n itself, negated where its sign says so
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
  void analyse();
  std::string describe(int n) const;

  const Recording& r_;
  EmitSink& sink_;
  Frame& frame_;
  bool real64_;
  int words_;  // of a REAL
  std::vector<bool> live_, temporary_;
  std::vector<int> uses_, last_use_;
  std::vector<int> slot_;               // a temporary's workspace word, while it lives
  std::vector<int> need_;               // -1 = not worked out yet
  std::vector<signed char> sign_;       // -1 = not worked out yet
  std::multimap<int, int> release_at_;  // event -> temporaries whose last use it is
  std::map<double, int> constants_;     // value -> word offset in the constant table
  bool uses_constants_ = false;
};

}  // namespace t800::codegen
