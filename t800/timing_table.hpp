// Every timing constant of the T800 model, in one table. Each row names its row in
// docs/t800-timing.md and its status there: S = stated by the source, D = derived from stated
// figures (arithmetic in the comment), U = a model assumption.
#pragma once

#include <cstdint>

#include "t800/operation_mix.hpp"

namespace t800::timing {

// ---- Section 2: integer and control instructions (processor cycles, on-chip memory) ----
constexpr int kSimpleOp = 1;     // ldc, adc, add, sub, ldlp, ldnlp, bsub (S)
constexpr int kWordLoad = 2;     // ldl, ldnl (S)
constexpr int kWordStore = 2;    // stnl 2; stl is 1 -- we take the non-local figure, data lives in arrays (S)
constexpr int kIntMul = 38;      // mul: 38 on the T805 sheet, 40 in NB; sources disagree, T805 sheet taken (S)
constexpr int kIntDiv = 39;      // div (S)
constexpr int kBranch = 4;       // cj taken 4, j 3: taken conditional jumps dominate loop control (S)
constexpr int kLoopEnd = 10;     // lend, looping (S)
constexpr int kCallReturn = 12;  // call 7 + ret 5 (S)
constexpr int kPrefix = 1;       // each pfix/nfix byte (S, section 1)

// ---- Section 4: FPU, typical cycles (S); {REAL32, REAL64} ----
struct FpCycles {
  int real32, real64;
  int of(bool real64_precision) const { return real64_precision ? real64 : real32; }
};
constexpr FpCycles kFpAdd{6, 6};
constexpr FpCycles kFpMul{11, 18};  // REAL32: NB prints "11/8"; 11 typical, derived from fpldnlmulsn = 2 + fpmul (D)
constexpr FpCycles kFpDiv{16, 31};
constexpr FpCycles kFpSqrt{119, 245};  // fpusqrtfirst + steps + fpusqrtlast
constexpr FpCycles kFpCompare{4, 4};   // fpgt
constexpr FpCycles kFpLoad{2, 3};      // fpldnlsn / fpldnldb (integer unit moves the data)
constexpr FpCycles kFpStore{2, 3};     // fpstnlsn / fpstnldb
// Issuing an FP arithmetic instruction costs the integer unit ldc + fpentry = 2 cycles (S for each part; the
// sum is D). The FPU executes concurrently (S, T805DS/MH); the overlap rule is in cost_model.cpp (U).
constexpr int kFpIssue = 2;

// ---- Sections 3 and 7: communication and scheduling ----
constexpr int kCommFixed = 19;         // in / out = 2w + 19 (S); on a link only the set-up runs on the CPU (U)
constexpr int kCommPerWord = 2;        // the 2w of 2w + 19 (S): a copy, only for internal channels
constexpr int kStartProcess = 12;      // startp (S)
constexpr int kEndProcess = 13;        // endp (S)
constexpr int kInterruptLatencyTypical = 19;  // high-priority preemption latency (S)
constexpr int kInterruptLatencyMax = 58;      // (S)
constexpr double kTimesliceUs = 1024.0;       // 5120 ticks of the 5 MHz input clock (S)

// ---- Section 5: memory ----
constexpr int kOnChipBytes = 4096;         // (S)
constexpr int kExternalExtraCycles = 2;    // per word at the minimum 3-cycle external cycle (U)

// ---- Section 6: links (in bit-times of the link's own clock unless stated) ----
constexpr int kDataPacketBits = 11;  // 1, 1, 8 data bits, 0 (S)
constexpr int kAckPacketBits = 2;    // 1, 0 (S)
// Two latencies make the byte-level protocol reproduce the datasheet rates (DBK Table 8.1); both are D:
//  * ack turnaround (receiver): from the first bit of a data packet (overlapped, T800) or from its last bit
//    (T414) until the receiver starts its acknowledge;
//  * ack processing (sender): from the end of an acknowledge until the sender may start its next data packet.
// One direction streaming: period = max(11, detect + 2 + process) bits. Both directions: an acknowledge must
// wait behind the data packet its wire is carrying, so the period is 11 + 2 + process bits.
//   20 Mbit/s: both 17 bits -> process = 4 bits = 200 ns; one 11.5 bits -> detect = 11.5 - 2 - 4 = 5.5 bits.
//   10 Mbit/s: both 16 bits -> process = 3 bits = 300 ns; one 11.0 bits needs detect <= 6 bits.
// A latency in nanoseconds fixed by logic plus one in link bit-times fits both speeds:
//   process = 2 bits + 100 ns (20: 100+100 = 200 ns; 10: 200+100 = 300 ns),
//   detect = 275 ns (20: 5.5 bits; 10: 2.75 bits <= 6).  5 Mbit/s has no datasheet figure: a prediction.
constexpr double kAckDetectNs = 275.0;
constexpr double kAckProcessBits = 2.0;
constexpr double kAckProcessNs = 100.0;
// Link DMA takes one memory access per byte per direction from the CPU (U); charged by the packet fidelity.
constexpr int kLinkDmaCyclesPerByte = 1;

// ---- Sine and cosine: occam's library routine, not an instruction (section 4) ----
// A documented op sequence per call, REAL64 (REAL32 uses fewer polynomial terms, see cost_model.cpp):
// call/return, range reduction x - k*pi/2 in two parts (Cody-Waite: 1 mul + fpint + 2 mul + 2 sub), quadrant
// selection (2 branches, 4 simple ops), and an odd/even polynomial in x^2 evaluated by Horner.
constexpr int kSinCosTermsReal32 = 4;
constexpr int kSinCosTermsReal64 = 7;
OperationMix sincos_routine(bool real64);

}  // namespace t800::timing
