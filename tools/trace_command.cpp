// `t800sim vcd TRACE.csv -o TRACE.vcd`: a CSV trace as VCD, through SystemC's sc_trace
// (trace_vcd.hpp). `t800sim run --trace-vcd` uses it in a child process; it is also handy on its
// own.
#include <fstream>
#include <iostream>

#include "tools/commands.hpp"
#include "tools/trace_format.hpp"
#include "tools/trace_vcd.hpp"

namespace tools {

namespace {
struct VcdArgs {
  std::string csv, output;
};

int convert(const VcdArgs& a) {
  const std::vector<TraceRow> rows = read_trace_csv(a.csv);
  // SystemC reports an unwritable trace file only as a warning; find out first.
  if (!std::ofstream(a.output, std::ios::app))
    throw std::invalid_argument("-o " + a.output + ": cannot write it");
  write_vcd(rows, a.output);
  return kExitOk;
}
}  // namespace

void add_vcd_command(CLI::App& app) {
  auto a = std::make_shared<VcdArgs>();
  auto* cmd = app.add_subcommand("vcd", "Convert a CSV trace (run --trace-csv) to VCD for GTKWave");
  cmd->add_option("trace", a->csv, "CSV trace file")->required();
  cmd->add_option("-o,--output", a->output, "the VCD file to write")->required();
  cmd->callback([a] { run_command([&] { return convert(*a); }); });
}

}  // namespace tools
