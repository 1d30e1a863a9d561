#include "t800/transputer.hpp"

#include "t800/timing_table.hpp"

namespace t800 {

Transputer::Transputer(const sc_core::sc_module_name& name, const ProcessorConfig& config)
    : sc_module(name),
      config_(config),
      cpu_(cycle_ns(config.type), activity_, timing::kInterruptLatencyTypical) {}

void Transputer::attach(int link_number, Link& link, int end) {
  ports_.at(link_number) = {&link, end};
  cpu_.attach_dma(link, end);
}

}  // namespace t800
