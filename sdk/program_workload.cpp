#include "sdk/program_workload.hpp"

#include <stdexcept>

#include "network/config_error.hpp"
#include "network/machine.hpp"
#include "network/unwound_frames.hpp"
#include "sdk/plugin_loader.hpp"
#include "sdk/realise.hpp"
#include "workloads/run/thrown.hpp"
#include "workloads/setting_error.hpp"

namespace t800sim::detail {

namespace {

// What the program's code threw, named after the workload; anything but the errors of settings
// and scene lines becomes `Failure`.
template <class Failure>
[[noreturn]] void throw_named(const std::string& label, const std::string& step,
                              const std::exception_ptr& thrown) {
  try {
    std::rethrow_exception(thrown);
  } catch (const workloads::SettingError& e) {
    throw workloads::SettingError(e.keys(), "workload " + label + ": " + e.what());
  } catch (const network::ConfigError&) {
    throw;
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument("workload " + label + ": " + e.what());
  } catch (...) {
    throw Failure("workload " + label + ": " + step + " threw " +
                  workloads::describe_thrown(thrown));
  }
}

template <class Failure>
void named_after_workload(const std::string& label, const std::string& step,
                          const std::function<void()>& code) {
  try {
    code();
  } catch (...) {
    network::forget_unwound_frames();  // `code` may be results(), after a simulation
    throw_named<Failure>(label, step, std::current_exception());
  }
}

}  // namespace

void run_program_code(const std::string& label, const std::string& step,
                      const std::function<void()>& code) {
  named_after_workload<std::invalid_argument>(label, step, code);
}

ProgramWorkload::ProgramWorkload(std::string kind, std::unique_ptr<Program> program,
                                 const workloads::WorkloadContext& context)
    : kind_(std::move(kind)),
      label_(workload_label(kind_)),
      program_(std::move(program)),
      topology_(context.topology),
      scene_placement_(context.placement ? *context.placement
                                         : std::vector<workloads::PlacementEntry>{}),
      builder_(context.topology) {}

void ProgramWorkload::build(network::Machine& machine) {
  builder_.attach(machine);
  run_program_code(label_, "its build()", [this] { program_->build(builder_); });
  placed_ = realise(label_, builder_, machine, scene_placement_);
  run_program_code(label_, "its booted processors", [&] {
    booted_.emplace(label_, builder_, topology_);
    booted_->join(machine, placed_);
    booted_->spawn(machine);
  });
}

workloads::ResultValue ProgramWorkload::results(const network::Machine& machine) const {
  workloads::ResultValue v;
  v.set("kind", kind_);
  tables_.clear();
  Results results(v, machine, tables_);
  // After the run: what else results() throws is a failed run, not bad input.
  named_after_workload<std::runtime_error>(label_, "its results()",
                                           [&] { program_->results(results); });
  check_tables();
  workloads::ResultValue placement = workloads::ResultValue::list();
  for (const PlacedProcess& p : placed_) {
    workloads::ResultValue r;
    r.set("process", p.name);
    r.set("processor", machine.node_name(p.node));
    r.set("placed_by", p.placed_by);
    placement.push(r);
  }
  v.set("placement", placement);
  if (booted_ && !booted_->empty()) v.set("booted", booted_->results());
  return v;
}

// A table is written where one of the kind's output_file parameters says: any other name would be
// a table nobody could ask for.
void ProgramWorkload::check_tables() const {
  const workloads::WorkloadInfo* info = workloads::find_workload(kind_);
  for (const workloads::OutputTable& t : tables_) {
    const workloads::ParamSpec* spec = info ? info->find(t.param) : nullptr;
    if (!spec || spec->type != workloads::ParamType::output_file)
      throw std::logic_error("workload " + kind_ + " reported a table for '" + t.param +
                             "', which is not one of its output_file parameters "
                             "(declare it with t800sim::output_file_param)");
  }
}

}  // namespace t800sim::detail
