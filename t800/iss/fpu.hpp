// The T800's floating-point unit: the register stack FA, FB, FC (each register with its own
// length), the rounding mode and the FP error flag, and every FPU operation except memory access.
// The ISS does the loads and stores and hands bits in and out; one method per FPU instruction.
//
// Build: no special flags. Directed rounding is exact software rounding (fpu.cpp), not fesetround,
// so the results do not depend on -frounding-math or on the host's FP environment; round-to-nearest
// uses the host's IEEE arithmetic, which is exact for one operation on an IEEE-754 host with
// FLT_EVAL_METHOD == 0 (checked at compile time) and denormals on. Never build with -ffast-math
// (it flushes denormals and assumes no NaNs). -ffp-contract=off is harmless.
//
// Semantics (sources are cited where each is implemented, fpu.cpp): "Transputer instruction set: a
// compiler writer's guide" (INMOS 1988, CWG), the T800 datasheet, pahihu/t4 (fparithmetic.c, p.c,
// Notebook.txt: a T800 emulator checked against INMOS's validation suite TVS1F), and the code the
// INMOS occam compiler emits (concurrency/kroc tools/occ21). In short:
// - FB op FA: binary operations consume FA and FB and leave the result in FA; FB := FC.
// - Where the CWG leaves a register undefined it keeps its old value here: a pop leaves FC as it
//   was (FA := FB, FB := FC), and the square root's scratch use of FB and FC is not modelled.
// - The rounding mode set by set_rounding (fpurn/fpurz/fpurp/fpurm) applies to the next FPU
//   instruction only, whatever it is (a load counts); every other method ends by resetting it to
//   round-to-nearest. fpldnladd/fpldnlmul are one instruction: use load_add_*/load_mul_*.
// - The FP error flag is set by invalid operations, division by zero and overflow, and by any
//   infinite or NaN operand of arithmetic; never by underflow or inexact results.
#pragma once

#include <cstdint>

namespace t800::iss {

class Fpu {
 public:
  enum class Length : std::uint8_t { real32, real64 };
  enum class Rounding : std::uint8_t { nearest, zero, plus, minus };

  // bits: a REAL64 pattern, or for real32 a REAL32 pattern in the low 32 bits. unrounded (real32
  // only): the result of fpunoround, which keeps the REAL64 value (bits is then a REAL64 pattern)
  // so that the next add rounds once; a store writes it truncated (see no_round).
  struct Register {
    std::uint64_t bits = 0;
    Length length = Length::real64;
    bool unrounded = false;
    bool operator==(const Register& o) const {
      return bits == o.bits && length == o.length && unrounded == o.unrounded;
    }
  };

  const Register& fa() const { return fa_; }
  const Register& fb() const { return fb_; }
  const Register& fc() const { return fc_; }
  bool error() const { return error_; }
  Rounding rounding() const { return rounding_; }

  // Loads push: FC := FB, FB := FA, FA := the value.
  void load_single(std::uint32_t bits);        // fpldnlsn, fpldnlsni
  void load_double(std::uint64_t bits);        // fpldnldb, fpldnldbi
  void load_zero_single();                     // fpldzerosn
  void load_zero_double();                     // fpldzerodb
  void load_int32_as_real32(std::int32_t v);   // fpi32tor32 (rounded)
  void load_int32_as_real64(std::int32_t v);   // fpi32tor64
  void load_bit32_as_real64(std::uint32_t v);  // fpb32tor64 (unsigned)
  void load_add_single(std::uint32_t bits);    // fpldnladdsn: FA := FA + value
  void load_add_double(std::uint64_t bits);    // fpldnladddb
  void load_mul_single(std::uint32_t bits);    // fpldnlmulsn: FA := FA * value
  void load_mul_double(std::uint64_t bits);    // fpldnlmuldb

  // Stores pop FA (FA := FB, FB := FC) and return what goes to memory.
  std::uint32_t store_single();  // fpstnlsn
  std::uint64_t store_double();  // fpstnldb
  std::uint32_t store_int32();   // fpstnli32: floor(FA) mod 2^32; 0 for Inf and NaN

  void add();  // fpadd: FA := FB + FA
  void sub();  // fpsub: FA := FB - FA
  void mul();  // fpmul
  void div();  // fpdiv: FA := FB / FA
  // fpremfirst: FA := FB REM FA (IEEE remainder), FB := the quotient. Returns the Areg value
  // (TRUE: done, so the compiler's "eqc 0; cj" skips the fpremstep loop); rem_step likewise.
  std::uint32_t rem_first();
  std::uint32_t rem_step();
  void sqrt_first();  // fpusqrtfirst; then sqrt_step (2 for REAL32, 5 for REAL64), sqrt_last:
  void sqrt_step();   // FA := the correctly rounded square root, rounded at sqrt_last
  void sqrt_last();
  void abs();        // fpuabs
  void mul_by_2();   // fpumulby2
  void div_by_2();   // fpudivby2
  void exp_inc32();  // fpuexpinc32: FA * 2^32
  void exp_dec32();  // fpuexpdec32: FA / 2^32

  void to_integral();       // fpint: round to an integral value, same length
  void real_to_int32();     // fprtoi32: fpint, FP error if the result is outside INT32
  void check_int32();       // fpuchki32: FP error unless -2^31 <= FA < 2^31
  void check_int64();       // fpuchki64: FP error unless -2^63 <= FA < 2^63
  void real32_to_real64();  // fpur32tor64
  void real64_to_real32();  // fpur64tor32 (rounded)
  void no_round();          // fpunoround: REAL64 -> REAL32 without rounding

  void rev();  // fprev: swap FA and FB
  void dup();  // fpdup: push FA

  void set_error();               // fpuseterr
  void clear_error();             // fpuclrerr
  std::uint32_t test_error();     // fptesterr: TRUE if no FP error, then clears it
  bool check_error();             // fpchkerr: whether the integer Error flag must be set
  void set_rounding(Rounding m);  // fpurn, fpurz, fpurp, fpurm

  // Integer results (TRUE 1, FALSE 0) for Areg. fpgt and fpeq pop FA and FB (FA := FC); fpordered,
  // fpnan and fpnotfinite leave the FP stack alone.
  std::uint32_t gt();          // fpgt: FB > FA
  std::uint32_t eq();          // fpeq: FB = FA
  std::uint32_t ordered();     // fpordered: neither FA nor FB is a NaN
  std::uint32_t is_nan();      // fpnan
  std::uint32_t not_finite();  // fpnotfinite

 private:
  void push(const Register& r);
  // A binary operation's end: its two operands FB and FA are replaced by the result.
  void replace_fa_fb(const Register& result) {
    fa_ = result;
    fb_ = fc_;
  }
  void done() { rounding_ = Rounding::nearest; }

  Register fa_, fb_, fc_;
  Rounding rounding_ = Rounding::nearest;
  bool error_ = false;
};

}  // namespace t800::iss
