// One T800: a CPU with its scheduler, the accounting of its time, and four link ports. Processes
// are placed on it by the network layer; its links are wired by the network layer from a topology.
#pragma once

#include <array>
#include <string>

#include <systemc>

#include "t800/activity.hpp"
#include "t800/cpu.hpp"
#include "t800/link.hpp"
#include "t800/processor_config.hpp"

namespace t800 {

class Transputer : public sc_core::sc_module {
 public:
  struct Port {
    Link* link = nullptr;
    int end = 0;  // which end of `link` this transputer is
  };

  Transputer(const sc_core::sc_module_name& name, const ProcessorConfig& config);

  void attach(int link_number, Link& link, int end);
  const Port& port(int link_number) const { return ports_.at(link_number); }
  Cpu& cpu() { return cpu_; }
  ProcessorActivity& activity() { return activity_; }
  const ProcessorActivity& activity() const { return activity_; }
  const ProcessorConfig& config() const { return config_; }

 private:
  ProcessorConfig config_;
  ProcessorActivity activity_;
  Cpu cpu_;
  std::array<Port, 4> ports_;
};

}  // namespace t800
