// Code compiled from recorded kernels, shared by the processors of one machine: what generate()
// makes depends only on the kernel and the target, so a kernel is compiled once per target however
// many processors run it (issue 14: a farm's master, which prices every subtask to allocate them,
// and its workers compiled the same subtasks again, 123 compilations for 66 kernels at 9 workers).
// Timing stays with each ComputeModel: it depends on the processor and its memory map.
#pragma once

#include <map>
#include <memory>
#include <tuple>

#include "t800/codegen/code_unit.hpp"
#include "t800/codegen/generator.hpp"

namespace t800 {

class CodeCache {
 public:
  // The code of `kernel` for `target`, compiled on first use; stays valid while the cache lives.
  const codegen::CodeUnit& unit(const std::shared_ptr<const codegen::Recording>& kernel,
                                const codegen::Target& target);

 private:
  struct Compiled {
    std::shared_ptr<const codegen::Recording> kernel;  // kept alive: the cache is keyed by it
    codegen::CodeUnit unit;
  };
  std::map<std::tuple<const codegen::Recording*, bool, bool, bool>, Compiled> units_;
};

}  // namespace t800
