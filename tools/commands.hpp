// The t800sim sub-commands. Each registers itself on the application; main.cpp only assembles them.
#pragma once

#include <exception>
#include <functional>
#include <string>

#include <CLI/CLI.hpp>

namespace tools {

void add_run_command(CLI::App& app);
void add_check_command(CLI::App& app);
void add_paper_command(CLI::App& app);  // also `calibrate`
void add_dynamics_command(CLI::App& app);
void add_stress_command(CLI::App& app);  // numerical stability of elimination and integration
void add_sweep_command(CLI::App& app);
void add_merge_command(CLI::App& app);
void add_vcd_command(CLI::App& app);      // trace CSV -> VCD, through SystemC's sc_trace
void add_listing_command(CLI::App& app);  // generated T800 code of a scene's kernels
void add_asm_command(CLI::App& app);      // assembler text to a bootable file
void add_boot_command(CLI::App& app);     // a bootable file run on the instruction-set simulator
void add_occam_command(CLI::App& app);    // occam built by an INMOS toolset running on the ISS

// Exit codes shared by the commands.
constexpr int kExitOk = 0;
constexpr int kExitFailure =
    1;  // the simulated program did not finish (deadlock) or a check failed
constexpr int kExitBadInput = 2;   // a configuration or command-line error
constexpr int kExitBadResult = 3;  // the run ended but its results are not results (a failed solve,
                                   // a NaN or infinity: workloads::RunReport::failure)
constexpr int kExitLimit = 4;      // --max-sim-time or --max-wall-time stopped the run
constexpr int kExitHostProtocol = 5;  // t800sim boot: the program's host-link bytes were not SP

// Thrown by run_command with the exit code; main() catches it and returns the code, so that every
// object (the CLI::App, the simulation) is destroyed on the way out, as std::exit would not.
struct CommandExit {
  int code;
};

// Runs a command's body and ends the command with the code it returns (throws CommandExit). Errors
// become one message on stderr: a configuration error (file:line:column), a bad argument or an
// unusable path exits kExitBadInput; any other failure exits kExitFailure. The one place commands
// turn exceptions into exit codes.
[[noreturn]] void run_command(const std::function<int()>& body);

// What run_command does with an exception thrown by a command's body: its exit code and message.
struct CommandError {
  int code;
  std::string message;
};
CommandError command_error(const std::exception_ptr& thrown);

}  // namespace tools
