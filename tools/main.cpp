// t800sim: the command line. libsystemc.so provides main() and calls sc_main().
#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <systemc>

#include "network/unwound_frames.hpp"
#include "tools/cli_errors.hpp"
#include "tools/commands.hpp"

int sc_main(int argc, char* argv[]) {
  CLI::App app{
      "t800sim: a cycle-approximate simulator of INMOS T800 transputer networks.\n"
      "Scenes (configs/scenes/*.toml) name a topology and a workload; see README.md."};
  app.require_subcommand(1);
  tools::add_run_command(app);
  tools::add_check_command(app);
  tools::add_paper_command(app);
  tools::add_dynamics_command(app);
  tools::add_stress_command(app);
  tools::add_sweep_command(app);
  tools::add_merge_command(app);
  tools::add_vcd_command(app);
  tools::add_listing_command(app);
  tools::add_asm_command(app);
  tools::add_boot_command(app);
  tools::add_occam_command(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    network::forget_unwound_frames();
    if (const auto message =
            tools::explain_parse_error(app, std::vector<std::string>(argv + 1, argv + argc), e)) {
      std::cerr << "error: " << *message << "\n";
      return tools::kExitBadInput;
    }
    const int code = app.exit(e);
    return code == 0 ? tools::kExitOk : tools::kExitBadInput;
  } catch (const tools::CommandExit& e) {
    network::forget_unwound_frames();
    return e.code;
  }
  return tools::kExitOk;
}
