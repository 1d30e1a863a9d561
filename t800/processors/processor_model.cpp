#include "t800/processors/processor_model.hpp"

#include <array>
#include <stdexcept>

namespace t800 {

namespace {

// docs/t800-timing.md, sections "Clock" and "Memory". The speed grade is the processor clock in
// MHz (a 5 MHz input clock multiplied on chip): cycle = 1000 / MHz ns. On-chip RAM: 4 KB on the
// T800 and T805, 2 KB on the T414. MemStart: #80000070 on the T800/T805 (28 reserved words),
// #80000048 on the T414 (18 words). The external memory interface needs at least three processor
// cycles per access (T800-20: 26 MB/s against 80 MB/s on chip).
constexpr int kT800OnChip = 4096, kT414OnChip = 2048;
constexpr int kT800Reserved = 0x70, kT414Reserved = 0x48;
constexpr int kExternalAccess = 3;

std::array<ProcessorModel, 8> make_models() {
  const InstructionTimingTable* t800 = &t800_timing();
  const InstructionTimingTable* t805 = &t805_timing();
  const InstructionTimingTable* t414 = &t414_timing();
  const LinkProtocol overlapped = LinkProtocol::overlapped;
  return {{
      {ProcessorType::T800_20, "T800-20", 50.0, true, kT800OnChip, kT800Reserved, kExternalAccess,
       overlapped, t800},
      {ProcessorType::T800_25, "T800-25", 40.0, true, kT800OnChip, kT800Reserved, kExternalAccess,
       overlapped, t800},
      {ProcessorType::T800_30, "T800-30", 100.0 / 3.0, true, kT800OnChip, kT800Reserved,
       kExternalAccess, overlapped, t800},
      {ProcessorType::T805_20, "T805-20", 50.0, true, kT800OnChip, kT800Reserved, kExternalAccess,
       overlapped, t805},
      {ProcessorType::T805_25, "T805-25", 40.0, true, kT800OnChip, kT800Reserved, kExternalAccess,
       overlapped, t805},
      {ProcessorType::T805_30, "T805-30", 100.0 / 3.0, true, kT800OnChip, kT800Reserved,
       kExternalAccess, overlapped, t805},
      {ProcessorType::T414_15, "T414-15", 200.0 / 3.0, false, kT414OnChip, kT414Reserved,
       kExternalAccess, LinkProtocol::t414, t414},
      {ProcessorType::T414_20, "T414-20", 50.0, false, kT414OnChip, kT414Reserved, kExternalAccess,
       LinkProtocol::t414, t414},
  }};
}

const std::array<ProcessorModel, 8>& models() {
  static const std::array<ProcessorModel, 8> all = make_models();
  return all;
}

}  // namespace

const ProcessorModel& processor_model(ProcessorType type) {
  for (const ProcessorModel& m : models())
    if (m.type == type) return m;
  throw std::logic_error("processor_model: unknown processor type");
}

std::string_view to_string(ProcessorType type) {
  return processor_model(type).name;
}

std::optional<ProcessorType> parse_processor_type(std::string_view text) {
  for (const ProcessorModel& m : models())
    if (m.name == text) return m.type;
  return std::nullopt;
}

std::string processor_type_names() {
  std::string names;
  for (const ProcessorModel& m : models()) {
    if (!names.empty()) names += ", ";
    names += m.name;
  }
  return names;
}

std::vector<ProcessorType> all_processor_types() {
  std::vector<ProcessorType> types;
  for (const ProcessorModel& m : models()) types.push_back(m.type);
  return types;
}

}  // namespace t800
