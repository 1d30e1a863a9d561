#include <stdexcept>

#include <fmt/format.h>

#include "network/limits.hpp"
#include "network/machine.hpp"
#include "network/topology.hpp"
#include "t800sim/program.hpp"
#include "workloads/run/output_table.hpp"

namespace t800sim {

int Network::processors() const {
  return int(topology_.processors.size());
}

const std::string& Network::processor_name(int index) const {
  return topology_.processors.at(std::size_t(index)).name;
}

int Network::find(const std::string& name) const {
  return topology_.find(name);
}

std::vector<int> Network::neighbours(int index) const {
  return topology_.neighbours(index);
}

int Network::host_processor() const {
  return std::max(topology_.host_processor(), 0);
}

ProcessDecl& Builder::process(const std::string& name, Process::Body body) {
  if (!body) return add(name, 1, false, nullptr);  // spawned by its caller (sdk/realise.hpp)
  return add(name, 1, false, [body](Process& p, int) { body(p); });
}

ProcessDecl& Builder::processes(const std::string& name, int n, Process::IndexedBody body) {
  return add(name, n, true, std::move(body));
}

ProcessDecl& Builder::add(const std::string& name, int n, bool group, Process::IndexedBody body) {
  if (name.empty() || name.find_first_of("[]. ") != std::string::npos)
    throw std::invalid_argument("process name \"" + name +
                                "\": a process needs a name without spaces, dots or brackets");
  if (n < 1)
    throw std::invalid_argument("process group " + name + ": needs at least one process, not " +
                                std::to_string(n));
  if (process_index_.count(name))
    throw std::invalid_argument("process " + name + " is declared twice");
  if (n > network::kMaxProcesses - process_count_)
    throw std::invalid_argument(fmt::format(
        "process {}{}: the program would have {} processes, more than the {} one simulation "
        "holds (each is a SystemC thread with its own stack; network/limits.hpp)",
        name, group ? fmt::format(" (a group of {})", n) : "", process_count_ + n,
        network::kMaxProcesses));
  ProcessDecl d;
  d.name = name;
  d.count = n;
  d.group = group;
  d.body = std::move(body);
  processes_.push_back(std::move(d));
  process_index_.emplace(name, &processes_.back());
  process_count_ += n;
  return processes_.back();
}

detail::ChannelSlot* Builder::declare(const std::string& name, const std::string& protocol,
                                      const std::string& from, const std::string& to) {
  end(name, protocol, from, true);
  return end(name, protocol, to, false);
}

detail::ChannelSlot* Builder::end(const std::string& name, const std::string& protocol,
                                  const std::string& process, bool writer) {
  if (name.empty()) throw std::invalid_argument("a channel needs a name");
  detail::ChannelSlot*& slot = channel_index_[name];
  if (!slot) {
    if (std::int64_t(channels_.size()) >= network::kMaxChannels) {
      channel_index_.erase(name);
      throw std::invalid_argument(fmt::format(
          "channel {}: the program would have more than the {} channels one simulation holds "
          "(network/limits.hpp)",
          name, network::kMaxChannels));
    }
    channels_.push_back({name, protocol, {}, {}, -1, 0, nullptr});
    slot = &channels_.back();
  }
  std::string& owner = writer ? slot->writer : slot->reader;
  const char* role = writer ? "outputs to" : "inputs from";
  if (!owner.empty() && owner != process)
    throw std::invalid_argument("channel " + name + ": both " + owner + " and " + process + " " +
                                role + " it; an occam channel has one writer and one reader");
  if (slot->protocol != protocol) {
    const std::string& other = writer ? slot->reader : slot->writer;
    throw std::invalid_argument("channel " + name + ": protocol mismatch -- " + process + " " +
                                role + " it as " + protocol + ", " + other +
                                (writer ? " inputs from" : " outputs to") + " it as " +
                                slot->protocol);
  }
  owner = process;
  return slot;
}

void Builder::code(const std::string& process, const Kernel& kernel) {
  code_.push_back({process, kernel});
}

void Builder::booted(const std::string& processor) {
  booted_.push_back(processor);  // checked against the network when the program is realised
}

ByteLink Builder::byte_link(const std::string& name, const std::string& process,
                            const std::string& booted_processor) {
  auto slot = std::make_shared<detail::ByteLinkSlot>();
  slot->name = name;
  slot->process = process;
  slot->processor = booted_processor;
  byte_links_.push_back(slot);
  return ByteLink(std::move(slot));
}

Results& Results::table(const std::string& param, std::vector<std::string> columns,
                        std::vector<std::vector<double>> rows) {
  for (const auto& row : rows)
    if (row.size() != columns.size())
      throw std::logic_error("table for workload." + param + ": a row of " +
                             std::to_string(row.size()) + " numbers under " +
                             std::to_string(columns.size()) + " columns");
  tables_.push_back({param, std::move(columns), std::move(rows), nullptr});
  return *this;
}

double Results::cycle_ns(const std::string& processor) const {
  const int node = machine_.topology().find(processor);
  if (node < 0) throw std::invalid_argument("results: no processor named " + processor);
  return machine_.compute_model(node).cycle_ns();
}

std::string Results::processor_type(const std::string& processor) const {
  const int node = machine_.topology().find(processor);
  if (node < 0) throw std::invalid_argument("results: no processor named " + processor);
  return std::string(machine_.compute_model(node).processor().name);
}

double Results::simulated_us() const {
  return machine_.simulated_us();
}

}  // namespace t800sim
