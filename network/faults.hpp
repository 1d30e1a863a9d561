// Faults injected into a run (a scene's [[fault]] tables, `--fault`), as the paper's level 3
// anticipates: a link direction that drops or corrupts a byte at time t, a link that goes dead at t
// (both directions), a processor that halts at t. They act in the link protocol and the CPU
// (t800/link.hpp, t800/cpu.hpp); this file says what was asked for and keeps what each did: when it
// took effect, what it hit, which program noticed it and how it recovered.
//
// A run ends cleanly only if every fault that took effect was recovered by the program; otherwise
// it is a reported failure (or a deadlock report that names the fault), never silent output.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "network/config_error.hpp"

namespace network {

class Machine;
class Process;

struct FaultSpec {
  enum class Kind { corrupt, drop, dead_link, halt };
  Kind kind = Kind::drop;
  std::string from, to;   // corrupt, drop: the link direction from -> to; dead_link: its ends
  std::string processor;  // halt
  double at_us = 0;
  int xor_mask = 1;  // corrupt: the byte arrives XORed with this (1..255)
  SourcePos origin;  // where it was given

  std::string where() const;  // "P1->P2", "P1-P2", "P3"
};

const char* to_string(FaultSpec::Kind kind);

// What one fault did in a run.
struct FaultRecord {
  FaultSpec spec;
  bool fired = false;       // it changed something
  double fired_us = -1;     // when it first did
  std::string hit;          // what it first hit
  std::string detected_by;  // which process noticed, and how; empty: nobody
  double detected_us = -1;
  std::string recovered_how;  // empty: not recovered
  double recovered_us = -1;
  std::vector<std::string> stranded;  // processes left waiting for ever because of it
  // Time from its first effect to the program's first recovery from it, us (-1 when not
  // recovered).
  double cost_us() const { return recovered_us >= 0 ? recovered_us - fired_us : -1; }
  std::string describe() const;  // "drop on L1->E2 at 150 us"
};

class FaultLog {
 public:
  void add(FaultSpec spec) {
    FaultRecord r;
    r.spec = std::move(spec);
    records_.push_back(std::move(r));
  }
  const std::vector<FaultRecord>& records() const { return records_; }
  std::vector<FaultRecord>& records() { return records_; }
  bool empty() const { return records_.empty(); }
  // Fault i took effect now (the first call counts).
  void fired(std::size_t i, const std::string& what);
  // A program noticed, at node `at`, that something sent along `path` (node indices) did not
  // arrive or arrived wrong; the faults that fired on that path (a link between two of its nodes,
  // or a halted node on it) are detected by `by`. Returns how many.
  int detected(const Machine& m, const std::vector<int>& path, const std::string& by);
  // The program recovered from what it detected along `path`.
  void recovered(const Machine& m, const std::vector<int>& path, const std::string& how);

 private:
  bool on_path(const Machine& m, const FaultRecord& r, const std::vector<int>& path) const;
  std::vector<FaultRecord> records_;
};

// Arms every fault of the machine's log on its links and processors (before the run). Names were
// checked when the scene was read; an unknown one here is a logic error.
void arm_faults(Machine& m);

// Whether a process left blocked at the end of a run waits because of a fault that took effect (it
// is on a halted processor; it waits on a channel at an end of a faulted link, whose partner gave
// it up; its channel crosses a faulted link or a halted processor; or it waits for PAR branches
// that do), and which fault.
int stranding_fault(const Machine& m, const Process& p);

}  // namespace network
