// The T414's floating-point support instructions: the T414 has no FPU, and its compilers'
// REAL32 routines unpack, normalise and round with these five operations ("Transputer instruction
// set: a compiler writer's guide", INMOS 1988 (CWG), the T414's floating-point support; the ST20C2
// instruction set manual repeats unpacksn's definition). They are T414 operations only: the T800
// and T805 tables lack them, so those processors halt on them as on any operation they do not
// have (Core::step). pahihu/t4 (p.c, the cases of unpacksn, postnormsn, roundsn, ldinf, cflerr,
// with M. Bruestle's corrections from a real T414) was read for the points the CWG leaves open.
//
// A single-length number moves through them as
//   unpacksn    A: packed number           -> A fraction, B exponent, C 4 * B + type
//   (integer arithmetic on the fractions: lmul, ldiv, shifts, ...; then norm: B:A normalised,
//    C the places shifted)
//   postnormsn  A guard, B fraction, C places, workspace word 0 the exponent before `norm`
//               -> A guard, B fraction, C exponent (denormalised when it falls to 0 or below)
//   roundsn     A guard, B fraction, C exponent -> A packed, rounded to nearest (ties to even)
// The sign travels apart (the library ORs it into the result); docs/t800-timing.md for cycles.
#pragma once

#include "t800/isa/opcode.hpp"
#include "t800/iss/machine_words.hpp"

namespace t800::iss {

// True for unpacksn, postnormsn, roundsn, ldinf and cflerr.
bool is_t414_float_support(isa::Op op);

// Executes one of them on the stack (a, b, c); `temp` is workspace word 0 (postnormsn's
// exponent). Returns true if the operation sets Error (cflerr on an infinity or NaN).
bool t414_float_support(isa::Op op, Word& a, Word& b, Word& c, Word temp);

}  // namespace t800::iss
