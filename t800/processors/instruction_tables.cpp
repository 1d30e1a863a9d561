// The instruction timing tables of the T800, T805 and T414 families. Cycle figures are the typical
// ones of the INMOS datasheet instruction tables (transcribed in pahihu/t4, Notebook.txt) for code
// and data in on-chip RAM; docs/t800-timing.md, section "Instructions", gives every source and
// status. Memory words (the last columns) are what each instruction reads or writes in memory,
// which is what external memory slows down (section "Memory").
#include <initializer_list>

#include "t800/processors/instruction_timing.hpp"

namespace t800 {

using isa::Op;

namespace {

struct Row {
  Op op;
  Unit unit;
  int cycles;
  int cycles_double = 0;
  int per_param = 0;
  int when_set = 0;
  int iu_part = 0;
  int words = 0;
  int words_per_param = 0;
};

constexpr Unit I = Unit::integer;
constexpr Unit L = Unit::fp_load;
constexpr Unit S = Unit::fp_store;
constexpr Unit A = Unit::fp_arithmetic;
constexpr Unit LA = Unit::fp_load_arithmetic;
constexpr Unit R = Unit::fp_result;

// Issuing an FPU operation occupies the IU for one cycle (U): the FPU decodes and executes it on
// its own (T805 datasheet, M. Homewood 1990). A combined load-and-operate instruction keeps the IU
// for its load, the figure of the plain load (fpldnlsn 2, fpldnldb 3): fpldnladdsn 8 = 2 + fpadd 6,
// fpldnlmulsn 13 = 2 + fpmul 11, fpldnlmuldb 21 = 3 + 18 (D).
constexpr int kIssue = 1;

// Integer and control instructions, common to the three families (T800 datasheet tables).
const std::initializer_list<Row> kInteger = {
    // op, unit, cycles, double, per param, when set, iu part, words, words per param
    {Op::j, I, 3},
    {Op::ldlp, I, 1},
    {Op::pfix, I, 1},
    {Op::ldnl, I, 2, 0, 0, 0, 0, 1},
    {Op::ldc, I, 1},
    {Op::ldnlp, I, 1},
    {Op::nfix, I, 1},
    {Op::ldl, I, 2, 0, 0, 0, 0, 1},
    {Op::adc, I, 1},
    {Op::call, I, 7, 0, 0, 0, 0, 4},  // stores Iptr, A, B, C below the new workspace
    {Op::cj, I, 2, 0, 0, 4},          // 2 not taken, 4 taken
    {Op::ajw, I, 1},
    {Op::eqc, I, 2},
    {Op::stl, I, 1, 0, 0, 0, 0, 1},
    {Op::stnl, I, 2, 0, 0, 0, 0, 1},
    {Op::rev, I, 1},
    {Op::lb, I, 5, 0, 0, 0, 0, 1},
    {Op::bsub, I, 1},
    {Op::endp, I, 13, 0, 0, 0, 0, 2},
    {Op::diff, I, 1},
    {Op::add, I, 1},
    {Op::gcall, I, 4},
    {Op::in, I, 19, 0, 2, 0, 0, 2, 2},  // 2w + 19; w words copied on an internal channel
    {Op::prod, I, 4, 0, 1},             // b + 4, b = highest set bit of A
    {Op::gt, I, 2},
    {Op::wsub, I, 2},
    {Op::out, I, 19, 0, 2, 0, 0, 2, 2},
    {Op::sub, I, 1},
    {Op::startp, I, 12, 0, 0, 0, 0, 2},
    {Op::outbyte, I, 23, 0, 0, 0, 0, 3},
    {Op::outword, I, 23, 0, 0, 0, 0, 3},
    {Op::seterr, I, 1},
    {Op::resetch, I, 3, 0, 0, 0, 0, 1},
    {Op::csub0, I, 2},
    {Op::stopp, I, 11, 0, 0, 0, 0, 2},
    {Op::ladd, I, 2},
    {Op::norm, I, 5, 0, 1},  // n + 5 (n < 32), n places shifted
    {Op::ldiv, I, 35},
    {Op::ldpi, I, 2},
    {Op::lend, I, 5, 0, 0, 10, 0, 4},  // 10 looping, 5 on exit; updates the two-word control block
    {Op::ldtimer, I, 2},
    {Op::testerr, I, 2, 0, 0, 3},
    {Op::tin, I, 4, 0, 0, 30, 0, 4},  // 4 time past, 30 time in the future (a timer queue insert)
    {Op::div, I, 39},
    {Op::dist, I, 23, 0, 0, 0, 0, 2},
    {Op::disc, I, 8, 0, 0, 0, 0, 2},
    {Op::diss, I, 4, 0, 0, 0, 0, 1},
    {Op::lmul, I, 33},
    {Op::not_, I, 1},
    {Op::xor_, I, 1},
    {Op::bcnt, I, 2},
    {Op::lshr, I, 3, 0, 1},
    {Op::lshl, I, 3, 0, 1},
    {Op::lsum, I, 2},
    {Op::lsub, I, 2},
    {Op::runp, I, 10, 0, 0, 0, 0, 2},
    {Op::xword, I, 4},
    {Op::sb, I, 4, 0, 0, 0, 0, 1},
    {Op::gajw, I, 2},
    {Op::wcnt, I, 5},
    {Op::shr, I, 2, 0, 1},
    {Op::shl, I, 2, 0, 1},
    {Op::mint, I, 1},
    {Op::alt, I, 2, 0, 0, 0, 0, 1},
    {Op::altwt, I, 5, 0, 0, 17, 0, 2},  // 5 a channel ready, 17 waiting
    {Op::altend, I, 4, 0, 0, 0, 0, 1},
    {Op::and_, I, 1},
    {Op::enbt, I, 8, 0, 0, 0, 0, 2},
    {Op::enbc, I, 5, 0, 0, 7, 0, 2},  // 7 ready, 5 not ready
    {Op::enbs, I, 3, 0, 0, 0, 0, 1},
    {Op::move, I, 8, 0, 2, 0, 0, 0, 2},  // 2w + 8
    {Op::or_, I, 1},
    {Op::csngl, I, 3},
    {Op::ccnt1, I, 3},
    {Op::talt, I, 4, 0, 0, 0, 0, 2},
    {Op::ldiff, I, 2},
    {Op::sum, I, 1},
    {Op::mul, I, 40},
    {Op::stoperr, I, 2},
    {Op::cword, I, 5},
    {Op::ret, I, 5, 0, 0, 0, 0, 1},
    {Op::rem, I, 37},
    {Op::taltwt, I, 15, 0, 0, 48, 0, 4},  // 15 time past, 48 in the future
    {Op::fmul, I, 35},                    // fractional multiply, rounding (38 without)
    // Processor initialisation and error handling (NB, "Processor initialisation operation codes").
    {Op::stlb, I, 1},
    {Op::sthf, I, 1},
    {Op::stlf, I, 1},
    {Op::sthb, I, 1},
    {Op::xdble, I, 2},
    {Op::ldpri, I, 1},
    {Op::testpranal, I, 2},
    {Op::savel, I, 4, 0, 0, 0, 0, 2},  // stores the two queue pointers
    {Op::saveh, I, 4, 0, 0, 0, 0, 2},
    {Op::sttimer, I, 1},
    {Op::clrhalterr, I, 1},
    {Op::sethalterr, I, 1},
    {Op::testhalterr, I, 2},
};

// Instructions the T800 and T805 have and the T414 has not (besides the FPU's).
const std::initializer_list<Row> kT800Integer = {
    {Op::dup, I, 1},
    {Op::wsubdb, I, 3},
    // 2D block moves: (2p + 23) cycles per row, p the row's words; the timing rule multiplies the
    // figure by the rows (TimedStep::rows). Each word is read and written.
    {Op::move2dinit, I, 8},
    {Op::move2dall, I, 23, 0, 2, 0, 0, 0, 2},
    {Op::move2dnonzero, I, 23, 0, 2, 0, 0, 0, 2},
    {Op::move2dzero, I, 23, 0, 2, 0, 0, 0, 2},
    {Op::crcword, I, 35},
    {Op::crcbyte, I, 11},
    {Op::bitcnt, I, 2, 0, 1},  // b + 2, b the bit number of A's highest set bit
    {Op::bitrevword, I, 36},
    {Op::bitrevnbits, I, 4, 0, 1},  // n + 4, n bits reversed
};

// The T805's additions (T805DS): the datasheet gives no cycles for them in the tables this
// project has; one cycle each is the model's assumption (U, docs/t800-timing.md), except break,
// timed as the j it replaces when its break flag is clear.
const std::initializer_list<Row> kT805Additions = {
    {Op::pop, I, 1},          {Op::timerdisableh, I, 1}, {Op::timerdisablel, I, 1},
    {Op::timerenableh, I, 1}, {Op::timerenablel, I, 1},  {Op::ldmemstartval, I, 1},
    {Op::break_, I, 3},       {Op::clrj0break, I, 1},    {Op::setj0break, I, 1},
    {Op::testj0break, I, 2},  {Op::lddevid, I, 1},
};

// The T414's floating-point support instructions (T414 datasheet; Notebook.txt).
const std::initializer_list<Row> kT414Support = {
    {Op::unpacksn, I, 15}, {Op::postnormsn, I, 5}, {Op::roundsn, I, 12},
    {Op::ldinf, I, 1},     {Op::cflerr, I, 3},
};

// The T800 FPU (typical cycles; REAL32 / REAL64 where they differ).
const std::initializer_list<Row> kFpu = {
    {Op::fpldnlsn, L, 2, 0, 0, 0, 0, 1},
    {Op::fpldnldb, L, 3, 0, 0, 0, 0, 2},
    {Op::fpldnlsni, L, 4, 0, 0, 0, 0, 1},
    {Op::fpldnldbi, L, 6, 0, 0, 0, 0, 2},
    {Op::fpldzerosn, L, 2},
    {Op::fpldzerodb, L, 2},
    {Op::fpldnladdsn, LA, 8, 0, 0, 0, 2, 1},
    {Op::fpldnladddb, LA, 9, 0, 0, 0, 3, 2},
    {Op::fpldnlmulsn, LA, 13, 0, 0, 0, 2, 1},
    {Op::fpldnlmuldb, LA, 21, 0, 0, 0, 3, 2},
    {Op::fpstnlsn, S, 2, 0, 0, 0, 0, 1},
    {Op::fpstnldb, S, 3, 0, 0, 0, 0, 2},
    {Op::fpstnli32, S, 4, 0, 0, 0, 0, 1},
    {Op::fpentry, A, 1, 0, 0, 0, kIssue},
    {Op::fprev, A, 1, 0, 0, 0, kIssue},
    {Op::fpdup, A, 1, 0, 0, 0, kIssue},
    {Op::fpchkerror, R, 1},
    {Op::fptesterror, R, 2},
    {Op::fpgt, R, 4},
    {Op::fpeq, R, 3},
    {Op::fpordered, R, 3},
    {Op::fpnan, R, 2},
    {Op::fpnotfinite, R, 2},
    {Op::fprtoi32, A, 7, 0, 0, 0, kIssue},
    {Op::fpi32tor32, L, 8, 0, 0, 0, 0, 1},
    {Op::fpi32tor64, L, 8, 0, 0, 0, 0, 1},
    {Op::fpb32tor64, L, 8, 0, 0, 0, 0, 1},
    {Op::fpint, A, 5, 0, 0, 0, kIssue},
    {Op::fpadd, A, 6, 6, 0, 0, kIssue},
    {Op::fpsub, A, 6, 6, 0, 0, kIssue},
    // REAL32 multiply: the table prints "11/8"; 11 typical follows from fpldnlmulsn 13 = 2 + 11
    // (D).
    {Op::fpmul, A, 11, 18, 0, 0, kIssue},
    {Op::fpdiv, A, 16, 31, 0, 0, kIssue},
    {Op::fpremfirst, A, 36, 0, 0, 0, kIssue},
    {Op::fpremstep, A, 32, 0, 0, 0, kIssue},
    {Op::fpurn, A, 1, 0, 0, 0, kIssue},
    {Op::fpurz, A, 1, 0, 0, 0, kIssue},
    {Op::fpurp, A, 1, 0, 0, 0, kIssue},
    {Op::fpurm, A, 1, 0, 0, 0, kIssue},
    {Op::fpuseterror, A, 1, 0, 0, 0, kIssue},
    {Op::fpuclearerror, A, 1, 0, 0, 0, kIssue},
    {Op::fpuchki32, R, 3},
    {Op::fpuchki64, R, 3},
    {Op::fpur32tor64, A, 3, 0, 0, 0, kIssue},
    {Op::fpur64tor32, A, 6, 0, 0, 0, kIssue},
    {Op::fpunoround, A, 2, 0, 0, 0, kIssue},
    {Op::fpuabs, A, 2, 0, 0, 0, kIssue},
    {Op::fpusqrtfirst, A, 27, 0, 0, 0, kIssue},
    {Op::fpusqrtstep, A, 42, 0, 0, 0, kIssue},
    {Op::fpusqrtlast, A, 8, 0, 0, 0, kIssue},
    {Op::fpuexpinc32, A, 6, 0, 0, 0, kIssue},
    {Op::fpuexpdec32, A, 6, 0, 0, 0, kIssue},
    {Op::fpumulby2, A, 6, 0, 0, 0, kIssue},
    {Op::fpudivby2, A, 6, 0, 0, 0, kIssue},
};

void fill(InstructionTimingTable& table, std::initializer_list<Row> rows) {
  for (const Row& r : rows) {
    InstructionTiming& t = table.rows[static_cast<std::size_t>(r.op)];
    t = {true,       r.unit,    r.cycles, r.cycles_double,  r.per_param,
         r.when_set, r.iu_part, r.words,  r.words_per_param};
  }
}

InstructionTimingTable make(const char* family,
                            std::initializer_list<std::initializer_list<Row>> parts) {
  InstructionTimingTable table;
  table.family = family;
  for (const auto& part : parts) fill(table, part);
  return table;
}

}  // namespace

const InstructionTimingTable& t800_timing() {
  static const InstructionTimingTable table = make("T800", {kInteger, kT800Integer, kFpu});
  return table;
}

// The T805 differs from the T800 in its integer multiply: 38 cycles on the T805 datasheet against
// 40 in the T800's table.
const InstructionTimingTable& t805_timing() {
  static const InstructionTimingTable table = [] {
    InstructionTimingTable t = make("T805", {kInteger, kT800Integer, kFpu, kT805Additions});
    fill(t, {{Op::mul, I, 38}});
    return t;
  }();
  return table;
}

const InstructionTimingTable& t414_timing() {
  static const InstructionTimingTable table = make("T414", {kInteger, kT414Support});
  return table;
}

}  // namespace t800
