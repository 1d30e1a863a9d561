#include "t800/iss/kernel_loader.hpp"

#include <fmt/format.h>

#include <cstring>
#include <limits>
#include <memory>
#include <stdexcept>

#include "t800/codegen/frame.hpp"
#include "t800/iss/core.hpp"

namespace t800::iss {

namespace {

using codegen::CodeRun;
using codegen::CodeUnit;
using isa::Instruction;
using isa::Op;

// ---- The execution order ----

struct Loop;
struct Element {
  int run = -1;                // a run, or
  std::shared_ptr<Loop> loop;  // a loop
};
using Body = std::vector<Element>;
struct Group {
  std::int64_t size = 0;  // iterations in a row with this code
  Body body;
};
struct Loop {
  int depth = 0;
  std::vector<Group> groups;
};

class OrderParser {
 public:
  explicit OrderParser(const std::vector<CodeRun>& runs) : runs_(runs) {}

  Body top() {
    Body b = body(0, 1, false);
    if (pos_ != runs_.size()) fail("runs left over");
    return b;
  }

 private:
  [[noreturn]] void fail(const std::string& what) const {
    throw std::runtime_error(
        fmt::format("execution order: {} at run {} of {}", what, pos_, runs_.size()));
  }
  // The run ends with a loop's set-up (its control block at 2 * depth, stored last, or the
  // count's test after it), and the generator says how many iterations follow.
  static bool setup(const CodeRun& r, int depth, std::int64_t* count) {
    if (r.seq_iterations < 0) return false;
    for (const Instruction& in : r.code)
      if (in.op == Op::stl && in.operand == 2 * depth + 1) {
        *count = r.seq_iterations;
        return true;
      }
    throw std::runtime_error("execution order: a SEQ's set-up without its control block");
  }
  // The run ends an iteration of the loop at `depth`: ldlp 2d; ldc back; lend.
  static bool closes(const CodeRun& r, int depth) {
    const auto& c = r.code;
    const std::size_t n = c.size();
    return n >= 3 && c[n - 1].op == Op::lend && c[n - 3].op == Op::ldlp &&
           c[n - 3].operand == 2 * depth;
  }

  Body body(int depth, std::int64_t times, bool iteration) {
    Body b;
    while (pos_ < runs_.size()) {
      const CodeRun& r = runs_[pos_];
      if (r.library) fail("a run-time library routine's run (its code is not the unit's)");
      if (r.times != times)
        fail(fmt::format("a run of {} times where its body runs {} times", r.times, times));
      b.push_back({int(pos_), nullptr});
      ++pos_;
      if (iteration && closes(r, depth - 1)) return b;
      std::int64_t count = 0;
      if (setup(r, depth, &count)) b.push_back({-1, loop(depth, times, count)});
    }
    if (iteration) fail("an iteration that does not end with its loop's lend");
    return b;
  }

  std::shared_ptr<Loop> loop(int depth, std::int64_t times, std::int64_t count) {
    auto l = std::make_shared<Loop>();
    l->depth = depth;
    std::int64_t done = 0;
    while (done < count) {
      if (pos_ >= runs_.size()) fail("a loop with fewer iterations than its count");
      const std::int64_t t = runs_[pos_].times;
      if (t % times != 0) fail("an iteration group whose times is not a multiple of its loop's");
      Group g;
      g.size = t / times;
      g.body = body(depth + 1, times * g.size, true);
      done += g.size;
      l->groups.push_back(std::move(g));
    }
    if (done != count) fail("a loop with more iterations than its count");
    return l;
  }

