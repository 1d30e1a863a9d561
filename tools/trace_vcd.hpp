// VCD traces through SystemC's own sc_trace, so GTKWave (or any VCD viewer) opens them.
//
// Why a replay: a link direction's busy interval is only known when its packet ends (the link model
// reports packets after they are sent), but sc_trace samples variables at the present simulated
// time. So the run records intervals, and a second, tiny simulation (in its own process: `t800sim
// vcd`, SystemC runs once per process) sets traced variables at the recorded times.
#pragma once

#include <string>
#include <vector>

#include "tools/trace_format.hpp"

namespace tools {

// One signal per processor ("processors.P0": 2 bits, 0 idle, 1 compute, 2 communicate) and per busy
// link direction ("links.P0_to_P1_...": 1 bit). Runs a SystemC simulation: once per process.
void write_vcd(const std::vector<TraceRow>& rows, const std::string& path);

// A track name as a VCD identifier: "P0->P1 (P0.link1-P1.link0)" -> "P0_to_P1_P0_link1_P1_link0".
std::string vcd_name(const std::string& name);

}  // namespace tools
