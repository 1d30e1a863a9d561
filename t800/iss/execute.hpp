// The direct functions' execution and the commonest operations' (most code is made of them),
// inline, so that both ways of running code (Core::step, one instruction at a time, and
// Core::run_block) compile it into their loops. Included only by those two.
#pragma once

#include "t800/iss/core.hpp"
#include "t800/iss/integer_arithmetic.hpp"

namespace t800::iss {

[[gnu::always_inline]] inline void Core::execute(const Decoded& d, TimedStep& t) {
  const Word n = Word(d.operand);
  switch (d.op) {
    case isa::Op::j:
      r_.iptr += n;
      control_moved();
      if (n == 0 && j0_break_) {
        halt("break: j 0 with the T805's j0 break enabled", r_.iptr);
        return;
      }
      timeslice_point();
      return;
    case isa::Op::ldlp:
      push(r_.wptr + 4 * n);
      return;
    case isa::Op::ldnl:
      r_.a = memory_.word(r_.a + 4 * n, t.data_external);
      return;
    case isa::Op::ldc:
      push(n);
      return;
    case isa::Op::ldnlp:
      r_.a += 4 * n;
      return;
    case isa::Op::ldl:
      push(memory_.word(r_.wptr + 4 * n, t.data_external));
      return;
    case isa::Op::adc: {
      const auto sum = checked_add(r_.a, n);
      r_.a = sum.value;
      if (sum.overflow) set_error("adc");
      return;
    }
    case isa::Op::call: {
      const Word back = r_.iptr;
      r_.wptr -= 16;
      data_at(t, r_.wptr);
      memory_.set_word(r_.wptr, back);
      memory_.set_word(r_.wptr + 4, r_.a);
      memory_.set_word(r_.wptr + 8, r_.b);
      memory_.set_word(r_.wptr + 12, r_.c);
      r_.a = back;
      r_.iptr += n;
      control_moved();
      return;
    }
    case isa::Op::cj:
      if (r_.a == 0) {
        r_.iptr += n;
        t.param = 1;  // taken
        control_moved();
      } else {
        pop();
      }
      return;
    case isa::Op::ajw:
      r_.wptr += 4 * n;
      return;
    case isa::Op::eqc:
      r_.a = r_.a == n ? kTrue : kFalse;
      return;
    case isa::Op::stl:
      memory_.set_word(r_.wptr + 4 * n, r_.a, t.data_external);
      pop();  // after the store: a faulting one leaves the stack as it was
      return;
    case isa::Op::stnl:
      memory_.set_word(r_.a + 4 * n, r_.b, t.data_external);
      r_.a = r_.c;
      return;
    // The operations most code uses, here so that they compile into the loops too.
    case isa::Op::rev:
      std::swap(r_.a, r_.b);
      return;
    case isa::Op::lb:
      data_at(t, r_.a);
      r_.a = memory_.byte(r_.a);
      return;
    case isa::Op::sb:
      data_at(t, r_.a);
      memory_.set_byte(r_.a, std::uint8_t(r_.b));
      r_.a = r_.c;
      return;
    case isa::Op::bsub:
      r_.a = r_.a + r_.b;
      r_.b = r_.c;
      return;
    case isa::Op::wsub:
      r_.a = r_.a + 4 * r_.b;
      r_.b = r_.c;
      return;
    case isa::Op::diff:
      r_.a = r_.b - r_.a;
      r_.b = r_.c;
      return;
    case isa::Op::sum:
      r_.a = r_.b + r_.a;
      r_.b = r_.c;
      return;
    case isa::Op::gt:
      r_.a = std::int32_t(r_.b) > std::int32_t(r_.a) ? kTrue : kFalse;
      r_.b = r_.c;
      return;
    case isa::Op::and_:
      r_.a &= r_.b;
      r_.b = r_.c;
      return;
    case isa::Op::or_:
      r_.a |= r_.b;
      r_.b = r_.c;
      return;
    case isa::Op::xor_:
      r_.a ^= r_.b;
      r_.b = r_.c;
      return;
    case isa::Op::not_:
      r_.a = ~r_.a;
      return;
    case isa::Op::add:
      arithmetic_result(checked_add(r_.b, r_.a), d.op);
      return;
    case isa::Op::prod:
      t.param = highest_bit(r_.a);
      r_.a = r_.b * r_.a;
      r_.b = r_.c;
      return;
    case isa::Op::ret:
      r_.iptr = memory_.word(r_.wptr, t.data_external);
      r_.wptr += 16;
      control_moved();
      return;
    case isa::Op::mint:
      push(kMostNeg);
      return;
    case isa::Op::dup:
      push(r_.a);
      return;
    default:
      if (d.op == isa::Op::pfix || d.op == isa::Op::nfix) return;  // never get here (decoder.hpp)
      operate(d, t);
  }
}

}  // namespace t800::iss
