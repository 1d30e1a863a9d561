// `t800sim vcd TRACE.csv -o TRACE.vcd`: a CSV trace as VCD, through SystemC's sc_trace
// (trace_vcd.hpp). `t800sim run --trace-vcd` uses it in a child process; it is also handy on its
// own.
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>

#include "tools/commands.hpp"
#include "tools/trace_format.hpp"
#include "tools/trace_vcd.hpp"
#include "workloads/run/output_file.hpp"

namespace tools {

namespace {
struct VcdArgs {
  std::string csv, output;
};

// SystemC writes the VCD itself and reports neither an unwritable file (only a warning) nor a write
// error; so it writes a temporary file, which then replaces the output whole through
// workloads::OutputFile, which does report them.
int convert(const VcdArgs& a) {
  const std::vector<TraceRow> rows = read_trace_csv(a.csv);
  workloads::check_output_path(a.output, "-o");
  const workloads::ScratchFile temporary(
      (std::filesystem::temp_directory_path() / ("t800sim-" + std::to_string(getpid()) + ".vcd"))
          .string());
  write_vcd(rows, temporary.path());
  std::ifstream in(temporary.path(), std::ios::binary);
  const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  in.close();
  workloads::write_output_file(a.output, text, "-o");
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
