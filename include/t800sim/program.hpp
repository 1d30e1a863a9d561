// A program for a network of transputers, as occam's configuration would describe it: named
// processes, the channels between them with their protocols, and where each process runs. The
// simulator places the processes (the scene's [placement] table first, then the program's own
// choice, then the stated default: the processor wired to the host), routes the channels, and
// reports where everything ran.
//
//   class Hello : public t800sim::Program {
//     void build(t800sim::Builder& b) override {
//       auto c = b.channel<INT>("c", "sender", "receiver");
//       b.process("sender", [c](Process& p) { p.out(c, 42); });
//       b.process("receiver", [c, this](Process& p) { got_ = p.in(c); });
//     }
//     void results(t800sim::Results& r) const override { r.set("got", got_); }
//     INT got_ = 0;
//   };
#pragma once

#include <cstdint>
#include <deque>
#include <functional>
#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

#include "t800sim/byte_link.hpp"
#include "t800sim/channel.hpp"
#include "t800sim/kernel.hpp"
#include "t800sim/process.hpp"
#include "workloads/run/result_value.hpp"

namespace network {
struct Topology;
class Machine;
}  // namespace network
namespace workloads {
struct OutputTable;
}

namespace t800sim {

// What a program may know of the network it runs on.
class Network {
 public:
  explicit Network(const network::Topology& topology) : topology_(topology) {}
  int processors() const;
  const std::string& processor_name(int index) const;
  int find(const std::string& name) const;  // index, or -1
  std::vector<int> neighbours(int index) const;
  int host_processor() const;  // the processor wired to the host, or 0 when none is

 private:
  const network::Topology& topology_;
};

// A process (or a replicated group of them) as declared: its body, priority and the program's own
// placement, which a scene's [placement] overrides.
struct ProcessDecl {
  std::string name;  // "worker" for a group
  int count = 1;     // > 1: a group "worker[0]" ... "worker[n-1]"
  bool group = false;
  Process::IndexedBody body;
  bool high_priority = false;
  std::vector<std::string> on;  // the program's placement: one processor, or one per member

  ProcessDecl& placed_on(std::string processor) {
    on = {std::move(processor)};
    return *this;
  }
  ProcessDecl& placed_on(std::vector<std::string> processors) {
    on = std::move(processors);
    return *this;
  }
  // A process the simulator's caller spawns on the host (declared without a body: a built-in
  // workload's client, fed from the host as a B004's program is): its channels end at the host's
  // link. A scene's [placement] entry for it still wins.
  bool on_host = false;
  ProcessDecl& placed_on_host() {
    on_host = true;
    return *this;
  }
  ProcessDecl& high() {
    high_priority = true;
    return *this;
  }
  // A group member i with runs[i] false is declared (channels may name it, the scene may place it)
  // but not run: a replicated PAR over the members that have work. Empty: every member runs.
  std::vector<bool> runs;
  ProcessDecl& running(std::vector<bool> members) {
    runs = std::move(members);
    return *this;
  }
};

class Builder {
 public:
  explicit Builder(const network::Topology& topology) : network_(topology) {}
  const Network& network() const { return network_; }

  ProcessDecl& process(const std::string& name, Process::Body body);
  // A replicated group: name[0] ... name[n-1], each running body(p, i).
  ProcessDecl& processes(const std::string& name, int n, Process::IndexedBody body);

  // A channel from one process to another (names as declared; "worker[2]" for a group member).
  template <class P>
  Chan<P> channel(const std::string& name, const std::string& from, const std::string& to) {
    return Chan<P>(declare(name, protocol<P>::name(), from, to));
  }
  // [n]CHAN: channel i from `from` to `to`, where a group of n names its member i.
  template <class P>
  Chans<P> channels(const std::string& name, int n, const std::string& from,
                    const std::string& to) {
    Chans<P> cs;
    for (int i = 0; i < n; ++i) {
      cs.emplace_back(declare(name + "[" + std::to_string(i) + "]", protocol<P>::name(), from, to));
      cs.back().slot()->index = i;
      cs.back().slot()->array = n;
    }
    return cs;
  }
  // One end of a channel, declared by the process that uses it; the two ends of a name are joined
  // when the program is placed, and must agree on the protocol.
  template <class P>
  Out<P> output(const std::string& channel, const std::string& process) {
    return Out<P>(end(channel, protocol<P>::name(), process, true));
  }
  template <class P>
  In<P> input(const std::string& channel, const std::string& process) {
    return In<P>(end(channel, protocol<P>::name(), process, false));
  }

