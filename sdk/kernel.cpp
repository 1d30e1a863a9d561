#include "t800sim/kernel.hpp"

#include "workloads/run/operation_mix.hpp"

namespace t800sim {

Kernel::Kernel(std::shared_ptr<const t800::codegen::Recording> code,
               const dynamics::OpCounts& counts, long loop_iterations) {
  work_.mix = workloads::to_operation_mix(counts);
  work_.mix.loop_ends += loop_iterations;
  work_.code = std::move(code);
}

const std::string& Kernel::name() const {
  return work_.code->name();
}

}  // namespace t800sim
