// The integer unit's operations (opr): arithmetic, logic, indexing, control, error handling,
// processor initialisation, the T800's block moves, CRC and bit operations. Stack effects as the
// CWG gives them; where it leaves a register undefined, the register keeps what a pop leaves.
// Each sets the parameter its timing depends on (TimedStep::param, instruction_timing.hpp). The
// commonest (rev, lb, sb, bsub, wsub, diff, sum, gt, and, or, xor, not, mint, dup) are in
// execute.hpp.
#include <fmt/format.h>

#include "t800/iss/core.hpp"
#include "t800/iss/integer_arithmetic.hpp"
#include "t800/iss/t414_float_support.hpp"

namespace t800::iss {

using isa::Op;

namespace {
Word words_of(Word bytes) {
  return (bytes + 3) / 4;
}
// lshl/lshr n + 3 below 32 places and n - 28 from 32; norm n + 5 below 32, n - 26 from 32, 3 for
// a zero value (NB, "Long arithmetic operation codes"): as a parameter of the table's n + base.
std::int64_t long_shift_param(Word places) {
  return places < 32 ? places : std::int64_t(places) - 31;
}
std::int64_t norm_param(Word places) {
  if (places == 64) return -2;
  return places < 32 ? places : std::int64_t(places) - 31;
}
// A shift's time grows with its places; beyond a word's worth the chip still counts them.
std::int64_t shift_param(Word places) {
  return places > 0xFFFF ? 0xFFFF : places;
}
}  // namespace

void Core::operate(const Decoded& d, TimedStep& t) {
  Registers& r = r_;
  switch (d.op) {
    case Op::wsubdb:
      r.a = r.a + 8 * r.b;
      r.b = r.c;
      return;
    case Op::bcnt:
      r.a *= 4;
      return;
    case Op::wcnt: {
      const Word v = r.a;
      r.c = r.b;
      r.b = v & 3;
      r.a = Word(std::int32_t(v) >> 2);
      return;
    }
    case Op::sub:
    case Op::mul:
    case Op::div:
    case Op::rem: {
      arithmetic_result(d.op == Op::sub   ? checked_sub(r.b, r.a)
                        : d.op == Op::mul ? checked_mul(r.b, r.a)
                        : d.op == Op::div ? divide(r.b, r.a)
                                          : remainder(r.b, r.a),
                        d.op);
      return;
    }
    case Op::fmul: {
      const Checked x = fractional_multiply(r.b, r.a);
      r.a = x.value;
      r.b = r.c;
      if (x.overflow) set_error("fmul");
      return;
    }
    case Op::shl:
    case Op::shr:
      t.param = shift_param(r.a);
      r.a = d.op == Op::shl ? shift_left(r.b, r.a) : shift_right(r.b, r.a);
      r.b = r.c;
      return;
    case Op::pop:
      pop();
      return;
    case Op::xdble:
      r.c = r.b;
      r.b = std::int32_t(r.a) < 0 ? 0xFFFFFFFFu : 0;
      return;
    case Op::xword:
      // A is the sign bit of a part-word value in B (CWG: B < 2A).
      r.a = r.b < r.a ? r.b : r.b - 2 * r.a;
      r.b = r.c;
      return;
    case Op::cword:
      if (std::int32_t(r.b) >= std::int32_t(r.a) || std::int32_t(r.b) < -std::int32_t(r.a))
        set_error("cword");
      r.a = r.b;
      r.b = r.c;
      return;
    case Op::csngl:
      if ((std::int32_t(r.a) < 0 && r.b != 0xFFFFFFFFu) || (std::int32_t(r.a) >= 0 && r.b != 0))
        set_error("csngl");
      r.b = r.c;
      return;
    case Op::csub0:
      if (r.b >= r.a) set_error("csub0");
      r.a = r.b;
      r.b = r.c;
      return;
    case Op::ccnt1:
      if (r.b == 0 || r.b > r.a) set_error("ccnt1");
      r.a = r.b;
      r.b = r.c;
      return;
    case Op::ladd: {
      const Checked x = long_add(r.b, r.a, r.c);
      r.a = x.value;
      if (x.overflow) set_error("ladd");
      return;
    }
    case Op::lsub: {
      const Checked x = long_sub(r.b, r.a, r.c);
      r.a = x.value;
      if (x.overflow) set_error("lsub");
      return;
    }
    case Op::lsum: {
      const DoubleWord x = long_sum(r.b, r.a, r.c);
      r.a = x.low;
      r.b = x.high;
      return;
    }
    case Op::ldiff: {
      const DoubleWord x = long_diff(r.b, r.a, r.c);
      r.a = x.low;
      r.b = x.high;
      return;
    }
    case Op::lmul: {
      const DoubleWord x = long_multiply(r.b, r.a, r.c);
      r.a = x.low;
      r.b = x.high;
      return;
    }
    case Op::ldiv: {
      const LongDivide x = long_divide(r.c, r.b, r.a);
      if (x.overflow) {
        set_error("ldiv");
        r.a = r.b;
        r.b = r.c;
        return;
      }
      r.a = x.quotient;
      r.b = x.remainder;
      return;
    }
    case Op::lshl:
    case Op::lshr: {
      t.param = long_shift_param(r.a);
      const DoubleWord x =
          d.op == Op::lshl ? long_shift_left(r.c, r.b, r.a) : long_shift_right(r.c, r.b, r.a);
      r.a = x.low;
      r.b = x.high;
      return;
    }
    case Op::norm: {
      const Normalised x = normalise(r.b, r.a);
      t.param = norm_param(x.places);
      r.a = x.low;
      r.b = x.high;
      r.c = x.places;
      return;
    }
    case Op::bitcnt:
      t.param = highest_bit(r.a);
      r.a = bit_count(r.a) + r.b;
      r.b = r.c;
      return;
    case Op::bitrevword:
      r.a = bit_reverse(r.a);
      return;
    case Op::bitrevnbits:
      t.param = r.a > 32 ? 32 : r.a;
      r.a = bit_reverse_bits(r.b, r.a);
      r.b = r.c;
      return;
    case Op::crcword:
    case Op::crcbyte: {
      // A data, B CRC so far, C generator (T800 datasheet): A := the new CRC.
      const Word crc = d.op == Op::crcword ? crc_word(r.b, r.a, r.c) : crc_byte(r.b, r.a, r.c);
      r.a = crc;
      r.b = r.c;
      return;
    }
    case Op::move:
      // C source, B destination, A bytes (CWG).
      if (!block_fits(r.a, "move")) return;
      t.param = words_of(r.a);
      data_at(t, r.b);
      memory_.copy(r.b, r.c, r.a);
      return;
    case Op::move2dinit:
      move2d_length_ = r.a;
      move2d_dest_stride_ = r.b;
      move2d_source_stride_ = r.c;
      return;
    case Op::move2dall:
    case Op::move2dnonzero:
    case Op::move2dzero: {
      // C source, B destination, A width in bytes; rows and strides from move2dinit.
      const Word width = r.a, rows = move2d_length_;
      if (std::int32_t(width) < 0 || std::int32_t(rows) < 0) return;
      if (!block_fits(Word(std::min<std::uint64_t>(std::uint64_t(width) * rows, ~0u)),
                      isa::mnemonic(d.op)))
        return;
      t.param = words_of(width);
      t.rows = rows;
      data_at(t, r.b);
      Word from = r.c, to = r.b;
      for (Word row = 0; row < rows; ++row) {
        for (Word k = 0; k < width; ++k) {
          const std::uint8_t v = memory_.byte(from + k);
          if (d.op == Op::move2dall || (d.op == Op::move2dnonzero) == (v != 0))
            memory_.set_byte(to + k, v);
        }
        from += move2d_source_stride_;
        to += move2d_dest_stride_;
      }
      return;
    }
    case Op::gcall:
      std::swap(r.a, r.iptr);
      control_moved();
      return;
    case Op::ldpi:
      r.a += r.iptr;
      return;
    case Op::gajw:
      std::swap(r.a, r.wptr);
      r.wptr &= ~3u;
      return;
    case Op::lend: {
      // A the offset back to the loop's start, B the control block (index, count).
      data_at(t, r.b);
      const Word count = memory_.word(r.b + 4) - 1;
      memory_.set_word(r.b + 4, count);
      if (std::int32_t(count) > 0) {
        memory_.set_word(r.b, memory_.word(r.b) + 1);
        r.iptr -= r.a;
        t.param = 1;  // looping
        control_moved();
        timeslice_point();
      }
      return;
    }
    case Op::seterr:
      set_error("seterr");
      return;
    case Op::testerr:
      push(r.error ? kFalse : kTrue);
      if (r.error) t.param = 1;
      r.error = false;
      return;
    case Op::stoperr:
      if (r.error) deschedule("stopped by stoperr", 0);
      return;
    case Op::clrhalterr:
      r.halt_on_error = false;
      return;
    case Op::sethalterr:
      r.halt_on_error = true;
      if (r.error) blocks_.stop_running_block();
      return;
    case Op::testhalterr:
      push(r.halt_on_error ? kTrue : kFalse);
      return;
    case Op::testpranal:
      push(kFalse);  // never booted to be analysed
      return;
    case Op::ldpri:
      push(Word(r.priority));
      return;
    case Op::stlf:
    case Op::stlb:
    case Op::sthf:
    case Op::sthb: {
      const int p = (d.op == Op::stlf || d.op == Op::stlb) ? kLow : kHigh;
      ((d.op == Op::stlf || d.op == Op::sthf) ? r.fptr : r.bptr)[p] = pop();
      return;
    }
    case Op::savel:
    case Op::saveh: {
      const int p = d.op == Op::savel ? kLow : kHigh;
      data_at(t, r.a);
      memory_.set_word(r.a, r.fptr[p]);
      memory_.set_word(r.a + 4, r.bptr[p]);
      pop();
      return;
    }
    case Op::sttimer:
      clock_base_[kHigh] = clock_base_[kLow] = pop();
      clock_base_ns_ = double(cycle()) * processor_.cycle_ns;
      timers_running_ = true;
      refresh_next_timer();
      return;
    case Op::ldtimer:
      push(clock(r.priority));
      return;
    case Op::tin:
      if (!after(clock(r.priority), r.a)) {
        t.param = 1;            // in the future: the process waits in the timer queue
        insert_timer(r.a + 1);  // due once the clock is AFTER A
        deschedule("timer input (tin)", 0);
      }
      return;
    case Op::timerdisableh:
    case Op::timerdisablel:
    case Op::timerenableh:
    case Op::timerenablel:
      // T805: the timers' enables, which only a debugger's monitor uses; both timers run here.
      return;
    case Op::ldmemstartval:
      push(mem_start());
      return;
    case Op::lddevid:
      // T805: A, B and C hold a device code the datasheet leaves to the chip's revision; the
      // model leaves them as they were (the instruction then behaves as on a T800, where it is
      // an ldc 0 of a sort: see docs/iss.md).
      return;
    case Op::setj0break:
      j0_break_ = true;
      return;
    case Op::clrj0break:
      j0_break_ = false;
      return;
    case Op::testj0break:
      push(j0_break_ ? kTrue : kFalse);
      return;
    case Op::break_:
      halt("break instruction (a debugger's breakpoint)", r.iptr - d.bytes);
      return;
    // Processes and communication (scheduler.cpp, channels.cpp).
    case Op::startp: {
      const Word wptr = pop() & ~3u, offset = pop();
      memory_.set_word(slot_of(wptr, kSlotIptr), r.iptr + offset);
      schedule(wptr | Word(r.priority));
      return;
    }
    case Op::endp: {
      const Word block = r.a;
      data_at(t, block);
      const Word count = memory_.word(block + 4) - 1;
      memory_.set_word(block + 4, count);
      if (count == 0) {
        r.wptr = block & ~3u;
        r.iptr = memory_.word(block);
        control_moved();
      } else {
        deschedule("ended (endp)", 0);
        waiting_.erase(r.wptr);
      }
      return;
    }
    case Op::runp:
      schedule(pop());
      return;
    case Op::stopp:
      deschedule("stopped (stopp)", 0);
      return;
    case Op::in:
    case Op::out: {
      const Word count = r.a, channel = r.b, pointer = r.c;
      t.param = is_link_channel(channel) ? 0 : words_of(count);
      data_at(t, pointer);
      if (d.op == Op::in)
        input(count, channel, pointer);
      else
        output(count, channel, pointer);
      return;
    }
    case Op::outbyte:
    case Op::outword: {
      const Word value = r.a, channel = r.b;
      const Word count = d.op == Op::outbyte ? 1 : 4;
      set_ws(kSlotTemp, d.op == Op::outbyte ? (value & 0xFF) : value);
      data_at(t, r.wptr);
      output(count, channel, r.wptr);
      return;
    }
    case Op::resetch:
      reset_channel(r.a);
      return;
    case Op::alt:
      set_ws(kSlotState, kEnabling);
      return;
    case Op::talt:
      set_ws(kSlotState, kEnabling);
      set_ws(kSlotTLink, kTimeNotSet);
      return;
    case Op::enbs:
      if (r.a) set_ws(kSlotState, kReady);
      return;
    case Op::enbc:
      if (enable_channel(r.a, r.b)) t.param = 1;  // ready
      return;
    case Op::enbt:
      // A guard, B time: the earliest enabled time is kept.
      if (r.a) {
        if (ws(kSlotTLink) == kTimeNotSet) {
          set_ws(kSlotTLink, kTimeSet);
          set_ws(kSlotTime, r.b);
        } else if (after(ws(kSlotTime), r.b)) {
          set_ws(kSlotTime, r.b);
        }
      }
      r.b = r.c;
      return;
    case Op::diss: {
      // A branch offset, B guard.
      const Word offset = pop(), guard = r.a;
      r.a = kFalse;
      if (guard && ws(kSlotTemp) == kNoneSelected) {
        set_ws(kSlotTemp, offset);
        r.a = kTrue;
      }
      return;
    }
    case Op::disc: {
      const Word offset = r.a, guard = r.b, channel = r.c;
      disable_channel(offset, guard, channel);
      return;
    }
    case Op::dist: {
      // A branch offset, B guard, C time: ready if the time is past.
      const Word offset = r.a, guard = r.b, time = r.c;
      remove_timer(r.wptr, r.priority);
      r.a = kFalse;
      if (guard && !after(time, clock(r.priority)) && ws(kSlotTemp) == kNoneSelected) {
        set_ws(kSlotTemp, offset);
        r.a = kTrue;
      }
      r.b = r.c;
      return;
    }
    case Op::altwt:
      if (ws(kSlotState) != kReady) t.param = 1;
      alt_wait();
      return;
    case Op::taltwt:
      timer_alt_wait();
      if (!running_) t.param = 1;
      return;
    case Op::altend:
      r.iptr += ws(kSlotTemp);
      control_moved();
      return;
    default:
      if (isa::info(d.op).encoding == isa::Encoding::fpu_entry || d.op >= Op::fpldnlsn) {
        fpu_operate(d.op, t);
        return;
      }
      if (is_t414_float_support(d.op)) {                               // t414_float_support.cpp
        const Word temp = d.op == Op::postnormsn ? ws(kSlotTemp) : 0;  // its exponent
        if (t414_float_support(d.op, r.a, r.b, r.c, temp)) set_error("cflerr");
        return;
      }
      halt(fmt::format("{} is not modelled by this simulator", isa::mnemonic(d.op)),
           r.iptr - d.bytes);
  }
}

}  // namespace t800::iss