  const std::vector<CodeRun>& runs_;
  std::size_t pos_ = 0;
};

// One execution of a run; `loop_start` >= 0: it begins the first iteration of the loop at that
// depth (the loop's code starts at the address it is placed at).
struct Execution {
  int run = -1;
  int loop_start = -1;
};

void flatten(const Body& body, std::vector<Execution>& out, int& mark) {
  for (const Element& e : body) {
    if (e.run >= 0) {
      out.push_back({e.run, mark});
      mark = -1;
      continue;
    }
    bool first = true;
    for (const Group& g : e.loop->groups)
      for (std::int64_t k = 0; k < g.size; ++k) {
        if (first) mark = e.loop->depth;
        first = false;
        flatten(g.body, out, mark);
      }
  }
}

std::vector<Execution> executions(const CodeUnit& unit) {
  const Body top = OrderParser(unit.runs).top();
  std::vector<Execution> out;
  int mark = -1;
  flatten(top, out, mark);
  return out;
}

// ---- Memory ----

constexpr int kOnChipBytes = 1 << 20;            // the enlarged on-chip RAM
constexpr std::int64_t kInstalled = 1 << 21;     // and as much external memory again
constexpr Word kCodeLimit = kMostNeg + 0x60000;  // code and constants below this
constexpr Word kOnChipData = kMostNeg + 0x60000;
constexpr Word kExternalData = kMostNeg + Word(kOnChipBytes);
constexpr int kGuardWords = 16;  // below the PROC's frame, never touched

// An element's value, as the array holds it: an INT (a word), a REAL32 or a REAL64.
void put_value(Memory& m, Word address, double value, int bytes, bool integer) {
  if (integer) {
    m.set_word(address, std::uint32_t(std::int32_t(value)));
    return;
  }
  if (bytes == 8) {
    std::uint8_t b[8];
    std::memcpy(b, &value, 8);
    m.write(address, b, 8);
  } else {
    const float f = float(value);
    std::uint32_t w;
    std::memcpy(&w, &f, 4);
    m.set_word(address, w);
  }
}

double get_value(const Memory& m, Word address, int bytes, bool integer) {
  if (integer) return double(std::int32_t(m.word(address)));
  if (bytes == 8) {
    std::uint8_t b[8];
    m.read(address, b, 8);
    double d;
    std::memcpy(&d, b, 8);
    return d;
  }
  const std::uint32_t w = m.word(address);
  float f;
  std::memcpy(&f, &w, 4);
  return double(f);
}

}  // namespace

std::vector<int> execution_order(const CodeUnit& unit) {
  std::vector<int> order;
  for (const Execution& e : executions(unit)) order.push_back(e.run);
  return order;
}

KernelExecution execute_kernel(const CodeUnit& unit, const codegen::Recording& recording,
                               const std::vector<std::vector<double>>& inputs, ProcessorType type,
                               const KernelPlacement& placement) {
  KernelExecution x;
  ProcessorModel model = processor_model(type);
  model.on_chip_bytes = kOnChipBytes;

  // The static model's view of this placement, and its time.
  const std::size_t arrays = unit.arrays.size();
  x.view.workspace_external = placement.workspace_external;
  x.view.array_external.assign(arrays, placement.arrays_external);
  x.view.external_cycles = model.external_access_cycles + placement.wait_states;
  for (const CodeRun& run : unit.runs)
    x.expected += time_sequence(run.code, model, x.view,
                                run.library ? isa::Region::library : isa::Region::code)
                      .repeated(run.times);

  std::vector<Execution> order;
  try {
    order = executions(unit);
  } catch (const std::exception& e) {
    x.failure = e.what();
    return x;
  }

  Core core({&model, kInstalled, AddressPolicy::strict, placement.wait_states});
  Memory& memory = core.memory();
  const bool real64 = unit.real64;
  const Word real_bytes = real64 ? 8 : 4;
  const codegen::Frame frame(recording);
  if (recording.arrays().size() != arrays) {
    x.failure = "the unit's arrays are not the recording's";
    return x;
  }

  // The workspace: the PROC's frame (`workspace_words`, its call linkage at the top) below the
  // caller's, whose parameter words beyond the three in registers are at its 0, 1, ...
  int pointer_parameters = 0;
  for (const auto& a : unit.arrays)
    if (a.storage == codegen::ArrayStorage::pointer) ++pointer_parameters;
  const Word workspace_base = placement.workspace_external ? kExternalData : kOnChipData;
  const Word frame_ptr = workspace_base + Word(4 * kGuardWords);
  const Word caller = frame_ptr + Word(4 * unit.workspace_words);
  const Word workspace_end = caller + Word(4 * (std::max(pointer_parameters - 3, 0) + 4));

  // The arrays reached through pointers, one after the other (8-byte aligned).
  Word data = placement.arrays_external
                  ? (placement.workspace_external ? (workspace_end + 7) & ~7u : kExternalData)
                  : (placement.workspace_external ? kOnChipData : (workspace_end + 7) & ~7u);
  std::vector<Word> element0(arrays);
  for (std::size_t a = 0; a < arrays; ++a) {
    const auto& decl = unit.arrays[a];
    if (decl.storage == codegen::ArrayStorage::workspace) {
      element0[a] = frame_ptr + Word(4 * frame.array_base(int(a)));
    } else {
      element0[a] = data;
      data += Word(decl.length) * Word(codegen::element_bytes(decl, real64));
      data = (data + 7) & ~7u;
      memory.set_word(frame_ptr + Word(4 * frame.array_base(int(a))), element0[a]);
    }
    for (std::int64_t i = 0; i < decl.length; ++i) {
      double v = 0;
      if (a < inputs.size() && std::size_t(i) < inputs[a].size()) v = inputs[a][std::size_t(i)];
      const int bytes = codegen::element_bytes(decl, real64);
      put_value(memory, element0[a] + Word(i) * Word(bytes), v, bytes,
                decl.element == codegen::ElementType::int32);
    }
  }
  const bool regions_fit =
      (placement.workspace_external ? workspace_end <= kMostNeg + Word(kInstalled)
                                    : workspace_end <= kExternalData) &&
      data <= (placement.arrays_external ? kMostNeg + Word(kInstalled) : kExternalData);
  if (!regions_fit) {
    x.failure = "the kernel's workspace and arrays do not fit the loader's memory";
    return x;
  }
  // The IF tests' integer condition: true, the path the generator compiled.
  memory.set_word(frame_ptr + Word(4 * frame.integer_variable()), 1);

  // The unit's first byte on a word boundary, as a compiled module's is: the generator places the
  // constant table (ldc distance; ldpi) on a word boundary from there.
  const Word code_start = core.mem_start();
  if (code_start % 4 != 0) {
    x.failure = fmt::format("MemStart #{:08X} is not word aligned", code_start);
    return x;
  }
  core.start_process(code_start, caller, kHigh);
  const std::int64_t cycle0 = core.cycle(), instructions0 = core.instructions();
  const StepTotals totals0 = core.timing();

  Word at = code_start, back = 0, code_end = code_start;
  Word table = 0, table_end = 0;
  std::vector<Word> loop_start(8, 0);
  for (const Execution& e : order) {
    const CodeRun& run = unit.runs[std::size_t(e.run)];
    ++x.sequences;
    if (e.loop_start >= 0) {
      if (std::size_t(e.loop_start) >= loop_start.size()) loop_start.resize(e.loop_start + 1);
      loop_start[std::size_t(e.loop_start)] = at;
    }
    for (std::size_t k = 0; k < run.code.size(); ++k) {
      const Instruction& in = run.code[k];
      const std::vector<std::uint8_t> bytes = isa::encode(in.op, in.operand);
      const std::string where = fmt::format("run {} (\"{}\") instruction {} ({})", e.run, run.label,
                                            k, isa::assembly(in));
      const Word end = at + Word(bytes.size());
      if (int(bytes.size()) != in.bytes()) {
        x.failure = where + ": its encoding's length is not Instruction::bytes()";
        return x;
      }
      if (end > kCodeLimit || (table_end > table && at < table_end && end > table)) {
        x.failure =
            where + fmt::format(": code at #{:08X} runs into the constant table or data", at);
        return x;
      }
      memory.write(at, bytes.data(), bytes.size());
      code_end = std::max(code_end, end);
      Word next = end;
      switch (in.op) {
        case Op::call:
          back = end;
          next = end + Word(in.operand);
          break;
        case Op::cj:
          if (in.param) next = end + Word(in.operand);
          break;
        case Op::lend:
          if (in.param) {
            const int depth =
                k >= 2 && run.code[k - 2].op == Op::ldlp ? int(run.code[k - 2].operand / 2) : -1;
            if (depth < 0 || std::size_t(depth) >= loop_start.size()) {
              x.failure = where + ": a lend whose control block is not ldlp 2d";
              return x;
            }
            next = loop_start[std::size_t(depth)];
          }
          break;
        case Op::ret:
          next = back;
          break;
        case Op::ldpi:
          // ldc distance; ldpi: the constant table is `distance` bytes after ldpi's successor.
          if (k >= 1 && run.code[k - 1].op == Op::ldc && !unit.constants.empty()) {
            table = end + Word(run.code[k - 1].operand);
            table_end = table + Word(unit.constants.size()) * real_bytes;
            if (table < code_end || table_end > kCodeLimit) {
              x.failure = where + fmt::format(
                                      ": the constant table at #{:08X} overlaps the code "
                                      "(which reaches #{:08X})",
                                      table, code_end);
              return x;
            }
            for (std::size_t c = 0; c < unit.constants.size(); ++c)
              put_value(memory, table + Word(c) * real_bytes, unit.constants[c], int(real_bytes),
                        false);
          }
          break;
        default:
          break;
      }
      if (core.registers().iptr != at) {
        x.failure = where + fmt::format(": the ISS is at #{:08X}, the code at #{:08X}",
                                        core.registers().iptr, at);
        return x;
      }
      const StopReason why = core.run(std::numeric_limits<std::int64_t>::max(), 1);
      if (why == StopReason::halted) {
        x.failure = where + ": halted: " + core.halt_report()->reason;
        return x;
      }
      if (core.instructions() != instructions0 + x.instructions + 1) {
        x.failure = where + ": the ISS did not execute it (" +
                    std::string(why == StopReason::idle ? "idle" : "stopped") + ")";
        return x;
      }
      ++x.instructions;
      if (core.registers().iptr != next) {
        x.failure = where + fmt::format(
                                ": the ISS went to #{:08X}, the code's path continues at "
                                "#{:08X}",
                                core.registers().iptr, next);
        return x;
      }
      at = next;
    }
  }

  x.cycles = core.cycle() - cycle0;
  const StepTotals& t = core.timing();
  x.timing.iu_busy = t.iu_busy - totals0.iu_busy;
  x.timing.fpu_busy = t.fpu_busy - totals0.fpu_busy;
  x.timing.fpu_waits = t.fpu_waits - totals0.fpu_waits;
  x.timing.fetch_waits = t.fetch_waits - totals0.fetch_waits;
  x.timing.memory_cycles = t.memory_cycles - totals0.memory_cycles;
  x.timing.bytes = t.bytes - totals0.bytes;
  x.timing.instructions = t.instructions - totals0.instructions;
  x.error = core.registers().error;
  x.fp_error = core.fpu().error();
  x.arrays.resize(arrays);
  for (std::size_t a = 0; a < arrays; ++a) {
    const int bytes = codegen::element_bytes(unit.arrays[a], real64);
    for (std::int64_t i = 0; i < unit.arrays[a].length; ++i)
      x.arrays[a].push_back(get_value(memory, element0[a] + Word(i) * Word(bytes), bytes,
                                      unit.arrays[a].element == codegen::ElementType::int32));
  }
  return x;
}

}  // namespace t800::iss
