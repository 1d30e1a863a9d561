// The T800's FPU instructions as the integer unit issues them: it forms addresses and moves
// operands between memory and the FPU (fpu.hpp does the arithmetic). Addressing from the CWG: a
// non-local load or store takes its address from A; the indexed loads take A + 4B (single) or
// A + 8B (double); the FPU-entry operations are selected by A at fpentry.
#include <fmt/format.h>

#include "t800/iss/core.hpp"

namespace t800::iss {

using isa::Op;

namespace {
bool real64(const Fpu::Register& r) {
  return r.length == Fpu::Length::real64;
}
}  // namespace

void Core::fpu_operate(Op op, TimedStep& t) {
  if (op == Op::fpentry) {
    // An fpentry not fused with the ldc before it (decoder.hpp): the selector is in A.
    const Word selector = pop();
    const auto entry = fpu_entry_of(selector);
    if (!entry) {
      halt(fmt::format("fpentry with undefined selector #{:X}", selector), r_.iptr - 2);
      return;
    }
    t.op = *entry;
    op = *entry;
  }
  Fpu& f = fpu_;
  auto load64 = [&](Word a) {
    return std::uint64_t(memory_.word(a)) | (std::uint64_t(memory_.word(a + 4)) << 32);
  };
  auto store64 = [&](Word a, std::uint64_t v) {
    memory_.set_word(a, Word(v));
    memory_.set_word(a + 4, Word(v >> 32));
  };
  t.real64 = real64(f.fa());
  switch (op) {
    case Op::fpldnlsn:
      data_at(t, r_.a);
      f.load_single(memory_.word(pop()));
      return;
    case Op::fpldnldb:
      data_at(t, r_.a);
      f.load_double(load64(pop()));
      return;
    case Op::fpldnlsni: {
      const Word address = r_.a + 4 * r_.b;
      data_at(t, address);
      pop();
      pop();
      f.load_single(memory_.word(address));
      return;
    }
    case Op::fpldnldbi: {
      const Word address = r_.a + 8 * r_.b;
      data_at(t, address);
      pop();
      pop();
      f.load_double(load64(address));
      return;
    }
    case Op::fpldzerosn:
      f.load_zero_single();
      return;
    case Op::fpldzerodb:
      f.load_zero_double();
      return;
    case Op::fpldnladdsn:
      data_at(t, r_.a);
      f.load_add_single(memory_.word(pop()));
      return;
    case Op::fpldnladddb:
      data_at(t, r_.a);
      f.load_add_double(load64(pop()));
      return;
    case Op::fpldnlmulsn:
      data_at(t, r_.a);
      f.load_mul_single(memory_.word(pop()));
      return;
    case Op::fpldnlmuldb:
      data_at(t, r_.a);
      f.load_mul_double(load64(pop()));
      return;
    case Op::fpstnlsn:
      data_at(t, r_.a);
      memory_.set_word(pop(), f.store_single());
      return;
    case Op::fpstnldb:
      data_at(t, r_.a);
      store64(pop(), f.store_double());
      return;
    case Op::fpstnli32:
      data_at(t, r_.a);
      memory_.set_word(pop(), f.store_int32());
      return;
    case Op::fpi32tor32:
      data_at(t, r_.a);
      f.load_int32_as_real32(std::int32_t(memory_.word(pop())));
      return;
    case Op::fpi32tor64:
      data_at(t, r_.a);
      f.load_int32_as_real64(std::int32_t(memory_.word(pop())));
      return;
    case Op::fpb32tor64:
      data_at(t, r_.a);
      f.load_bit32_as_real64(memory_.word(pop()));
      return;
    case Op::fprev:
      f.rev();
      return;
    case Op::fpdup:
      f.dup();
      return;
    case Op::fpchkerror:
      if (f.check_error()) set_error("fpchkerror");
      return;
    case Op::fptesterror:
      push(f.test_error());
      return;
    case Op::fpgt:
      push(f.gt());
      return;
    case Op::fpeq:
      push(f.eq());
      return;
    case Op::fpordered:
      push(f.ordered());
      return;
    case Op::fpnan:
      push(f.is_nan());
      return;
    case Op::fpnotfinite:
      push(f.not_finite());
      return;
    case Op::fprtoi32:
      f.real_to_int32();
      return;
    case Op::fpint:
      f.to_integral();
      return;
    case Op::fpadd:
      f.add();
      return;
    case Op::fpsub:
      f.sub();
      return;
    case Op::fpmul:
      f.mul();
      return;
    case Op::fpdiv:
      f.div();
      return;
    case Op::fpremfirst:
      push(f.rem_first());
      return;
    case Op::fpremstep:
      push(f.rem_step());
      return;
    case Op::fpurn:
      f.set_rounding(Fpu::Rounding::nearest);
      return;
    case Op::fpurz:
      f.set_rounding(Fpu::Rounding::zero);
      return;
    case Op::fpurp:
      f.set_rounding(Fpu::Rounding::plus);
      return;
    case Op::fpurm:
      f.set_rounding(Fpu::Rounding::minus);
      return;
    case Op::fpuseterror:
      f.set_error();
      return;
    case Op::fpuclearerror:
      f.clear_error();
      return;
    case Op::fpuchki32:
      f.check_int32();
      return;
    case Op::fpuchki64:
      f.check_int64();
      return;
    case Op::fpur32tor64:
      f.real32_to_real64();
      return;
    case Op::fpur64tor32:
      f.real64_to_real32();
      return;
    case Op::fpunoround:
      f.no_round();
      return;
    case Op::fpuabs:
      f.abs();
      return;
    case Op::fpusqrtfirst:
      f.sqrt_first();
      return;
    case Op::fpusqrtstep:
      f.sqrt_step();
      return;
    case Op::fpusqrtlast:
      f.sqrt_last();
      return;
    case Op::fpuexpinc32:
      f.exp_inc32();
      return;
    case Op::fpuexpdec32:
      f.exp_dec32();
      return;
    case Op::fpumulby2:
      f.mul_by_2();
      return;
    case Op::fpudivby2:
      f.div_by_2();
      return;
    default:
      halt(fmt::format("{} is not modelled by this simulator", isa::mnemonic(op)), r_.iptr - 1);
  }
}

}  // namespace t800::iss
