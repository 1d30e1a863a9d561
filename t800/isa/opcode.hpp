// The transputer instruction set as data: every instruction the code generator emits or the
// timing tables price, with how it is encoded. Sources: the INMOS instruction tables (T800
// datasheet, transcribed in the pahihu/t4 repository's Notebook.txt) and "Transputer instruction
// set: a compiler writer's guide" (INMOS, 1988). docs/t800-timing.md, section "Instructions".
//
// Three encodings exist:
//   direct     one byte: a 4-bit function code and a 4-bit operand; larger or negative operands
//              are built up by pfix/nfix bytes in front (ldc, ldl, stl, ldnlp, j, cj, ...);
//   operate    `opr` with the operation's code as its operand, so codes >= 16 take a pfix byte
//              (add = F5, one byte; fpadd = 28 F7, two bytes);
//   fpu entry  the FPU operations the tables mark "s": `ldc code` then `fpentry` (fpuabs =
//              4B 2A FB, three bytes).
#pragma once

#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

namespace t800::isa {

enum class Op : std::uint8_t {
  // Direct functions.
  j,
  ldlp,
  pfix,
  ldnl,
  ldc,
  ldnlp,
  nfix,
  ldl,
  adc,
  call,
  cj,
  ajw,
  eqc,
  stl,
  stnl,
  // Operations (opr).
  rev,
  lb,
  bsub,
  endp,
  diff,
  add,
  gcall,
  in,
  prod,
  gt,
  wsub,
  out,
  sub,
  startp,
  outbyte,
  outword,
  seterr,
  resetch,
  csub0,
  stopp,
  ladd,
  norm,
  ldiv,
  ldpi,
  lend,
  ldtimer,
  testerr,
  tin,
  div,
  dist,
  disc,
  diss,
  lmul,
  not_,
  xor_,
  bcnt,
  lshr,
  lshl,
  lsum,
  lsub,
  runp,
  xword,
  sb,
  gajw,
  wcnt,
  shr,
  shl,
  mint,
  alt,
  altwt,
  altend,
  and_,
  enbt,
  enbc,
  enbs,
  move,
  or_,
  csngl,
  ccnt1,
  talt,
  ldiff,
  sum,
  mul,
  stoperr,
  cword,
  dup,
  wsubdb,
  ret,
  rem,
  taltwt,
  fmul,
  // Processor initialisation, error and priority (T800DS; NB "Processor initialisation operation
  // codes"), and the T800's additions to the integer set: 2D block moves, CRC and bit operations.
  stlb,
  sthf,
  stlf,
  sthb,
  xdble,
  ldpri,
  testpranal,
  savel,
  saveh,
  sttimer,
  clrhalterr,
  sethalterr,
  testhalterr,
  move2dinit,
  move2dall,
  move2dnonzero,
  move2dzero,
  crcword,
  crcbyte,
  bitcnt,
  bitrevword,
  bitrevnbits,
  // The T805's additions (T805DS): debugging support and the timers' enables.
  pop,
  timerdisableh,
  timerdisablel,
  timerenableh,
  timerenablel,
  ldmemstartval,
  break_,
  clrj0break,
  setj0break,
  testj0break,
  lddevid,
  // T414 floating-point support.
  unpacksn,
  postnormsn,
  roundsn,
  ldinf,
  cflerr,
  // T800 FPU: loads, stores, stack and error handling, comparisons, conversions, arithmetic.
  fpldnlsn,
  fpldnldb,
  fpldnlsni,
  fpldnldbi,
  fpldzerosn,
  fpldzerodb,
  fpldnladdsn,
  fpldnladddb,
  fpldnlmulsn,
  fpldnlmuldb,
  fpstnlsn,
  fpstnldb,
  fpstnli32,
  fpentry,
  fprev,
  fpdup,
  fpchkerror,
  fptesterror,
  fpgt,
  fpeq,
  fpordered,
  fpnan,
  fpnotfinite,
  fprtoi32,
  fpi32tor32,
  fpi32tor64,
  fpb32tor64,
  fpint,
  fpadd,
  fpsub,
  fpmul,
  fpdiv,
  fpremfirst,
  fpremstep,
  // FPU operations through fpentry ("s" in the tables).
  fpurn,
  fpurz,
  fpurp,
  fpurm,
  fpuseterror,
  fpuclearerror,
  fpuchki32,
  fpuchki64,
  fpur32tor64,
  fpur64tor32,
  fpunoround,
  fpuabs,
  fpusqrtfirst,
  fpusqrtstep,
  fpusqrtlast,
  fpuexpinc32,
  fpuexpdec32,
  fpumulby2,
  fpudivby2,
};
constexpr int kOpCount = static_cast<int>(Op::fpudivby2) + 1;

enum class Encoding : std::uint8_t { direct, operate, fpu_entry };

struct OpInfo {
  Op op;
  std::string_view mnemonic;
  Encoding encoding;
  int code;  // function code (direct), operation code (operate) or fpentry selector
};

const OpInfo& info(Op op);
std::string_view mnemonic(Op op);
std::optional<Op> parse_op(std::string_view mnemonic);

// pfix/nfix bytes a direct function needs in front of it for `operand` (compiler writer's guide,
// "prefixing"): 0 for 0..15, one more for every further 4 bits; negative operands start with nfix.
int prefix_bytes(std::int64_t operand);

// Bytes of an instruction in memory, prefixes included. For direct functions `operand` is the
// operand; operations and fpu-entry operations take none (their code is fixed).
int encoded_bytes(Op op, std::int64_t operand = 0);
// The bytes themselves (pfix/nfix chain, then the instruction byte; an fpu-entry operation is
// ldc code, fpentry).
std::vector<std::uint8_t> encode(Op op, std::int64_t operand = 0);

}  // namespace t800::isa
