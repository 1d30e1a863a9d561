#include <stdexcept>

#include "sdk/plugin_loader.hpp"
#include "sdk/program_workload.hpp"
#include "t800sim/workload.hpp"
#include "workloads/registry.hpp"

namespace t800sim {

void register_workload(WorkloadSpec spec) {
  try {
    if (!spec.make) throw std::invalid_argument("workload kind " + spec.kind + " has no factory");
    auto make = std::move(spec.make);
    const std::string kind = spec.kind;
    workloads::register_kind(
        {spec.kind, spec.summary, std::move(spec.params)},
        [make, kind](const workloads::WorkloadContext& context) {
          const Network network(context.topology);
          std::unique_ptr<Program> program;
          detail::run_program_code(detail::workload_label(kind), "its factory",
                                   [&] { program = make(context.params, network); });
          return std::make_unique<detail::ProgramWorkload>(kind, std::move(program), context);
        });
    detail::note_plugin_kind(kind);
  } catch (const std::invalid_argument& e) {
    if (!detail::note_plugin_registration_error(e.what())) throw;
  }
}

Param integer_param(std::string name, std::int64_t fallback, std::string help, double min,
                    double max) {
  return {std::move(name), workloads::ParamType::integer, fallback, std::move(help), min, max, {}};
}

Param real_param(std::string name, double fallback, std::string help, double min, double max) {
  return {std::move(name), workloads::ParamType::real, fallback, std::move(help), min, max, {}};
}

Param flag_param(std::string name, bool fallback, std::string help) {
  return {std::move(name), workloads::ParamType::flag, fallback, std::move(help), {}, {}, {}};
}

Param text_param(std::string name, std::string fallback, std::string help,
                 std::vector<std::string> choices) {
  return {
      std::move(name),   workloads::ParamType::text, std::move(fallback), std::move(help), {}, {},
      std::move(choices)};
}

Param real_list_param(std::string name, std::vector<double> fallback, std::string help) {
  return {std::move(name),
          workloads::ParamType::real_list,
          std::move(fallback),
          std::move(help),
          {},
          {},
          {}};
}

Param processor_param(std::string name, std::string help) {
  return {
      std::move(name), workloads::ParamType::processor, std::string{}, std::move(help), {}, {}, {}};
}

Param precision_param(std::string name, std::string fallback, std::string help) {
  return {std::move(name),
          workloads::ParamType::precision,
          std::move(fallback),
          std::move(help),
          {},
          {},
          {}};
}

Param input_file_param(std::string name, std::string help) {
  return {std::move(name),
          workloads::ParamType::input_file,
          std::string{},
          std::move(help),
          {},
          {},
          {}};
}

Param output_file_param(std::string name, std::string help) {
  return {std::move(name),
          workloads::ParamType::output_file,
          std::string{},
          std::move(help),
          {},
          {},
          {}};
}

}  // namespace t800sim
