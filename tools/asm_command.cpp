// `t800sim asm SOURCE -o FILE`: T800 assembler text (t800/asm/assembler.hpp) to a bootable file
// that `t800sim boot` (or a real board's iserver) sends down the host link.
#include <iostream>
#include <sstream>

#include <fmt/format.h>

#include "network/input_file.hpp"
#include "t800/asm/assembler.hpp"
#include "t800/asm/boot_file.hpp"
#include "t800/processors/processor_model.hpp"
#include "tools/commands.hpp"
#include "workloads/run/output_file.hpp"

namespace tools {

namespace {

struct AsmArgs {
  std::string source, output, listing;
  std::string boot = "auto";
  std::string processor = "T800-20";
};

// Assembly sources are text a person writes; the bound keeps a mistaken path from being read whole.
constexpr std::size_t kMaxSourceBytes = std::size_t(64) << 20;

std::string read_source(const std::string& path) {
  try {
    return network::read_input_file(path, kMaxSourceBytes);
  } catch (const network::InputFileError& e) {
    throw std::invalid_argument(path + ": " + e.what() + " (an assembly source file)");
  }
}

// An error in the source is bad input ("file:line:column: ..."), like a scene's.
t800::assembly::Program assemble_at(const std::string& text, std::uint32_t origin,
                                    const std::string& name) {
  try {
    return t800::assembly::assemble(text, {origin, name});
  } catch (const t800::assembly::AssemblyError& e) {
    throw std::invalid_argument(e.what());
  }
}

int assemble_file(const AsmArgs& args) {
  const auto type = t800::parse_processor_type(args.processor);
  if (!type)
    throw std::invalid_argument("--processor " + args.processor +
                                ": not a processor type; give one of " +
                                t800::processor_type_names());
  const std::uint32_t mem_start =
      0x80000000u + std::uint32_t(t800::processor_model(*type).reserved_bytes);
  const std::string text = read_source(args.source);
  // The layout decides the origin: a first stage runs at MemStart, a two-stage program after the
  // primary loader. Assemble for MemStart first; a program too long for one stage is assembled
  // again for its two-stage address.
  std::string boot = args.boot;
  auto program = assemble_at(text, mem_start, args.source);
  if (boot == "auto") boot = program.bytes.size() <= 255 ? "single" : "two-stage";
  if (boot == "two-stage")
    program = assemble_at(text, t800::assembly::program_address(mem_start), args.source);
  std::vector<std::uint8_t> bytes;
  try {
    bytes = boot == "single"      ? t800::assembly::single_stage(program.bytes)
            : boot == "two-stage" ? t800::assembly::two_stage(program.bytes)
                                  : program.bytes;
  } catch (const t800::assembly::BootFileError& e) {
    throw std::invalid_argument(fmt::format("--boot {}: {}", boot, e.what()));
  }
  workloads::write_output_file(args.output, std::string(bytes.begin(), bytes.end()), "-o");
  if (!args.listing.empty())
    workloads::write_output_file(args.listing, program.listing_text(), "--listing");
  std::cerr << fmt::format("{}: {} bytes of code at #{:08X}, {} bytes written ({} boot)\n",
                           args.source, program.bytes.size(), program.origin, bytes.size(), boot);
  return kExitOk;
}

}  // namespace

void add_asm_command(CLI::App& app) {
  auto args = std::make_shared<AsmArgs>();
  auto* cmd = app.add_subcommand(
      "asm", "Assemble T800 assembler text into a bootable file for `t800sim boot` (docs/iss.md)");
  cmd->add_option("source", args->source, "assembler text (syntax: docs/iss.md)")->required();
  cmd->add_option("-o", args->output, "the bootable file to write")->required()->type_name("FILE");
  cmd->add_option("--boot", args->boot,
                  "auto (single stage up to 255 bytes, else two stages), single, two-stage, or "
                  "raw (the code alone, no boot protocol)")
      ->check(CLI::IsMember({"auto", "single", "two-stage", "raw"}));
  cmd->add_option("--processor", args->processor, "the processor type (sets MemStart)")
      ->type_name("TYPE");
  cmd->add_option("--listing", args->listing, "write the listing (address, bytes, source) here")
      ->type_name("FILE");
  cmd->callback([args] { run_command([&] { return assemble_file(*args); }); });
}

}  // namespace tools
