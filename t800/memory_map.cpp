#include "t800/memory_map.hpp"

#include <algorithm>

#include <fmt/format.h>

namespace t800 {

const char* to_string(MemoryRegion::Kind kind) {
  switch (kind) {
    case MemoryRegion::Kind::reserved:
      return "reserved";
    case MemoryRegion::Kind::workspace:
      return "workspace";
    case MemoryRegion::Kind::data:
      return "data";
    case MemoryRegion::Kind::code:
      return "code";
    case MemoryRegion::Kind::library:
      return "library";
  }
  return "?";
}

// The occam toolset loads the application at #80000150 on a T800 (its memory maps): the words
// between MemStart and there hold its run-time system, which a T414 has above its own MemStart
// too (U: the T414's layout was not observed).
int loader_bytes() {
  constexpr int kT800ApplicationStart = 0x150, kT800MemStart = 0x70;
  return kT800ApplicationStart - kT800MemStart;
}

// Each wait state lengthens an external access by one Tm, half a processor cycle; an access
// ends on a whole cycle (docs/t800-timing.md, "Memory": U).
int external_access_cycles(const ProcessorModel& processor, int wait_states) {
  return processor.external_access_cycles + (wait_states + 1) / 2;
}

namespace {

std::string kilobytes(int bytes) {
  return fmt::format("{} bytes", bytes);
}

}  // namespace

MemoryMap::MemoryMap(const ProcessorModel& processor, const MemoryConfig& config,
                     const MemoryDemand& demand)
    : on_chip_bytes_(processor.on_chip_bytes),
      external_cycles_(external_access_cycles(processor, config.wait_states)),
      code_default_external_(config.code == Placement::external) {
  using Kind = MemoryRegion::Kind;
  int next = 0;
  auto add = [&](Kind kind, std::string name, int bytes, Placement placement) {
    if (bytes <= 0 && kind != Kind::reserved) return;
    MemoryRegion r{kind, std::move(name), next, bytes, false};
    next += bytes;
    r.external = placement == Placement::external ||
                 (placement == Placement::automatic && next > on_chip_bytes_);
    regions_.push_back(r);
  };
  add(Kind::reserved, "below MemStart", processor.reserved_bytes, Placement::on_chip);
  add(Kind::reserved, "run-time system", loader_bytes(), Placement::on_chip);
  add(Kind::workspace, "workspaces", demand.workspace_bytes, config.data);
  add(Kind::data, "arrays", demand.data_bytes, config.data);
  for (const MemoryDemand::Code& c : demand.code) add(Kind::code, c.name, c.bytes, config.code);
  add(Kind::library, "run-time library", demand.library_bytes, config.code);

  // Explicit on-chip placement must hold: everything placed on chip ends within on-chip RAM.
  int on_chip = 0;
  for (const MemoryRegion& r : regions_)
    if (!r.external) on_chip += r.bytes;
  if (on_chip > on_chip_bytes_)
    throw PlacementError(fmt::format(
        "{} on chip needs {} (reserved {}, workspaces {}, arrays {}, code {}, library {}) but "
        "on-chip RAM has {}: use memory = \"auto\" (what fits on chip, the rest external) or "
        "\"external\" for code or data",
        processor.name, kilobytes(on_chip), kilobytes(bytes(Kind::reserved)),
        kilobytes(bytes(Kind::workspace)), kilobytes(bytes(Kind::data)),
        kilobytes(bytes(Kind::code)), kilobytes(bytes(Kind::library)), kilobytes(on_chip_bytes_)));
}

int MemoryMap::bytes(MemoryRegion::Kind kind) const {
  int n = 0;
  for (const MemoryRegion& r : regions_)
    if (r.kind == kind) n += r.bytes;
  return n;
}

int MemoryMap::external_bytes(MemoryRegion::Kind kind) const {
  int n = 0;
  for (const MemoryRegion& r : regions_)
    if (r.kind == kind && r.external) n += r.bytes;
  return n;
}

bool MemoryMap::external(MemoryRegion::Kind kind) const {
  for (const MemoryRegion& r : regions_)
    if (r.kind == kind) return r.external;
  return false;
}

bool MemoryMap::code_external(const std::string& proc) const {
  for (const MemoryRegion& r : regions_)
    if (r.kind == MemoryRegion::Kind::code && r.name == proc) return r.external;
  return code_default_external_;
}

MemoryView MemoryMap::view(const std::string& proc, int arrays) const {
  MemoryView v;
  v.workspace_external = workspace_external();
  v.code_external = code_external(proc);
  v.library_external = library_external();
  v.array_external.assign(std::size_t(std::max(arrays, 0)), data_external());
  v.external_cycles = external_cycles_;
  return v;
}

}  // namespace t800
