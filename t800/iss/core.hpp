// One T800 (or T805, T414) executing real machine code: registers, memory, the microcoded
// scheduler with its queues in simulated memory, the timers, and every instruction, each timed by
// the one timing rule the static model uses (t800/processors/timing_stepper.hpp).
//
// The core runs ahead on its own clock (cycles since reset) and stops only where the world outside
// matters: a link transfer started, nothing to run, a limit, a halt. Whoever drives it (a test, a
// SystemC thread) tells it what the links did and how far time went (LinkEngine, advance_to).
// Facts: shared/reference/t800-iss.md; semantics from the compiler writer's guide (CWG).
#pragma once

#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "t800/iss/blocks.hpp"
#include "t800/iss/decoder.hpp"
#include "t800/iss/fpu.hpp"
#include "t800/iss/integer_arithmetic.hpp"
#include "t800/iss/machine_words.hpp"
#include "t800/iss/memory.hpp"
#include "t800/iss/profile.hpp"
#include "t800/processors/processor_model.hpp"
#include "t800/processors/timing_stepper.hpp"

namespace t800::iss {

struct Registers {
  Word a = 0, b = 0, c = 0;
  Word iptr = 0;
  Word wptr = 0;  // word aligned; the priority is kept apart (Wdesc = wptr | priority)
  int priority = kLow;
  bool error = false, halt_on_error = false;
  Word fptr[2] = {kNotProcess, kNotProcess}, bptr[2] = {kNotProcess, kNotProcess};
  Word wdesc() const { return wptr | Word(priority); }
};

// What the links do, seen from the processor: the core starts transfers and is told when they end
// (Core::output_done, input_done, input_arrived). One per processor.
class LinkEngine {
 public:
  virtual ~LinkEngine() = default;
  // The process outputting on `link` is descheduled until output_done(link).
  virtual void start_output(int link, std::vector<std::uint8_t> bytes) = 0;
  // The process inputting `count` bytes on `link` is descheduled until input_done(link, bytes).
  virtual void start_input(int link, Word count) = 0;
  // A byte is waiting on `link`'s input (an ALT may select it without taking it).
  virtual bool input_pending(int link) const = 0;
  // An ALT enabled (`on`) or disabled the link's input: tell input_arrived when a byte comes.
  virtual void watch_input(int link, bool on) = 0;
  // resetch on a link channel: the engine abandons the transfer in that direction.
  virtual void reset(int link, bool output) = 0;
};

// A process waiting for something (simulator bookkeeping for reports; the chip keeps none).
struct WaitingProcess {
  Word wdesc = 0;
  Word iptr = 0;
  Word channel = 0;  // the channel word it waits on, or 0
  std::string what;  // "input", "output", "ALT", "timer", "stopped"
};

// running: the cycle bound was reached; sync: something outside must act now (a link transfer
// started: its owner starts it at the core's cycle, see request_sync); limit: the instruction
// budget is spent; idle: nothing to run; halted: see halt_report.
enum class StopReason { running, sync, limit, idle, halted };

struct HaltReport {
  std::string reason;  // "undefined operation #1FE", "HaltOnError: error set by add", ...
  Word iptr = 0;
  std::vector<std::uint8_t> bytes;  // the instruction's
  Registers registers;
};

struct CoreConfig {
  const ProcessorModel* processor = nullptr;
  std::int64_t installed_bytes = 1 << 20;  // from MostNeg, on-chip RAM included
  AddressPolicy policy = AddressPolicy::wrap;
  int wait_states = 0;  // added to each external access
  // Straight-line code is timed once for each way it runs and replayed (blocks.hpp): the same
  // cycles as stepping every instruction, faster. False steps every instruction (tests compare).
  bool blocks = true;
};

class Core {
 public:
  explicit Core(const CoreConfig& config);

  // Boot: the program's bytes are at MemStart; the process starts at low priority with its
  // workspace just above the code, C holding the boot link's input channel (t800-iss.md).
  void start_boot_program(Word length, int boot_link);
  // Starts a process at `iptr` with workspace `wptr` (tests, loaders).
  void start_process(Word iptr, Word wptr, int priority);

  // Runs until cycle `until` (exclusive: an instruction may start before it and end after), or
  // `max_instructions` more instructions, or nothing is left to run, or a halt.
  StopReason run(std::int64_t until, std::int64_t max_instructions);
  // Time moved on to `cycle` while the core was idle: due timers fire.
  void advance_to(std::int64_t cycle);

