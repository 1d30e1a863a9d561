// The processor types t800sim models, as data: each type's clock, memory, links and instruction
// timing table (docs/t800-timing.md). A topology names the type of each processor
// ("T800-20", "T805-25", "T414-20", ...); everything that depends on the type reads it from here.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "t800/processors/instruction_timing.hpp"

namespace t800 {

enum class ProcessorType { T800_20, T800_25, T800_30, T805_20, T805_25, T805_30, T414_15, T414_20 };

// T800 and T805 links acknowledge a byte as soon as its packet starts arriving ("overlapped"); the
// T414's only after the whole packet.
enum class LinkProtocol { overlapped, t414 };

struct ProcessorModel {
  ProcessorType type;
  std::string_view name;  // as written in topology and scene files
  double cycle_ns;        // processor cycle
  bool has_fpu;           // T800/T805: REAL arithmetic by the FPU; T414: by software routines
  int on_chip_bytes;      // on-chip RAM
  int reserved_bytes;     // on-chip words below MemStart: link channels, event, timer queues, save
                          // area
  // External memory interface: the shortest external access, in processor cycles; programmed wait
  // states add to it (docs/t800-timing.md, "Memory").
  int external_access_cycles;
  LinkProtocol link_protocol;  // the protocol of its links unless a topology says otherwise
  const InstructionTimingTable* timing;
};

const ProcessorModel& processor_model(ProcessorType type);
std::string_view to_string(ProcessorType type);
std::optional<ProcessorType> parse_processor_type(std::string_view text);
// "T800-20, T800-25, ..." for error messages.
std::string processor_type_names();
std::vector<ProcessorType> all_processor_types();

}  // namespace t800
