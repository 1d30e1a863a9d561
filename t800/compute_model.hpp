// What computation costs on one processor: recorded kernels compiled to this processor's T800 code
// (codegen/generator.hpp), timed instruction by instruction with its memory map (the default,
// ComputeCost::instructions), or operation mixes priced by the op-count model (ComputeCost::mix,
// and any work that has no recorded code). Compiled code and its timing are kept, so a kernel
// run many times is compiled and timed once.
#pragma once

#include <array>
#include <cstdint>
#include <limits>
#include <memory>
#include <unordered_map>

#include "t800/code_cache.hpp"
#include "t800/codegen/code_unit.hpp"
#include "t800/codegen/generator.hpp"
#include "t800/compute_work.hpp"
#include "t800/cost_model.hpp"
#include "t800/fidelity.hpp"
#include "t800/memory_map.hpp"
#include "t800/processors/sequence_timing.hpp"

namespace t800 {

struct ComputeSettings {
  Precision precision = Precision::real64;  // of mixes (recordings carry their own)
  // Cycles of the study's compiled occam per cycle of the modelled code; 1 unless a study's
  // calibration says otherwise.
  double code_efficiency = 1.0;
  ComputeCost cost = ComputeCost::instructions;
  bool checked = true;  // occam's run-time checks compiled in (codegen::Target::checked)
};

class ComputeModel {
 public:
  // `code`: compiled code shared with other processors (a machine's); by default its own.
  ComputeModel(const ProcessorConfig& config, const ComputeSettings& settings,
               std::shared_ptr<CodeCache> code = nullptr);

  std::int64_t cycles(const ComputeWork& work) const;
  // One channel communication as occam compiles it (docs/t800-timing.md, "Communication and
  // processes"): the buffer's address, the channel word, the length, then in or out -- 2w + 19 when
  // this end copies the message (an internal channel's second party), 19 when a link engine moves
  // it.
  std::int64_t communication_cycles(std::int64_t bytes, bool copies) const;
  // A short sequence of the process's own instructions (ALT's enables and disables, a timer's
  // input), timed with this processor's table and its workspace's placement.
  std::int64_t process_cycles(const isa::Sequence& code) const;

  // This processor's code for a recorded kernel (compiled once), as timed: without listing notes.
  const codegen::CodeUnit& code(const std::shared_ptr<const codegen::Recording>& kernel) const;
  // The same code with each instruction's note, for listings (compiled again on first use).
  const codegen::CodeUnit& annotated_code(
      const std::shared_ptr<const codegen::Recording>& kernel) const;
  // Its timing with this processor's memory map; per-instruction times for listings if asked.
  SequenceTime time(const codegen::CodeUnit& unit) const;
  MemoryView memory_view(const codegen::CodeUnit& unit) const;

  // The placement of what runs here, once the machine knows it; until then, all on chip.
  void set_memory(MemoryMap map);
  const MemoryMap& memory() const { return memory_; }

  const ProcessorModel& processor() const { return processor_; }
  const ComputeSettings& settings() const { return settings_; }
  // What its code is compiled for; no notes: nothing but a listing reads them.
  codegen::Target target() const { return {processor_.has_fpu, settings_.checked, false}; }
  double cycle_ns() const { return processor_.cycle_ns; }
  const CostModel& mix_model() const { return mix_; }

 private:
  struct Compiled {
    const codegen::CodeUnit* unit = nullptr;  // in code_
    std::int64_t cycles = -1;                 // -1: not timed yet (timing needs the memory map)
  };
  Compiled& compiled(const std::shared_ptr<const codegen::Recording>& kernel) const;

  ProcessorConfig config_;
  const ProcessorModel& processor_;
  ComputeSettings settings_;
  CostModel mix_;
  MemoryMap memory_;
  std::shared_ptr<CodeCache> code_;
  // By kernel; code_ keeps each kernel alive, so the keys stay unique.
  mutable std::unordered_map<const codegen::Recording*, Compiled> compiled_;
  mutable std::unordered_map<std::int64_t, std::int64_t> communication_;  // by signed length
  // The lengths asked last, by signed length modulo the size: asked at every channel communication,
  // and a hash table's lookup was a percent of a finest-level run.
  struct Recent {
    std::int64_t key = std::numeric_limits<std::int64_t>::min();  // no length
    std::int64_t cycles = 0;
  };
  mutable std::array<Recent, 16> communication_recent_;
};

}  // namespace t800
