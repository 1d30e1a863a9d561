#include "t800/compute_model.hpp"

#include <cmath>

namespace t800 {

ComputeModel::ComputeModel(const ProcessorConfig& config, const ComputeSettings& settings,
                           std::shared_ptr<CodeCache> code)
    : config_(config),
      processor_(processor_model(config.type)),
      settings_(settings),
      mix_(config, settings.precision, settings.code_efficiency),
      code_(code ? std::move(code) : std::make_shared<CodeCache>()) {}

void ComputeModel::set_memory(MemoryMap map) {
  memory_ = std::move(map);
  communication_.clear();
  for (auto& [key, c] : compiled_) c.cycles = -1;  // timed again with the new placement
  // The op-count model knows placement by kind only: data and code external when the map put
  // them there.
  ProcessorConfig resolved = config_;
  resolved.memory.data = memory_.data_external() || memory_.workspace_external()
                             ? Placement::external
                             : Placement::on_chip;
  resolved.memory.code =
      memory_.external_bytes(MemoryRegion::Kind::code) * 2 > memory_.bytes(MemoryRegion::Kind::code)
          ? Placement::external
          : Placement::on_chip;
  mix_ = CostModel(resolved, settings_.precision, settings_.code_efficiency);
}

ComputeModel::Compiled& ComputeModel::compiled(
    const std::shared_ptr<const codegen::Recording>& kernel) const {
  auto found = compiled_.find(kernel.get());
  if (found != compiled_.end()) return found->second;
  return compiled_.emplace(kernel.get(), Compiled{&code_->unit(kernel, target()), -1})
      .first->second;
}

const codegen::CodeUnit& ComputeModel::code(
    const std::shared_ptr<const codegen::Recording>& kernel) const {
  return *compiled(kernel).unit;
}

const codegen::CodeUnit& ComputeModel::annotated_code(
    const std::shared_ptr<const codegen::Recording>& kernel) const {
  codegen::Target annotated = target();
  annotated.notes = true;
  return code_->unit(kernel, annotated);
}

MemoryView ComputeModel::memory_view(const codegen::CodeUnit& unit) const {
  return memory_.view(unit.name, int(unit.arrays.size()));
}

SequenceTime ComputeModel::time(const codegen::CodeUnit& unit) const {
  const MemoryView view = memory_view(unit);
  SequenceTime total;
  for (const codegen::CodeRun& run : unit.runs)
    total += time_sequence(run.code, processor_, view,
                           run.library ? isa::Region::library : isa::Region::code)
                 .repeated(run.times);
  return total;
}

std::int64_t ComputeModel::cycles(const ComputeWork& work) const {
  if (settings_.cost == ComputeCost::mix || !work.code) return mix_.cycles(work.mix);
  Compiled& c = compiled(work.code);
  if (c.cycles < 0)
    c.cycles =
        std::int64_t(std::ceil(double(time(*c.unit).cycles) * settings_.code_efficiency - 1e-9));
  return c.cycles;
}

std::int64_t ComputeModel::communication_cycles(std::int64_t bytes, bool copies) const {
  const std::int64_t key = copies ? -bytes - 1 : bytes;
  Recent& recent = communication_recent_[std::uint64_t(key) % communication_recent_.size()];
  if (recent.key == key) return recent.cycles;
  recent.key = key;
  auto found = communication_.find(key);
  if (found != communication_.end()) return recent.cycles = found->second;
  const isa::MemoryRef workspace{isa::Region::workspace, -1};
  const std::int64_t words = copies ? (bytes + 3) / 4 : 0;  // part words count as whole
  const std::int64_t cycles = process_cycles({
      {isa::Op::ldlp, 0, 0, false, {}, "the message's buffer"},
      {isa::Op::ldl, 1, 0, false, workspace, "the channel"},
      {isa::Op::ldc, bytes, 0, false, {}, "its length"},
      {isa::Op::in, 0, words, false, workspace, "in (or out)"},
  });
  communication_.emplace(key, cycles);
  return recent.cycles = cycles;
}

std::int64_t ComputeModel::process_cycles(const isa::Sequence& code) const {
  MemoryView view;
  view.workspace_external = memory_.workspace_external();
  view.code_external = memory_.code_external("");
  view.external_cycles = memory_.external_cycles();
  return time_sequence(code, processor_, view).cycles;
}

}  // namespace t800