  // Link events (from the LinkEngine's owner), at the core's current cycle.
  void output_done(int link);
  void input_done(int link, const std::vector<std::uint8_t>& bytes);
  void input_arrived(int link);
  void set_link_engine(LinkEngine* engine) { links_ = engine; }
  // From a LinkEngine callback: run() returns StopReason::sync after the current instruction, so
  // the transfer can start at the core's cycle instead of wherever its run-ahead reaches.
  void request_sync() { sync_requested_ = true; }
  // Link DMA took `cycles` memory cycles the CPU waited for (docs/t800-timing.md 6).
  void stall(std::int64_t cycles) { stepper_.wait_until(cycle() + cycles); }

  // A run that may have to be undone (a processor of a network running ahead of its neighbours,
  // docs/iss.md "Running ahead"): checkpoint() keeps the core's state and starts the memory's undo
  // log; rollback() goes back to that state, as if the run since had not happened; commit() lets
  // it stand. A profile's tallies are not kept: a profiled core is not rolled back.
  void checkpoint();
  void rollback();
  void commit();
  bool checkpointed() const { return checkpoint_ != nullptr; }

  std::int64_t cycle() const { return stepper_.iu_free(); }
  // The earliest cycle a waiting timer fires, or none.
  std::optional<std::int64_t> next_timer_cycle() const;
  bool idle() const;
  bool halted() const { return halt_.has_value(); }
  const std::optional<HaltReport>& halt_report() const { return halt_; }
  std::vector<WaitingProcess> waiting() const;

  Memory& memory() { return memory_; }
  const Memory& memory() const { return memory_; }
  Registers& registers() { return r_; }
  const Registers& registers() const { return r_; }
  Fpu& fpu() { return fpu_; }
  const ProcessorModel& processor() const { return processor_; }
  const StepTotals& timing() const { return stepper_.totals(); }
  // Every instruction from now on is tallied in `profile` (null: none; not owned).
  void set_profile(InstructionProfile* profile) { profile_ = profile; }
  std::int64_t instructions() const { return instructions_; }
  const BlockCounts& block_counts() const { return blocks_.counts(); }
  Word mem_start() const { return kMostNeg + Word(processor_.reserved_bytes); }
  // The timer of `priority` at the current cycle.
  Word clock(int priority) const;

 private:
  void step(const Decoded& d);
  // Runs the block at Iptr if there is one that ends before cycle `before` within the instruction
  // budget (`last`), and the blocks after it while they do; false if none ran (the caller steps
  // the instruction).
  bool run_block(std::int64_t before, std::int64_t last);
  bool run_one_block(std::int64_t before, std::int64_t last);
  // Executes the block's instructions from `done` up to `to`; false if one stopped it first.
  bool execute_block(const Block& b, int to, std::uint64_t stops, int& done,
                     std::uint64_t& variants, TimedStep& t);
  // Steps the timing rule through the block's instructions [from, to), as step() does one (the
  // last with its timing parameter `last_param`).
  void time_block(const Block& b, int from, int to, std::uint64_t variants,
                  std::int64_t last_param);
  void execute(const Decoded& d, TimedStep& t);
  void operate(const Decoded& d, TimedStep& t);
  void fpu_operate(isa::Op op, TimedStep& t);
  [[gnu::noinline, gnu::cold]] void refuse(const Decoded& d);
  void undefined(const Decoded& d, const std::string& what);
  void halt(const std::string& reason, Word iptr);
  void set_error(const char* by);
  // A block (in, out, move) longer than the installed memory is refused with a halt: on a board
  // with partial decoding it would copy over itself for minutes of host time, on any board it is a
  // wild count.
  bool block_fits(Word count, std::string_view what);
  void memory_fault(const MemoryFault& fault, Word iptr);
  void output_done_unguarded(int link);
  void input_done_unguarded(int link, const std::vector<std::uint8_t>& bytes);
  void input_arrived_unguarded(int link);

  // Stack.
  void push(Word v) {
    r_.c = r_.b;
    r_.b = r_.a;
    r_.a = v;
  }
  Word pop() {
    const Word v = r_.a;
    r_.a = r_.b;
    r_.b = r_.c;
    return v;
  }
  Word ws(int slot) const { return memory_.word(r_.wptr + Word(slot * 4)); }
  void set_ws(int slot, Word v) { memory_.set_word(r_.wptr + Word(slot * 4), v); }
  static Word slot_of(Word wptr, int slot) { return wptr + Word(slot * 4); }

