#include "tools/listing_format.hpp"

#include <fmt/format.h>

namespace tools {

namespace {

using t800::isa::Instruction;
using t800::isa::Region;

std::string hex_bytes(const Instruction& in) {
  std::string text;
  for (std::uint8_t b : t800::isa::encode(in.op, in.operand)) text += fmt::format("{:02X} ", b);
  return text;
}

std::string memory_text(const Instruction& in, const t800::MemoryView& view,
                        const t800::codegen::CodeUnit& unit) {
  switch (in.data.region) {
    case Region::none:
      return "";
    case Region::workspace:
      return view.external(in.data) ? "ws ext" : "ws";
    case Region::code:
      return view.external(in.data) ? "code ext" : "code";
    case Region::library:
      return view.external(in.data) ? "lib ext" : "lib";
    case Region::array: {
      const std::string name = in.data.array >= 0 && std::size_t(in.data.array) < unit.arrays.size()
                                   ? unit.arrays[std::size_t(in.data.array)].name
                                   : "array";
      return view.external(in.data) ? name + " ext" : name;
    }
  }
  return "";
}

}  // namespace

std::string format_listing(const t800::codegen::CodeUnit& unit, const t800::ComputeModel& model) {
  const t800::MemoryView view = model.memory_view(unit);
  const t800::SequenceTime total = model.time(unit);
  std::string out = fmt::format(
      "PROC {} on a {} ({} ns cycle), {}: {} bytes of code, {} of constants, {} workspace words; "
      "code in {} memory\n",
      unit.name, model.processor().name, model.cycle_ns(), unit.real64 ? "REAL64" : "REAL32",
      unit.code_bytes, unit.constant_bytes, unit.workspace_words,
      view.code_external ? "external" : "on-chip");
  out += fmt::format(
      "executed: {} instructions, {} cycles ({:.2f} us); IU busy {}, FPU busy {}, IU waiting for "
      "the FPU {}, for code {}; external data accesses +{}\n",
      total.instructions, total.cycles, total.cycles * model.cycle_ns() / 1000.0, total.iu_busy,
      total.fpu_busy, total.fpu_waits, total.fetch_waits, total.memory_cycles);
  out +=
      "columns: address, bytes, instruction, start cycle, IU free, FPU free, waited, memory, "
      "source\n";
  for (const t800::codegen::CodeRun& run : unit.runs) {
    std::vector<t800::InstructionTime> trace;
    const t800::SequenceTime t = t800::time_sequence(
        run.code, model.processor(), view, run.library ? Region::library : Region::code, &trace);
    out +=
        fmt::format("\n-- {}{}: {} cycles{}\n", run.label, run.library ? " (run-time library)" : "",
                    t.cycles, run.times > 1 ? fmt::format(" each, {} times", run.times) : "");
    int address = 0;
    for (std::size_t i = 0; i < run.code.size(); ++i) {
      const Instruction& in = run.code[i];
      const t800::InstructionTime& when = trace[i];
      out +=
          fmt::format("{:04X}  {:<12} {:<16} {:>5} {:>5} {:>5} {:>4}  {:<10} {}\n", address,
                      hex_bytes(in), t800::isa::assembly(in), when.start, when.iu_end,
                      when.fpu_end == when.start ? std::string("-") : std::to_string(when.fpu_end),
                      when.waited ? std::to_string(when.waited) : std::string(""),
                      memory_text(in, view, unit), in.note);
      address += in.bytes();
    }
  }
  return out;
}

}  // namespace tools
