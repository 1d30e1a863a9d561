// `t800sim listing SCENE`: the T800 code each processor of a scene runs, compiled from the
// workload's recorded kernels, with its footprint and timing; --kernel NAME prints one PROC's
// listing instruction by instruction.
#include <iostream>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "tools/commands.hpp"
#include "tools/listing_format.hpp"
#include "tools/run_inputs.hpp"
#include "tools/scene.hpp"
#include "workloads/run/run.hpp"
#include "workloads/run/workload.hpp"

namespace tools {

namespace {

struct ListingArgs {
  std::string scene;
  std::vector<std::string> overrides;
  std::string kernel;
  std::string processor;
};

std::string kernel_table(const network::Machine& machine) {
  std::string out =
      fmt::format("{:<10} {:<10} {:<20} {:>7} {:>7} {:>6} {:>9} {:>10}  {}\n", "processor",
                  "process", "kernel", "code_B", "const_B", "ws_w", "cycles", "us", "code in");
  for (const network::Machine::DeclaredCode& d : machine.declared_code()) {
    const t800::ComputeModel& model = machine.compute_model(d.node);
    const t800::codegen::CodeUnit& unit = model.code(d.kernel);
    const auto cycles = model.time(unit).cycles;
    out += fmt::format("{:<10} {:<10} {:<20} {:>7} {:>7} {:>6} {:>9} {:>10.2f}  {}\n",
                       machine.node_name(d.node), d.process, unit.name, unit.code_bytes,
                       unit.constant_bytes, unit.workspace_words, cycles,
                       cycles * model.cycle_ns() / 1000.0,
                       model.memory().code_external(unit.name) ? "external" : "on-chip");
  }
  return out;
}

int list(const ListingArgs& args) {
  const Scene scene = load_scene(args.scene, args.overrides);
  const workloads::RunInputs inputs = inputs_from(scene);
  const workloads::Realised realised = workloads::realise(inputs);
  const network::Machine& machine = *realised.machine;
  if (machine.declared_code().empty())
    throw std::invalid_argument("scene " + scene.name + ": its workload (" + scene.workload_kind +
                                ") declares no recorded kernels, so there is no code to list");
  if (args.kernel.empty()) {
    std::cout << kernel_table(machine) << "\n(t800sim listing " << args.scene
              << " --kernel NAME prints one of them)\n";
    return kExitOk;
  }
  std::vector<std::string> names;
  for (const network::Machine::DeclaredCode& d : machine.declared_code()) {
    const t800::ComputeModel& model = machine.compute_model(d.node);
    const t800::codegen::CodeUnit& unit = model.annotated_code(d.kernel);
    names.push_back(unit.name);
    if (unit.name != args.kernel) continue;
    if (!args.processor.empty() && machine.node_name(d.node) != args.processor) continue;
    std::cout << format_listing(unit, model);
    return kExitOk;
  }
  throw std::invalid_argument(
      "--kernel " + args.kernel + (args.processor.empty() ? "" : " --processor " + args.processor) +
      ": no such kernel in scene " + scene.name + "; run without --kernel for the list");
}

}  // namespace

void add_listing_command(CLI::App& app) {
  auto args = std::make_shared<ListingArgs>();
  auto* cmd = app.add_subcommand(
      "listing", "Print the T800 code a scene's processors run: every kernel, or one (--kernel)");
  cmd->add_option("scene", args->scene, "scene TOML file (configs/scenes/*.toml)")->required();
  cmd->add_option("--set", args->overrides, "override a scene key, as for run")
      ->type_name("KEY=VALUE");
  cmd->add_option("--kernel", args->kernel, "print this kernel's listing (e.g. D11, LOOP7)");
  cmd->add_option("--processor", args->processor,
                  "the processor whose copy to print (default: the first that runs it)");
  cmd->callback([args] { run_command([&] { return list(*args); }); });
}

}  // namespace tools
