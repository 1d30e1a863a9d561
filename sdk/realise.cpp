#include "sdk/realise.hpp"

#include <stdexcept>
#include <unordered_map>

#include <fmt/format.h>
#include <systemc>

#include "network/machine.hpp"
#include "workloads/run/process_error.hpp"
#include "workloads/run/thrown.hpp"

namespace t800sim::detail {

namespace {

// Whatever the body lets out is recorded with the process's own name before SystemC sees it
// (workloads/run/process_error.hpp); SystemC's own unwinding of a thread it kills passes through.
void run_body(const std::string& kind, const Process::Body& body, Process& process) {
  try {
    body(process);
  } catch (const sc_core::sc_unwind_exception&) {
    throw;
  } catch (...) {
    const workloads::ProcessError error(
        fmt::format("workload {}: process {} on {} threw {} (at {} us of simulated time)", kind,
                    process.name(), process.processor(),
                    workloads::describe_thrown(std::current_exception()), process.now_us()));
    workloads::record_process_error(error);
    throw error;
  }
}

class Realisation {
 public:
  Realisation(const std::string& kind, Builder& builder, std::vector<PlacedProcess> placed)
      : kind_(kind), builder_(builder), placed_(std::move(placed)) {
    for (std::size_t i = 0; i < placed_.size(); ++i) index_.emplace(placed_[i].name, i);
  }

  void join_channels(network::Machine& machine) {
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

  void declare_code(network::Machine& machine) const {
    for (const Builder::DeclaredCode& c : builder_.declared_code())
      machine.declare_code(placed(c.process, "").node, c.process, c.kernel.work().code);
  }

  void spawn(network::Machine& machine) const {
    for (const PlacedProcess& p : placed_) {
      if (!p.decl->body) continue;
      const std::vector<bool>& runs = p.decl->runs;
      if (std::size_t(p.index) < runs.size() && !runs[std::size_t(p.index)]) continue;
      const Process::IndexedBody& body = p.decl->body;
      const int index = p.index;
      detail::spawn(
          kind_, machine, p.node, p.name,
          [&body, index](Process& process) { body(process, index); }, p.decl->high_priority);
    }
  }

  std::vector<PlacedProcess> placed() && { return std::move(placed_); }

 private:
  const PlacedProcess& placed(const std::string& process, const std::string& channel) const {
    if (const auto at = index_.find(process); at != index_.end()) return placed_[at->second];
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
  std::string end_process(const std::string& process, const ChannelSlot& slot) const {
    if (slot.index < 0) return process;
    for (const ProcessDecl& d : builder_.declared_processes())
      if (d.group && d.name == process) {
        if (d.count != slot.array)
          throw std::invalid_argument(
              "workload " + kind_ + ": channel " + slot.name + " is one of " +
              std::to_string(slot.array) + ", joined to process group " + process + " of " +
              std::to_string(d.count) + ": an array is joined to a group of its size");
        return process + "[" + std::to_string(slot.index) + "]";
      }
    return process;
  }

  const std::string& kind_;
  Builder& builder_;
  std::vector<PlacedProcess> placed_;
  std::unordered_map<std::string, std::size_t> index_;  // placed_ by process name (the first)
};

}  // namespace

void spawn(const std::string& kind, network::Machine& machine, int node, const std::string& name,
           const Process::Body& body, bool high_priority) {
  machine.spawn(node, name, high_priority ? t800::Priority::high : t800::Priority::low,
                [kind, body](network::Process& impl) {
                  Process process(impl);
                  run_body(kind, body, process);
                });
}

// Nothing runs before every declaration is known good: the processes are placed, the channels
// joined and routed, then the processes spawned.
std::vector<PlacedProcess> realise(const std::string& kind, Builder& builder,
                                   network::Machine& machine,
                                   const std::vector<workloads::PlacementEntry>& scene) {
  Realisation r(kind, builder, place(kind, builder, machine.topology(), scene));
  r.join_channels(machine);
  r.declare_code(machine);
  r.spawn(machine);
  return std::move(r).placed();
}

}  // namespace t800sim::detail
