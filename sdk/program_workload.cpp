#include "sdk/program_workload.hpp"

#include <stdexcept>

#include "network/machine.hpp"
#include "workloads/setting_error.hpp"

namespace t800sim::detail {

ProgramWorkload::ProgramWorkload(std::string kind, std::unique_ptr<Program> program,
                                 const workloads::WorkloadContext& context)
    : kind_(std::move(kind)),
      program_(std::move(program)),
      topology_(context.topology),
      scene_placement_(context.placement ? *context.placement
                                         : std::vector<workloads::PlacementEntry>{}),
      builder_(context.topology) {}

// Nothing runs before every declaration is known good: the program builds, its processes are
// placed, its channels joined and routed, then the processes are spawned.
void ProgramWorkload::build(network::Machine& machine) {
  try {
    program_->build(builder_);
  } catch (const workloads::SettingError& e) {
    throw workloads::SettingError(e.keys(), "workload " + kind_ + ": " + e.what());
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument("workload " + kind_ + ": " + e.what());
  }
  placed_ = place(kind_, builder_, topology_, scene_placement_);
  join_channels(machine);
  for (const Builder::DeclaredCode& c : builder_.declared_code())
    machine.declare_code(placed(c.process, "").node, c.process, c.kernel.work().code);
  for (const PlacedProcess& p : placed_) {
    const auto priority = p.decl->high_priority ? t800::Priority::high : t800::Priority::low;
    const Process::IndexedBody& body = p.decl->body;
    const int index = p.index;
    machine.spawn(p.node, p.name, priority, [&body, index](network::Process& impl) {
      Process process(impl);
      body(process, index);
    });
  }
}

const PlacedProcess& ProgramWorkload::placed(const std::string& process,
                                             const std::string& channel) const {
  for (const PlacedProcess& p : placed_)
    if (p.name == process) return p;
  std::string message = "workload " + kind_ + ": ";
  message += channel.empty() ? "code declared for process " + process
                             : "channel " + channel + " is joined to process " + process;
  for (const ProcessDecl& d : builder_.declared_processes())
    if (d.group && d.name == process)
      throw std::invalid_argument(message + ", a group of " + std::to_string(d.count) +
                                  ": name one member, " + process + "[i]");
  throw std::invalid_argument(message + ", which the program does not declare");
}

// Channel i of an array named after a group of as many processes joins member i.
std::string ProgramWorkload::end_process(const std::string& process,
                                         const ChannelSlot& slot) const {
  if (slot.index < 0) return process;
  for (const ProcessDecl& d : builder_.declared_processes())
    if (d.group && d.name == process) {
      if (d.count != slot.array)
        throw std::invalid_argument("workload " + kind_ + ": channel " + slot.name + " is one of " +
                                    std::to_string(slot.array) + ", joined to process group " +
                                    process + " of " + std::to_string(d.count) +
                                    ": an array is joined to a group of its size");
      return process + "[" + std::to_string(slot.index) + "]";
    }
  return process;
}

void ProgramWorkload::join_channels(network::Machine& machine) {
  for (ChannelSlot& slot : builder_.declared_channels()) {
    if (slot.writer.empty() || slot.reader.empty())
      throw std::invalid_argument("workload " + kind_ + ": channel " + slot.name + " has " +
                                  (slot.writer.empty()
                                       ? "no writer (its reader is " + slot.reader + ")"
                                       : "no reader (its writer is " + slot.writer + ")"));
    const PlacedProcess& from = placed(end_process(slot.writer, slot), slot.name);
    const PlacedProcess& to = placed(end_process(slot.reader, slot), slot.name);
    try {
      slot.impl = &machine.channel(slot.name, from.node, to.node);
    } catch (const std::runtime_error& e) {
      const std::string message =
          "channel " + slot.name + " from " + from.name + " to " + to.name + ": " + e.what();
      if (from.where) throw network::ConfigError(*from.where, "[placement] " + message);
      if (to.where) throw network::ConfigError(*to.where, "[placement] " + message);
      throw std::invalid_argument("workload " + kind_ + ": " + message);
    }
  }
}

workloads::ResultValue ProgramWorkload::results(const network::Machine& machine) const {
  workloads::ResultValue v;
  v.set("kind", kind_);
  tables_.clear();
  Results results(v, machine, tables_);
  program_->results(results);
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
