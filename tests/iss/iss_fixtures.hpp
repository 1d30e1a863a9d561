// A processor of the instruction-set simulator with a program assembled by the project's assembler
// and loaded as a boot would load it, driven the way a network drives it: run until it stops, let
// simulated time pass to the next timer when it is idle.
#pragma once

#include <gtest/gtest.h>

#include <deque>
#include <string>
#include <vector>

#include "t800/asm/assembler.hpp"
#include "t800/iss/core.hpp"

namespace iss_test {

using t800::iss::Word;

// Links as a test scripts them: what the program outputs is recorded and acknowledged at once; an
// input takes the next bytes of `incoming[link]` if there are enough, or waits for them.
class ScriptedLinks : public t800::iss::LinkEngine {
 public:
  std::vector<std::uint8_t> sent[4];
  std::deque<std::uint8_t> incoming[4];
  int resets = 0;
  t800::iss::Core* core = nullptr;

  void start_output(int link, std::vector<std::uint8_t> bytes) override {
    sent[link].insert(sent[link].end(), bytes.begin(), bytes.end());
    pending_output_[link] = true;
  }
  void start_input(int link, Word count) override { wanted_[link] = count; }
  bool input_pending(int link) const override { return !incoming[link].empty(); }
  void watch_input(int link, bool on) override { watched_[link] = on; }
  void reset(int link, bool output) override {
    ++resets;
    if (output)
      pending_output_[link] = false;
    else
      wanted_[link] = 0;
  }
  // Completes what can complete; true if anything did.
  bool deliver() {
    bool any = false;
    for (int l = 0; l < 4; ++l) {
      if (pending_output_[l]) {
        pending_output_[l] = false;
        core->output_done(l);
        any = true;
      }
      if (wanted_[l] && incoming[l].size() >= wanted_[l]) {
        std::vector<std::uint8_t> bytes(incoming[l].begin(), incoming[l].begin() + wanted_[l]);
        incoming[l].erase(incoming[l].begin(), incoming[l].begin() + wanted_[l]);
        wanted_[l] = 0;
        core->input_done(l, bytes);
        any = true;
      } else if (watched_[l] && !incoming[l].empty()) {
        watched_[l] = false;
        core->input_arrived(l);
        any = true;
      }
    }
    return any;
  }

 private:
  bool pending_output_[4] = {};
  Word wanted_[4] = {};
  bool watched_[4] = {};
};

struct TestMachine {
  explicit TestMachine(t800::ProcessorType type = t800::ProcessorType::T800_20,
                       std::int64_t installed = 1 << 20,
                       t800::iss::AddressPolicy policy = t800::iss::AddressPolicy::wrap,
                       int wait_states = 0, bool blocks = true)
      : core({&t800::processor_model(type), installed, policy, wait_states, blocks}) {
    links.core = &core;
    core.set_link_engine(&links);
  }

  // Assembles `source` for MemStart, loads it there and starts it as a booted program.
  t800::assembly::Program boot(const std::string& source) {
    auto program = t800::assembly::assemble(source, {core.mem_start(), "test"});
    core.memory().write(core.mem_start(), program.bytes.data(), program.bytes.size());
    core.start_boot_program(Word(program.bytes.size()), 0);
    return program;
  }

  // Runs until nothing can happen any more (idle with no timer due), a halt, or the limit.
  t800::iss::StopReason run(std::int64_t max_instructions = 10'000'000) {
    using t800::iss::StopReason;
    for (;;) {
      const std::int64_t left = max_instructions - core.instructions();
      const StopReason why = core.run(std::numeric_limits<std::int64_t>::max(), left);
      if (why == StopReason::halted || why == StopReason::limit) return why;
      if (links.deliver()) continue;
      if (const auto due = core.next_timer_cycle()) {
        core.advance_to(*due);
        continue;
      }
      return why;
    }
  }

  Word word(Word address) const { return core.memory().word(address); }
  Word label(const t800::assembly::Program& p, const std::string& name) const {
    return p.labels.at(name);
  }

  t800::iss::Core core;
  ScriptedLinks links;
};

// A body's results as it leaves them on the stack (A, B, C) and the Error flag.
struct Stack {
  Word a, b, c;
  bool error;
};

// Runs `body` after `ajw 16` (so workspace words 0..15 are the body's), then stopp, on a fresh
// processor of `type`; the run must end idle (`body` names it in a failure).
inline Stack run_stack(const std::string& body,
                       t800::ProcessorType type = t800::ProcessorType::T800_20,
                       std::int64_t installed = 1 << 20) {
  TestMachine m(type, installed);
  m.boot("ajw 16\n" + body + "\nstopp\n");
  EXPECT_EQ(m.run(), t800::iss::StopReason::idle) << body;
  const auto& r = m.core.registers();
  return {r.a, r.b, r.c, r.error};
}

// A loop whose blocks recur with their data on chip (even counts) and off it (odd counts), their
// FPU operands REAL32 and REAL64, while a high-priority process waits on the timer and interrupts
// it; `padding` bytes in front put the code in external memory (the on-chip RAM is 4 KB).
inline std::string mixed_loop(int padding, int iterations) {
  return R"(
        j start
        .space )" +
         std::to_string(padding) + R"(
start:  ajw 64
        ldc 0
        sttimer
        ldc child - next
        ldpi
next:   stl -21              -- the child's Iptr, below its workspace
        ldlp -20             -- its Wdesc: priority 0, high
        runp
        ldc )" +
         std::to_string(iterations) +
         R"(
        stl 1
loop:   ldl 1
        ldc 1
        and
        cj even
        ldc #80020000        -- odd: data in external memory, REAL64
        stl 3
        ldc #80020000
        fpldnldb
        j body
even:   ldc #80000F00        -- even: data on chip, REAL32
        stl 3
        ldc #80000F00
        fpldnlsn
body:   ldl 3
        ldnl 0
        adc 3
        ldl 3
        stnl 0
        fpdup
        fpadd
        ldl 1
        ldl 1
        mul
        ldl 3
        stnl 1
        ldl 1
        ldc 1
        and
        cj single
        ldl 3
        fpstnldb
        j counted
single: ldl 3
        fpstnlsn
counted: ldl 1
        adc -1
        stl 1
        ldl 1
        cj done
        j loop
done:   ldl -19              -- what the child saw
        stl 2
        stopp
child:  ldtimer
        adc 40
        tin
        ldtimer
        stl 1
        stopp
)";
}

}  // namespace iss_test