  // A kernel the process runs: its code and data count in the processor's memory (what fits in the
  // 4 KB on chip is placed there).
  void code(const std::string& process, const Kernel& kernel);

  // A processor that runs real machine code instead of this program's processes (docs/iss.md,
  // "Mixed networks"): at reset it waits on its links, as the chip does, to be booted through one
  // of them -- by a process of this program over a byte_link, or by a booted neighbour.
  void booted(const std::string& processor);
  // The link between `process` and its neighbour `booted_processor`, carrying raw bytes
  // (t800sim/byte_link.hpp). The two must be placed on neighbours, and no channel may use the link.
  ByteLink byte_link(const std::string& name, const std::string& process,
                     const std::string& booted_processor);

  // ---- For the simulator ----
  // The machine the program will run on, for the SDK's skeletons, which plan with its timing
  // (t800sim/farm.hpp); nullptr until the simulator attaches it.
  void attach(const network::Machine& machine) { machine_ = &machine; }
  const network::Machine* machine() const { return machine_; }
  const std::deque<ProcessDecl>& declared_processes() const { return processes_; }
  const std::deque<detail::ChannelSlot>& declared_channels() const { return channels_; }
  std::deque<detail::ChannelSlot>& declared_channels() { return channels_; }
  struct DeclaredCode {
    std::string process;
    Kernel kernel;
  };
  const std::vector<DeclaredCode>& declared_code() const { return code_; }
  const std::vector<std::string>& declared_booted() const { return booted_; }
  const std::vector<std::shared_ptr<detail::ByteLinkSlot>>& declared_byte_links() const {
    return byte_links_;
  }

 private:
  ProcessDecl& add(const std::string& name, int n, bool group, Process::IndexedBody body);
  detail::ChannelSlot* declare(const std::string& name, const std::string& protocol,
                               const std::string& from, const std::string& to);
  detail::ChannelSlot* end(const std::string& name, const std::string& protocol,
                           const std::string& process, bool writer);

  Network network_;
  std::deque<ProcessDecl> processes_;  // stable addresses: declarations are returned
  std::unordered_map<std::string, const ProcessDecl*> process_index_;  // by name, as channels
  std::int64_t process_count_ = 0;            // a group's members each counted (network/limits.hpp)
  std::deque<detail::ChannelSlot> channels_;  // stable addresses: handles point into it
  // By name: a program of thousands of channels declares each end in constant time.
  std::unordered_map<std::string, detail::ChannelSlot*> channel_index_;
  std::vector<DeclaredCode> code_;
  std::vector<std::string> booted_;
  std::vector<std::shared_ptr<detail::ByteLinkSlot>> byte_links_;
  const network::Machine* machine_ = nullptr;
};

// A value of a report: a number, text, a list (ResultValue::list(), then push) or a record (set).
using ResultValue = workloads::ResultValue;

// What a program reports after its run, in the run's report (JSON and text) under `workload`.
class Results {
 public:
  Results(workloads::ResultValue& value, const network::Machine& machine,
          std::vector<workloads::OutputTable>& tables)
      : value_(value), machine_(machine), tables_(tables) {}
  Results& set(const std::string& key, workloads::ResultValue v) {
    value_.set(key, std::move(v));
    return *this;
  }
  // A table for one of the program's output_file parameters (output_file_param): t800sim writes it
  // as CSV where the scene's parameter says -- a header of the column names, then one line per row,
  // numbers to 17 significant digits -- or nothing when the parameter is empty. Throws
  // std::logic_error when `param` is not an output_file parameter of the program's kind, or a row's
  // length is not the columns'.
  Results& table(const std::string& param, std::vector<std::string> columns,
                 std::vector<std::vector<double>> rows);
  double cycle_ns(const std::string& processor) const;             // the processor's clock period
  std::string processor_type(const std::string& processor) const;  // "T800-20"
  double simulated_us() const;

 private:
  workloads::ResultValue& value_;
  const network::Machine& machine_;
  std::vector<workloads::OutputTable>& tables_;
};

class Program {
 public:
  virtual ~Program() = default;
  virtual void build(Builder& b) = 0;
  virtual void results(Results&) const {}
};

}  // namespace t800sim
