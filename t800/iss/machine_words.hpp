// The words the T800's microcode keeps in memory and the special values it gives them ("Transputer
// instruction set: a compiler writer's guide", INMOS 1988 (CWG), chapters on processes,
// communication and the memory map; the T800 datasheet's memory map). A process's state lives in
// the words just below its workspace pointer; the link channels, the event channel, the timer queue
// pointers and the interrupted low-priority process's registers live in the reserved words above
// MostNeg.
#pragma once

#include <cstdint>

namespace t800::iss {

using Word = std::uint32_t;

constexpr Word kMostNeg = 0x80000000u;
constexpr Word kMostPos = 0x7FFFFFFFu;
constexpr Word kTrue = 1, kFalse = 0;

// Special values (CWG): NotProcess.p is MostNeg; the ALT states follow it.
constexpr Word kNotProcess = kMostNeg;
constexpr Word kEnabling = kMostNeg + 1;
constexpr Word kWaiting = kMostNeg + 2;
constexpr Word kReady = kMostNeg + 3;
constexpr Word kTimeSet = kMostNeg + 1;
constexpr Word kTimeNotSet = kMostNeg + 2;
constexpr Word kNoneSelected = 0xFFFFFFFFu;  // -1

// Workspace slots, in words relative to Wptr (CWG): the selected ALT branch at 0, the saved Iptr,
// the queue link, the channel pointer or ALT state, the timer queue link, the time waited for.
constexpr int kSlotTemp = 0;
constexpr int kSlotIptr = -1;
constexpr int kSlotLink = -2;
constexpr int kSlotState = -3;  // also Pointer.s: where a waiting input or output's data is
constexpr int kSlotTLink = -4;
constexpr int kSlotTime = -5;

// Reserved words above MostNeg (T800 datasheet memory map): the hard link channels, the event
// channel, the timer queue heads, the save area of an interrupted low-priority process.
constexpr Word kLinkOutput0 = kMostNeg + 0x00;  // link n's output channel: + 4n
constexpr Word kLinkInput0 = kMostNeg + 0x10;   // link n's input channel: + 4n
constexpr Word kEventChannel = kMostNeg + 0x20;
constexpr Word kTimerQueueHigh = kMostNeg + 0x24;  // TPtrLoc0
constexpr Word kTimerQueueLow = kMostNeg + 0x28;   // TPtrLoc1
constexpr Word kSaveWdesc = kMostNeg + 0x2C;
constexpr Word kSaveIptr = kMostNeg + 0x30;
constexpr Word kSaveA = kMostNeg + 0x34;
constexpr Word kSaveB = kMostNeg + 0x38;
constexpr Word kSaveC = kMostNeg + 0x3C;
constexpr Word kSaveStatus = kMostNeg + 0x40;

constexpr int kLinks = 4;

enum Priority : int { kHigh = 0, kLow = 1 };

inline bool is_link_channel(Word address) {
  return address >= kLinkOutput0 && address < kEventChannel && (address & 3) == 0;
}
inline bool is_link_output(Word address) {
  return is_link_channel(address) && address < kLinkInput0;
}
inline int link_of(Word address) {
  return int((address - kMostNeg) >> 2) & 3;
}
// occam's AFTER: a is later than b, modulo the wrap of the clock.
inline bool after(Word a, Word b) {
  return std::int32_t(a - b) > 0;
}

}  // namespace t800::iss
