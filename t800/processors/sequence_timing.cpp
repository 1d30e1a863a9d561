#include "t800/processors/sequence_timing.hpp"

namespace t800 {

using isa::Instruction;

bool MemoryView::external(const isa::MemoryRef& ref) const {
  switch (ref.region) {
    case isa::Region::none:
      return false;
    case isa::Region::workspace:
      return workspace_external;
    case isa::Region::code:
      return code_external;
    case isa::Region::library:
      return library_external;
    case isa::Region::array:
      return ref.array >= 0 && std::size_t(ref.array) < array_external.size() &&
             array_external[std::size_t(ref.array)];
  }
  return false;
}

bool MemoryView::operator==(const MemoryView& o) const {
  return workspace_external == o.workspace_external && code_external == o.code_external &&
         library_external == o.library_external && array_external == o.array_external &&
         external_cycles == o.external_cycles;
}

SequenceTime& SequenceTime::operator+=(const SequenceTime& o) {
  cycles += o.cycles;
  iu_busy += o.iu_busy;
  fpu_busy += o.fpu_busy;
  fpu_waits += o.fpu_waits;
  fetch_waits += o.fetch_waits;
  memory_cycles += o.memory_cycles;
  bytes += o.bytes;
  instructions += o.instructions;
  return *this;
}

SequenceTime SequenceTime::repeated(std::int64_t times) const {
  SequenceTime t;
  t.cycles = cycles * times;
  t.iu_busy = iu_busy * times;
  t.fpu_busy = fpu_busy * times;
  t.fpu_waits = fpu_waits * times;
  t.fetch_waits = fetch_waits * times;
  t.memory_cycles = memory_cycles * times;
  t.bytes = bytes * times;
  t.instructions = instructions * times;
  return t;
}

SequenceTime time_sequence(const isa::Sequence& code, const ProcessorModel& processor,
                           const MemoryView& memory, isa::Region code_region,
                           std::vector<InstructionTime>* trace) {
  TimingStepper stepper(*processor.timing, memory.external_cycles,
                        memory.external({code_region, -1}));
  std::int64_t position = 0;
  if (trace) trace->clear();
  for (const Instruction& in : code) {
    TimedStep step;
    step.op = in.op;
    step.prefix_cycles = prefix_cycles(in.op, in.operand);
    step.bytes = in.bytes();
    step.address = position;
    step.param = in.param;
    step.real64 = in.real64;
    step.data_external = memory.external(in.data);
    const InstructionTime when = stepper.step(step);
    if (trace) trace->push_back(when);
    position += step.bytes;
  }
  const StepTotals& t = stepper.totals();
  SequenceTime total;
  total.cycles = stepper.end();
  total.iu_busy = t.iu_busy;
  total.fpu_busy = t.fpu_busy;
  total.fpu_waits = t.fpu_waits;
  total.fetch_waits = t.fetch_waits;
  total.memory_cycles = t.memory_cycles;
  total.bytes = t.bytes;
  total.instructions = t.instructions;
  return total;
}

}  // namespace t800
