#include "t800/isa/opcode.hpp"

#include <array>
#include <stdexcept>

namespace t800::isa {

namespace {

constexpr Encoding D = Encoding::direct;
constexpr Encoding O = Encoding::operate;
constexpr Encoding F = Encoding::fpu_entry;

// Codes from the INMOS instruction tables (T800 datasheet; pahihu/t4 Notebook.txt; the T805's
// additions from the T805 datasheet, as the occam compiler's instruction codes list them), in Op
// order.
constexpr std::array<OpInfo, kOpCount> kTable{{
    {Op::j, "j", D, 0x0},
    {Op::ldlp, "ldlp", D, 0x1},
    {Op::pfix, "pfix", D, 0x2},
    {Op::ldnl, "ldnl", D, 0x3},
    {Op::ldc, "ldc", D, 0x4},
    {Op::ldnlp, "ldnlp", D, 0x5},
    {Op::nfix, "nfix", D, 0x6},
    {Op::ldl, "ldl", D, 0x7},
    {Op::adc, "adc", D, 0x8},
    {Op::call, "call", D, 0x9},
    {Op::cj, "cj", D, 0xA},
    {Op::ajw, "ajw", D, 0xB},
    {Op::eqc, "eqc", D, 0xC},
    {Op::stl, "stl", D, 0xD},
    {Op::stnl, "stnl", D, 0xE},
    {Op::rev, "rev", O, 0x00},
    {Op::lb, "lb", O, 0x01},
    {Op::bsub, "bsub", O, 0x02},
    {Op::endp, "endp", O, 0x03},
    {Op::diff, "diff", O, 0x04},
    {Op::add, "add", O, 0x05},
    {Op::gcall, "gcall", O, 0x06},
    {Op::in, "in", O, 0x07},
    {Op::prod, "prod", O, 0x08},
    {Op::gt, "gt", O, 0x09},
    {Op::wsub, "wsub", O, 0x0A},
    {Op::out, "out", O, 0x0B},
    {Op::sub, "sub", O, 0x0C},
    {Op::startp, "startp", O, 0x0D},
    {Op::outbyte, "outbyte", O, 0x0E},
    {Op::outword, "outword", O, 0x0F},
    {Op::seterr, "seterr", O, 0x10},
    {Op::resetch, "resetch", O, 0x12},
    {Op::csub0, "csub0", O, 0x13},
    {Op::stopp, "stopp", O, 0x15},
    {Op::ladd, "ladd", O, 0x16},
    {Op::norm, "norm", O, 0x19},
    {Op::ldiv, "ldiv", O, 0x1A},
    {Op::ldpi, "ldpi", O, 0x1B},
    {Op::lend, "lend", O, 0x21},
    {Op::ldtimer, "ldtimer", O, 0x22},
    {Op::testerr, "testerr", O, 0x29},
    {Op::tin, "tin", O, 0x2B},
    {Op::div, "div", O, 0x2C},
    {Op::dist, "dist", O, 0x2E},
    {Op::disc, "disc", O, 0x2F},
    {Op::diss, "diss", O, 0x30},
    {Op::lmul, "lmul", O, 0x31},
    {Op::not_, "not", O, 0x32},
    {Op::xor_, "xor", O, 0x33},
    {Op::bcnt, "bcnt", O, 0x34},
    {Op::lshr, "lshr", O, 0x35},
    {Op::lshl, "lshl", O, 0x36},
    {Op::lsum, "lsum", O, 0x37},
    {Op::lsub, "lsub", O, 0x38},
    {Op::runp, "runp", O, 0x39},
    {Op::xword, "xword", O, 0x3A},
    {Op::sb, "sb", O, 0x3B},
    {Op::gajw, "gajw", O, 0x3C},
    {Op::wcnt, "wcnt", O, 0x3F},
    {Op::shr, "shr", O, 0x40},
    {Op::shl, "shl", O, 0x41},
    {Op::mint, "mint", O, 0x42},
    {Op::alt, "alt", O, 0x43},
    {Op::altwt, "altwt", O, 0x44},
    {Op::altend, "altend", O, 0x45},
    {Op::and_, "and", O, 0x46},
    {Op::enbt, "enbt", O, 0x47},
    {Op::enbc, "enbc", O, 0x48},
    {Op::enbs, "enbs", O, 0x49},
    {Op::move, "move", O, 0x4A},
    {Op::or_, "or", O, 0x4B},
    {Op::csngl, "csngl", O, 0x4C},
    {Op::ccnt1, "ccnt1", O, 0x4D},
    {Op::talt, "talt", O, 0x4E},
    {Op::ldiff, "ldiff", O, 0x4F},
    {Op::sum, "sum", O, 0x52},
    {Op::mul, "mul", O, 0x53},
    {Op::stoperr, "stoperr", O, 0x55},
    {Op::cword, "cword", O, 0x56},
    {Op::dup, "dup", O, 0x5A},
    {Op::wsubdb, "wsubdb", O, 0x81},
    {Op::ret, "ret", O, 0x20},
    {Op::rem, "rem", O, 0x1F},
    {Op::taltwt, "taltwt", O, 0x51},
    {Op::fmul, "fmul", O, 0x72},
    {Op::stlb, "stlb", O, 0x17},
    {Op::sthf, "sthf", O, 0x18},
    {Op::stlf, "stlf", O, 0x1C},
    {Op::sthb, "sthb", O, 0x50},
    {Op::xdble, "xdble", O, 0x1D},
    {Op::ldpri, "ldpri", O, 0x1E},
    {Op::testpranal, "testpranal", O, 0x2A},
    {Op::savel, "savel", O, 0x3D},
    {Op::saveh, "saveh", O, 0x3E},
    {Op::sttimer, "sttimer", O, 0x54},
    {Op::clrhalterr, "clrhalterr", O, 0x57},
    {Op::sethalterr, "sethalterr", O, 0x58},
    {Op::testhalterr, "testhalterr", O, 0x59},
    {Op::move2dinit, "move2dinit", O, 0x5B},
    {Op::move2dall, "move2dall", O, 0x5C},
    {Op::move2dnonzero, "move2dnonzero", O, 0x5D},
    {Op::move2dzero, "move2dzero", O, 0x5E},
    {Op::crcword, "crcword", O, 0x74},
    {Op::crcbyte, "crcbyte", O, 0x75},
    {Op::bitcnt, "bitcnt", O, 0x76},
    {Op::bitrevword, "bitrevword", O, 0x77},
    {Op::bitrevnbits, "bitrevnbits", O, 0x78},
    {Op::pop, "pop", O, 0x79},
    {Op::timerdisableh, "timerdisableh", O, 0x7A},
    {Op::timerdisablel, "timerdisablel", O, 0x7B},
    {Op::timerenableh, "timerenableh", O, 0x7C},
    {Op::timerenablel, "timerenablel", O, 0x7D},
    {Op::ldmemstartval, "ldmemstartval", O, 0x7E},
    {Op::break_, "break", O, 0xB1},
    {Op::clrj0break, "clrj0break", O, 0xB2},
    {Op::setj0break, "setj0break", O, 0xB3},
    {Op::testj0break, "testj0break", O, 0xB4},
    {Op::lddevid, "lddevid", O, 0x17C},
    {Op::unpacksn, "unpacksn", O, 0x63},
    {Op::postnormsn, "postnormsn", O, 0x6C},
    {Op::roundsn, "roundsn", O, 0x6D},
    {Op::ldinf, "ldinf", O, 0x71},
    {Op::cflerr, "cflerr", O, 0x73},
    {Op::fpldnlsn, "fpldnlsn", O, 0x8E},
    {Op::fpldnldb, "fpldnldb", O, 0x8A},
    {Op::fpldnlsni, "fpldnlsni", O, 0x86},
    {Op::fpldnldbi, "fpldnldbi", O, 0x82},
    {Op::fpldzerosn, "fpldzerosn", O, 0x9F},
    {Op::fpldzerodb, "fpldzerodb", O, 0xA0},
    {Op::fpldnladdsn, "fpldnladdsn", O, 0xAA},
    {Op::fpldnladddb, "fpldnladddb", O, 0xA6},
    {Op::fpldnlmulsn, "fpldnlmulsn", O, 0xAC},
    {Op::fpldnlmuldb, "fpldnlmuldb", O, 0xA8},
    {Op::fpstnlsn, "fpstnlsn", O, 0x88},
    {Op::fpstnldb, "fpstnldb", O, 0x84},
    {Op::fpstnli32, "fpstnli32", O, 0x9E},
    {Op::fpentry, "fpentry", O, 0xAB},
    {Op::fprev, "fprev", O, 0xA4},
    {Op::fpdup, "fpdup", O, 0xA3},
    {Op::fpchkerror, "fpchkerror", O, 0x83},
    {Op::fptesterror, "fptesterror", O, 0x9C},
    {Op::fpgt, "fpgt", O, 0x94},
    {Op::fpeq, "fpeq", O, 0x95},
    {Op::fpordered, "fpordered", O, 0x92},
    {Op::fpnan, "fpnan", O, 0x91},
    {Op::fpnotfinite, "fpnotfinite", O, 0x93},
    {Op::fprtoi32, "fprtoi32", O, 0x9D},
    {Op::fpi32tor32, "fpi32tor32", O, 0x96},
    {Op::fpi32tor64, "fpi32tor64", O, 0x98},
    {Op::fpb32tor64, "fpb32tor64", O, 0x9A},
    {Op::fpint, "fpint", O, 0xA1},
    {Op::fpadd, "fpadd", O, 0x87},
    {Op::fpsub, "fpsub", O, 0x89},
    {Op::fpmul, "fpmul", O, 0x8B},
    {Op::fpdiv, "fpdiv", O, 0x8C},
    {Op::fpremfirst, "fpremfirst", O, 0x8F},
    {Op::fpremstep, "fpremstep", O, 0x90},
    {Op::fpurn, "fpurn", F, 0x22},
    {Op::fpurz, "fpurz", F, 0x06},
    {Op::fpurp, "fpurp", F, 0x04},
    {Op::fpurm, "fpurm", F, 0x05},
    {Op::fpuseterror, "fpuseterror", F, 0x23},
    {Op::fpuclearerror, "fpuclearerror", F, 0x9C},
    {Op::fpuchki32, "fpuchki32", F, 0x0E},
    {Op::fpuchki64, "fpuchki64", F, 0x0F},
    {Op::fpur32tor64, "fpur32tor64", F, 0x07},
    {Op::fpur64tor32, "fpur64tor32", F, 0x08},
    {Op::fpunoround, "fpunoround", F, 0x0D},
    {Op::fpuabs, "fpuabs", F, 0x0B},
    {Op::fpusqrtfirst, "fpusqrtfirst", F, 0x01},
    {Op::fpusqrtstep, "fpusqrtstep", F, 0x02},
    {Op::fpusqrtlast, "fpusqrtlast", F, 0x03},
    {Op::fpuexpinc32, "fpuexpinc32", F, 0x0A},
    {Op::fpuexpdec32, "fpuexpdec32", F, 0x09},
    {Op::fpumulby2, "fpumulby2", F, 0x12},
    {Op::fpudivby2, "fpudivby2", F, 0x11},
}};

constexpr bool table_in_op_order() {
  for (int i = 0; i < kOpCount; ++i)
    if (static_cast<int>(kTable[static_cast<std::size_t>(i)].op) != i) return false;
  return true;
}
static_assert(table_in_op_order(), "kTable must list the operations in the order of enum Op");

}  // namespace

const OpInfo& info(Op op) {
  return kTable[static_cast<std::size_t>(op)];
}

std::string_view mnemonic(Op op) {
  return info(op).mnemonic;
}

std::optional<Op> parse_op(std::string_view text) {
  for (const OpInfo& i : kTable)
    if (i.mnemonic == text) return i.op;
  return std::nullopt;
}

// The operand register is built 4 bits per byte: pfix shifts the bits so far up by 4, nfix
// complements them first. A non-negative operand needs one prefix per further 4 bits; a negative
// one is reached through an nfix chain one byte shorter than the prefixes of its complement needs
// bits for (compiler writer's guide, section on prefixing).
int prefix_bytes(std::int64_t operand) {
  if (operand >= 0 && operand < 16) return 0;
  if (operand >= 16) return 1 + prefix_bytes(operand >> 4);
  return 1 + prefix_bytes((~operand) >> 4);
}

int encoded_bytes(Op op, std::int64_t operand) {
  const OpInfo& i = info(op);
  switch (i.encoding) {
    case Encoding::direct:
      return 1 + prefix_bytes(operand);
    case Encoding::operate:
      return 1 + prefix_bytes(i.code);
    case Encoding::fpu_entry:
      return 1 + prefix_bytes(i.code) + encoded_bytes(Op::fpentry);
  }
  throw std::logic_error("encoded_bytes: unknown encoding");
}

namespace {
constexpr std::uint8_t kPfix = 0x2, kNfix = 0x6;

// The compiler writer's guide's prefixing: an operand below 16 fits the instruction byte; larger
// ones are built by pfix bytes, negative ones start with nfix.
void prefixed(std::uint8_t function, std::int64_t operand, std::vector<std::uint8_t>& out) {
  if (operand >= 0 && operand < 16) {
    out.push_back(std::uint8_t(function << 4 | operand));
  } else if (operand >= 16) {
    prefixed(kPfix, operand >> 4, out);
    out.push_back(std::uint8_t(function << 4 | (operand & 0xF)));
  } else {
    prefixed(kNfix, (~operand) >> 4, out);
    out.push_back(std::uint8_t(function << 4 | (operand & 0xF)));
  }
}
}  // namespace

std::vector<std::uint8_t> encode(Op op, std::int64_t operand) {
  const OpInfo& i = info(op);
  std::vector<std::uint8_t> out;
  constexpr std::uint8_t kOpr = 0xF, kLdc = 0x4;
  switch (i.encoding) {
    case Encoding::direct:
      prefixed(std::uint8_t(i.code), operand, out);
      break;
    case Encoding::operate:
      prefixed(kOpr, i.code, out);
      break;
    case Encoding::fpu_entry:
      prefixed(kLdc, i.code, out);
      prefixed(kOpr, info(Op::fpentry).code, out);
      break;
  }
  return out;
}

}  // namespace t800::isa
