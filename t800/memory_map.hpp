// What lives where in one processor's memory: its footprint (the code of the processes placed on
// it, their workspaces and arrays, the reserved low memory) laid out from the bottom of on-chip
// RAM, and which parts therefore sit in external memory (docs/compute-model.md, "On-chip memory
// that matters").
//
// The layout follows the INMOS occam toolset's memory maps: the words below MemStart are the
// processor's own, the loaded program's run-time system takes the next ones (the application
// starts at #80000150 on a T800), then come the workspaces, then the arrays (kept next to the
// workspace, as the toolset's option "V", which INMOS's own benchmarks use, does), then each PROC's
// code in the order its process declared it, then the run-time library's. With memory = "auto" a
// region lies on chip when it ends within on-chip RAM and in external memory otherwise (a region
// straddling the boundary counts as external); "onchip" requires it to fit (an error otherwise),
// "external" puts it outside.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

#include "t800/processor_config.hpp"
#include "t800/processors/sequence_timing.hpp"

namespace t800 {

// What the processes on one processor need.
struct MemoryDemand {
  int workspace_bytes = 0;
  int data_bytes = 0;
  struct Code {
    std::string name;  // the PROC's name
    int bytes = 0;     // instructions and constant table
  };
  std::vector<Code> code;  // declaration order, each PROC once
  int library_bytes = 0;   // run-time library routines, each once
};

struct MemoryRegion {
  enum class Kind { reserved, workspace, data, code, library };
  Kind kind = Kind::reserved;
  std::string name;
  int offset = 0;  // bytes from the bottom of memory (#80000000)
  int bytes = 0;
  bool external = false;
};
const char* to_string(MemoryRegion::Kind kind);

class MemoryMap {
 public:
  MemoryMap() = default;  // everything on chip, nothing declared
  MemoryMap(const ProcessorModel& processor, const MemoryConfig& config,
            const MemoryDemand& demand);

  const std::vector<MemoryRegion>& regions() const { return regions_; }
  int on_chip_bytes() const { return on_chip_bytes_; }
  int bytes(MemoryRegion::Kind kind) const;           // declared bytes of a kind
  int external_bytes(MemoryRegion::Kind kind) const;  // of those, in external memory
  int external_cycles() const { return external_cycles_; }

  bool workspace_external() const { return external(MemoryRegion::Kind::workspace); }
  bool data_external() const { return external(MemoryRegion::Kind::data); }
  bool library_external() const { return external(MemoryRegion::Kind::library); }
  bool code_external(const std::string& proc) const;
  // How a PROC of this processor sees memory (code by its name; its arrays with the data).
  MemoryView view(const std::string& proc, int arrays) const;

 private:
  bool external(MemoryRegion::Kind kind) const;
  std::vector<MemoryRegion> regions_;
  int on_chip_bytes_ = 4096;
  int external_cycles_ = 3;
  bool code_default_external_ = false;  // a PROC not declared: where explicit placement puts code
};

// An explicit "onchip" placement that cannot hold what the processor runs.
class PlacementError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The toolset's run-time system's share of on-chip RAM above MemStart (#80000150 - #80000070 on
// a T800), and the external access's cycles with wait states.
int loader_bytes();
int external_access_cycles(const ProcessorModel& processor, int wait_states);

}  // namespace t800
