// The timing constants of the T800 model that are not instruction cycles (those are in the
// processors' instruction tables): scheduling, links, the op-count model's SIN/COS. Each names
// its source and status in docs/t800-timing.md: S = stated by the source, D = derived from stated
// figures (arithmetic in the comment), U = a model assumption.
#pragma once

#include <cstdint>

#include "t800/operation_mix.hpp"

namespace t800::timing {

// Instruction cycles live in the processors' instruction tables
// (processors/instruction_tables.cpp).

// ---- Sections 3 and 7: communication and scheduling ----
// in / out = 2w + 19, startp, endp: the instruction table's figures (the same on every type).
int start_process_cycles();
int end_process_cycles();
constexpr int kInterruptLatencyTypical = 19;  // high-priority preemption latency (S)
constexpr int kInterruptLatencyMax = 58;      // (S)
constexpr double kTimesliceUs = 1024.0;       // 5120 ticks of the 5 MHz input clock (S)

// Memory sizes and external access cycles: processors/processor_model.cpp, memory_map.cpp.

// ---- Section 6: links (in bit-times of the link's own clock unless stated) ----
constexpr int kDataPacketBits = 11;  // 1, 1, 8 data bits, 0 (S)
constexpr int kAckPacketBits = 2;    // 1, 0 (S)
// Two latencies make the byte-level protocol reproduce the datasheet rates (DBK Table 8.1); both
// are D:
//  * ack turnaround (receiver): from the first bit of a data packet (overlapped, T800) or from its
//  last bit
//    (T414) until the receiver starts its acknowledge;
//  * ack processing (sender): from the end of an acknowledge until the sender may start its next
//  data packet.
// One direction streaming: period = max(11, detect + 2 + process) bits. Both directions: an
// acknowledge must wait behind the data packet its wire is carrying, so the period is 11 + 2 +
// process bits.
//   20 Mbit/s: both 17 bits -> process = 4 bits = 200 ns; one 11.5 bits -> detect = 11.5 - 2 - 4
//   = 5.5 bits. 10 Mbit/s: both 16 bits -> process = 3 bits = 300 ns; one 11.0 bits needs detect <=
//   6 bits.
// A latency in nanoseconds fixed by logic plus one in link bit-times fits both speeds:
//   process = 2 bits + 100 ns (20: 100+100 = 200 ns; 10: 200+100 = 300 ns),
//   detect = 275 ns (20: 5.5 bits; 10: 2.75 bits <= 6).  5 Mbit/s has no datasheet figure: a
//   prediction.
constexpr double kAckDetectNs = 275.0;
constexpr double kAckProcessBits = 2.0;
constexpr double kAckProcessNs = 100.0;
// Link DMA takes one memory access per byte per direction from the CPU (U); charged by the packet
// fidelity.
constexpr int kLinkDmaCyclesPerByte = 1;

// ---- Sine and cosine: occam's library routine, not an instruction (section 4) ----
// A documented op sequence per call, REAL64 (REAL32 uses fewer polynomial terms, see
// cost_model.cpp): call/return, range reduction x - k*pi/2 in two parts (Cody-Waite: 1 mul + fpint
// + 2 mul + 2 sub), quadrant selection (2 branches, 4 simple ops), and an odd/even polynomial in
// x^2 evaluated by Horner.
constexpr int kSinCosTermsReal32 = 4;
constexpr int kSinCosTermsReal64 = 7;
OperationMix sincos_routine(bool real64);

}  // namespace t800::timing
