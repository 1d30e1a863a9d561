// Communication as the microcode does it (CWG, "communication" and "alternative"): an internal
// channel is one word, NotProcess.p or the descriptor of the process that got there first, whose
// data pointer (or ALT state) is in its workspace; the second party copies the message and
// reschedules the first. A hard link channel (the words above MostNeg) hands the transfer to the
// link engine and deschedules the process until the engine is done.
#include <fmt/format.h>

#include "t800/iss/core.hpp"

namespace t800::iss {

namespace {
bool alternating(Word state) {
  return state == kEnabling || state == kWaiting || state == kReady;
}
}  // namespace

void Core::input(Word count, Word channel, Word pointer) {
  if (!block_fits(count, "in")) return;
  if (is_link_channel(channel)) {
    if (is_link_output(channel)) {
      halt(fmt::format("in on link {}'s output channel #{:08X}", link_of(channel), channel),
           r_.iptr - 1);
      return;
    }
    if (count == 0) return;
    if (!links_) {
      halt(fmt::format("in on link {}, which is connected to nothing", link_of(channel)),
           r_.iptr - 1);
      return;
    }
    memory_.set_word(channel, r_.wdesc());
    set_ws(kSlotState, pointer);
    deschedule("input", channel);
    links_->start_input(link_of(channel), count);
    return;
  }
  const Word waiting = memory_.word(channel);
  if (waiting == kNotProcess) {
    memory_.set_word(channel, r_.wdesc());
    set_ws(kSlotState, pointer);
    deschedule("input", channel);
    return;
  }
  const Word other = waiting & ~3u;
  memory_.copy(pointer, memory_.word(slot_of(other, kSlotState)), count);
  memory_.set_word(channel, kNotProcess);
  schedule(waiting);
}

void Core::output(Word count, Word channel, Word pointer) {
  if (!block_fits(count, "out")) return;
  if (is_link_channel(channel)) {
    if (!is_link_output(channel)) {
      halt(fmt::format("out on link {}'s input channel #{:08X}", link_of(channel), channel),
           r_.iptr - 1);
      return;
    }
    if (count == 0) return;
    if (!links_) {
      halt(fmt::format("out on link {}, which is connected to nothing", link_of(channel)),
           r_.iptr - 1);
      return;
    }
    std::vector<std::uint8_t> bytes(count);
    memory_.read(pointer, bytes.data(), count);
    memory_.set_word(channel, r_.wdesc());
    deschedule("output", channel);
    links_->start_output(link_of(channel), std::move(bytes));
    return;
  }
  const Word waiting = memory_.word(channel);
  if (waiting == kNotProcess) {
    memory_.set_word(channel, r_.wdesc());
    set_ws(kSlotState, pointer);
    deschedule("output", channel);
    return;
  }
  const Word other = waiting & ~3u;
  const Word state = memory_.word(slot_of(other, kSlotState));
  if (alternating(state)) {
    // The receiver is in an ALT that enabled this channel: the outputter waits for the input
    // that follows its selection, and the ALT becomes ready.
    memory_.set_word(channel, r_.wdesc());
    set_ws(kSlotState, pointer);
    deschedule("output", channel);
    if (state == kWaiting) {
      memory_.set_word(slot_of(other, kSlotState), kReady);
      remove_timer(other, int(waiting & 1));
      schedule(waiting);
    } else if (state == kEnabling) {
      memory_.set_word(slot_of(other, kSlotState), kReady);
    }
    return;
  }
  memory_.copy(state, pointer, count);
  memory_.set_word(channel, kNotProcess);
  schedule(waiting);
}

bool Core::enable_channel(Word guard, Word channel) {
  // enbc: A guard, B channel; A stays.
  r_.b = r_.c;
  if (!guard) return false;
  if (is_link_channel(channel)) {
    if (links_ && links_->input_pending(link_of(channel))) {
      set_ws(kSlotState, kReady);
      return true;
    }
    memory_.set_word(channel, r_.wdesc());
    if (links_) links_->watch_input(link_of(channel), true);
    return false;
  }
  const Word waiting = memory_.word(channel);
  if (waiting == kNotProcess) {
    memory_.set_word(channel, r_.wdesc());
    return false;
  }
  if (waiting == r_.wdesc()) return false;
  set_ws(kSlotState, kReady);
  return true;
}

void Core::disable_channel(Word offset, Word guard, Word channel) {
  bool ready = false;
  if (guard) {
    if (is_link_channel(channel)) {
      ready = links_ && links_->input_pending(link_of(channel));
      if (links_) links_->watch_input(link_of(channel), false);
      if (memory_.word(channel) == r_.wdesc()) memory_.set_word(channel, kNotProcess);
    } else {
      const Word waiting = memory_.word(channel);
      if (waiting == r_.wdesc())
        memory_.set_word(channel, kNotProcess);
      else
        ready = waiting != kNotProcess;
    }
  }
  r_.a = kFalse;
  if (ready && ws(kSlotTemp) == kNoneSelected) {
    set_ws(kSlotTemp, offset);
    r_.a = kTrue;
  }
}

void Core::alt_wait() {
  set_ws(kSlotTemp, kNoneSelected);
  if (ws(kSlotState) == kReady) return;
  set_ws(kSlotState, kWaiting);
  deschedule("ALT", 0);
}

void Core::timer_alt_wait() {
  set_ws(kSlotTemp, kNoneSelected);
  if (ws(kSlotState) == kReady) return;
  if (ws(kSlotTLink) == kTimeSet) {
    const Word time = ws(kSlotTime);
    if (!after(time, clock(r_.priority))) {
      set_ws(kSlotState, kReady);
      return;
    }
    set_ws(kSlotState, kWaiting);
    insert_timer(time);
    deschedule("timer ALT", 0);
    return;
  }
  set_ws(kSlotState, kWaiting);
  deschedule("ALT", 0);
}

void Core::reset_channel(Word channel) {
  // resetch: A := what the channel held; the channel is empty again.
  const Word held = memory_.word(channel);
  memory_.set_word(channel, kNotProcess);
  if (is_link_channel(channel) && links_) links_->reset(link_of(channel), is_link_output(channel));
  r_.a = held;
}

void Core::output_done_unguarded(int link) {
  const Word channel = kLinkOutput0 + Word(4 * link);
  const Word waiting = memory_.word(channel);
  if (waiting == kNotProcess) return;  // reset meanwhile
  memory_.set_word(channel, kNotProcess);
  schedule(waiting);
}

void Core::output_done(int link) {
  try {
    output_done_unguarded(link);
  } catch (const MemoryFault& fault) {
    memory_fault(fault, r_.iptr);
  }
}

void Core::input_done_unguarded(int link, const std::vector<std::uint8_t>& bytes) {
  const Word channel = kLinkInput0 + Word(4 * link);
  const Word waiting = memory_.word(channel);
  if (waiting == kNotProcess) return;
  const Word pointer = memory_.word(slot_of(waiting & ~3u, kSlotState));
  memory_.write(pointer, bytes.data(), bytes.size());
  memory_.set_word(channel, kNotProcess);
  schedule(waiting);
}

void Core::input_done(int link, const std::vector<std::uint8_t>& bytes) {
  try {
    input_done_unguarded(link, bytes);
  } catch (const MemoryFault& fault) {
    memory_fault(fault, r_.iptr);
  }
}

void Core::input_arrived_unguarded(int link) {
  const Word channel = kLinkInput0 + Word(4 * link);
  const Word waiting = memory_.word(channel);
  if (waiting == kNotProcess) return;
  const Word wptr = waiting & ~3u;
  const Word state = memory_.word(slot_of(wptr, kSlotState));
  if (state == kWaiting) {
    memory_.set_word(slot_of(wptr, kSlotState), kReady);
    remove_timer(wptr, int(waiting & 1));
    schedule(waiting);
  } else if (state == kEnabling) {
    memory_.set_word(slot_of(wptr, kSlotState), kReady);
  }
}

void Core::input_arrived(int link) {
  try {
    input_arrived_unguarded(link);
  } catch (const MemoryFault& fault) {
    memory_fault(fault, r_.iptr);
  }
}

}  // namespace t800::iss
