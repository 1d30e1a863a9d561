// Times a straight-line instruction sequence on one processor, instruction by instruction (through
// the one timing rule, timing_stepper.hpp, which the instruction-set simulator shares): the
// integer unit (IU) and the FPU run concurrently by the rules of instruction_timing.hpp's Unit, and
// every instruction fetch and data access is priced by where it lives (docs/t800-timing.md,
// "FPU overlap" and "Memory").
//
// Memory: on-chip RAM answers in the one cycle per access the instruction tables assume. An
// external access holds the one external bus for MemoryView::external_cycles; data accesses of an
// instruction take the bus when it starts, so the instruction lasts until they are done. Code in
// external memory is fetched a word (four instruction bytes) at a time, one word ahead of the
// instruction being executed (the prefetch buffer): an instruction waits for its word, and fetches
// share the bus with data. A sequence starts with an empty prefetch buffer, as after a jump.
#pragma once

#include <cstdint>
#include <vector>

#include "t800/isa/instruction.hpp"
#include "t800/processors/processor_model.hpp"
#include "t800/processors/timing_stepper.hpp"

namespace t800 {

// Where the memory a piece of code touches lives on its processor.
struct MemoryView {
  bool workspace_external = false;
  bool code_external = false;
  bool library_external = false;     // the run-time library's code and constants
  std::vector<bool> array_external;  // by array index of the code unit; missing = on chip
  int external_cycles = 3;           // one external access, wait states included

  bool external(const isa::MemoryRef& ref) const;
  bool operator==(const MemoryView& o) const;
};

struct SequenceTime {
  std::int64_t cycles = 0;         // until both units are idle
  std::int64_t iu_busy = 0;        // cycles the IU executed (waits excluded)
  std::int64_t fpu_busy = 0;       // cycles the FPU executed
  std::int64_t fpu_waits = 0;      // IU cycles spent waiting for the FPU
  std::int64_t fetch_waits = 0;    // cycles spent waiting for code from external memory
  std::int64_t memory_cycles = 0;  // cycles external data accesses added
  std::int64_t bytes = 0;          // code bytes executed
  std::int64_t instructions = 0;

  SequenceTime& operator+=(const SequenceTime& o);
  SequenceTime repeated(std::int64_t times) const;
};

// `code_region` is where the sequence's own instructions are fetched from (Region::code or
// Region::library).
SequenceTime time_sequence(const isa::Sequence& code, const ProcessorModel& processor,
                           const MemoryView& memory, isa::Region code_region = isa::Region::code,
                           std::vector<InstructionTime>* trace = nullptr);

}  // namespace t800