  // Scheduling (scheduler.cpp).
  void enqueue(Word wdesc);
  void schedule(Word wdesc);
  void deschedule(const char* what, Word channel);
  void next_process();
  bool run_next_from_queue(int priority);
  void interrupt_low();
  void timeslice_point();
  void insert_timer(Word time);
  void remove_timer(Word wptr, int priority);
  void fire_timers();
  void refresh_next_timer();
  std::int64_t ns_to_cycle_ceiling(double ns) const;

  // Communication (channels.cpp).
  void input(Word count, Word channel, Word pointer);
  void output(Word count, Word channel, Word pointer);
  bool enable_channel(Word guard, Word channel);  // true: ready
  void disable_channel(Word offset, Word guard, Word channel);
  void alt_wait();
  void timer_alt_wait();
  void reset_channel(Word channel);
  void unblocked(Word wptr) { waiting_.erase(wptr); }

  void data_at(TimedStep& t, Word address) { t.data_external = memory_.external(address); }
  // A checked operation's result replaces A and B; an overflow sets Error.
  void arithmetic_result(Checked x, isa::Op op) {
    r_.a = x.value;
    r_.b = r_.c;
    if (x.overflow) [[unlikely]]
      set_error(isa::mnemonic(op).data());
  }
  // Control goes elsewhere (a jump taken, a call, a process switch): the prefetch buffer is emptied
  // once the instruction doing it is timed -- its own code was fetched before it ran -- or at once
  // between instructions.
  void control_moved() {
    if (stepping_)
      moved_ = true;
    else
      stepper_.restart_fetch();
  }

  // Every member below that a run changes is kept by checkpoint() (checkpoint.cpp), memory by its
  // undo log; the caches (decoded_, blocks_) hold only what memory says, and follow its undo.
  struct Checkpoint;
  template <class Keep>
  void each_kept(Checkpoint& c, Keep keep);
  std::unique_ptr<Checkpoint> checkpoint_;
  const ProcessorModel& processor_;
  Memory memory_;
  DecodeCache decoded_;
  TimingStepper stepper_;
  BlockCache blocks_;
  bool blocks_on_;
  Word stepping_from_ = 0, stepping_to_ = 0;  // a block declined, stepped instead (run_block)
  Registers r_;
  Fpu fpu_;
  LinkEngine* links_ = nullptr;
  std::int64_t instructions_ = 0;
  bool running_ = false;  // a process holds the CPU
  InstructionProfile* profile_ = nullptr;
  bool stepping_ = false;  // an instruction is executing (control_moved)
  bool moved_ = false;     // it moved control elsewhere
  bool sync_requested_ = false;
  bool low_interrupted_ = false;  // a low-priority process's state is in the save area
  Fpu saved_low_fpu_;             // its FPU registers (the chip keeps them in the FPU)
  bool timers_running_ = false;
  Word clock_base_[2] = {0, 0};
  double clock_base_ns_ = 0;
  std::int64_t next_timer_ = std::numeric_limits<std::int64_t>::max();
  std::int64_t slice_start_ = 0;  // the running low-priority process's dispatch cycle
  // A block's instructions execute before its timing is taken (block_run.cpp): a timeslice point
  // ending one is the clock's only reader, and starts this many cycles after cycle().
  std::int64_t slice_clock_ahead_ = 0;
  std::int64_t timeslice_cycles_;
  int interrupt_latency_;
  bool j0_break_ = false;  // T805 setj0break
  Word move2d_length_ = 0, move2d_dest_stride_ = 0, move2d_source_stride_ = 0;
  std::unordered_map<Word, WaitingProcess> waiting_;
  std::optional<HaltReport> halt_;
  std::string error_by_;  // the instruction that set Error last
};

// What Core::checkpoint keeps (checkpoint.cpp): every member a run changes but memory.
struct Core::Checkpoint {
  explicit Checkpoint(const TimingStepper& s) : stepper(s) {}  // the rest: Core::each_kept
  TimingStepper stepper;
  BlockCounts block_counts;
  Word stepping_from, stepping_to;
  Registers registers;
  Fpu fpu, saved_low_fpu;
  std::int64_t instructions;
  bool running, low_interrupted, timers_running, j0_break;
  Word clock_base[2];
  double clock_base_ns;
  std::int64_t next_timer, slice_start, slice_clock_ahead;
  Word move2d_length, move2d_dest_stride, move2d_source_stride;
  std::unordered_map<Word, WaitingProcess> waiting;
  std::optional<HaltReport> halt;
  std::string error_by;
};

}  // namespace t800::iss
