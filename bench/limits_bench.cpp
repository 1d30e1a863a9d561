// The measurements behind network/limits.hpp (issue 27), a benchmark program, not a test. Each
// probe runs in a child of this program (SystemC elaborates once per process), whose wall time and
// peak resident memory are measured:
//   threads N   N SystemC threads spawned as the machine spawns a process (sc_spawn, default
//               options), each waiting once; run past the simulator's limit to find SystemC's own
//               (E518 "stack setup failed" when the host refuses another stack mapping).
//   channels N  an SDK program of two processes and N channels between them, declared, realised
//               and run on a chain of two T800s, as `t800sim run` would.
// Prints one row per probe and the host's vm.max_map_count, which bounds the threads. Where SystemC
// gives out varies between runs at one count (how the stacks' maps fall), so counts may be
// repeated.
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <CLI/CLI.hpp>
#include <systemc>

#include "network/families.hpp"
#include "network/limits.hpp"
#include "network/machine.hpp"
#include "sdk/program_workload.hpp"
#include "t800sim/program.hpp"
#include "tools/child_run.hpp"

namespace {

int probe_threads(long n) {
  try {
    for (long i = 0; i < n; ++i)
      sc_core::sc_spawn([] { sc_core::wait(1, sc_core::SC_NS); }, sc_core::sc_gen_unique_name("t"));
    sc_core::sc_start();
  } catch (const std::exception& e) {
    std::cerr << e.what() << "\n";
    return 3;
  }
  return 0;
}

class ManyChannels : public t800sim::Program {
 public:
  explicit ManyChannels(long n) : n_(n) {}
  void build(t800sim::Builder& b) override {
    for (long i = 0; i < n_; ++i) b.channel<int>(fmt::format("c{}", i), "a", "b");
    b.process("a", [](t800sim::Process&) {}).placed_on("P0");
    b.process("b", [](t800sim::Process&) {}).placed_on("P1");
  }

 private:
  long n_;
};

int probe_channels(long n) {
  try {
    const network::Topology topology =
        network::generate(network::Family::chain, 1, {}, {"limits", 0, 0});
    network::Machine machine(topology, {});
    const workloads::Params params;
    const workloads::Placement placement;
    const workloads::WorkloadContext context{params, topology, nullptr, &placement};
    t800sim::detail::ProgramWorkload workload("limits", std::make_unique<ManyChannels>(n), context);
    workload.build(machine);
    machine.run();
  } catch (const std::exception& e) {
    std::cerr << e.what() << "\n";
    return 3;
  }
  return 0;
}

std::string max_map_count() {
  std::ifstream f("/proc/sys/vm/max_map_count");
  std::string v;
  return f >> v ? v : "unknown";
}

void report(const std::string& probe, long n) {
  const tools::ChildOutput c = tools::run_self({"--child", probe, std::to_string(n)});
  std::string outcome = c.exit_code == 0 ? "ran" : "failed";
  if (c.exit_code != 0) {
    const std::string first_line = c.err.substr(0, c.err.find('\n'));
    outcome += fmt::format(" (exit {}): {}", c.exit_code, first_line.substr(0, 70));
  }
  std::cout << fmt::format("{:<9} {:>10} {:>9.2f} {:>10.1f}  {}\n", probe, n, c.wall_s,
                           c.maxrss_kib / 1024.0, outcome)
            << std::flush;
}

}  // namespace

int main(int argc, char** argv) {
  const long limit = network::kMaxProcesses;
  std::vector<long> threads{1000, 10000, limit, limit, limit, 33200, 33200, 33200, 35000, 40000};
  std::vector<long> channels{10000, 100000, network::kMaxChannels};
  std::vector<std::string> child;
  CLI::App app{"The measurements behind the stated process and channel limits (network/limits.hpp)",
               "limits_bench"};
  app.add_option("--threads", threads, "SystemC thread counts to probe")->capture_default_str();
  app.add_option("--channels", channels, "channel counts to probe")->capture_default_str();
  app.add_option("--child", child, "run one probe here (what the parent runs as a child)")
      ->expected(2)
      ->group("");
  CLI11_PARSE(app, argc, argv);
  if (!child.empty()) {
    const long n = std::stol(child[1]);
    return child[0] == "threads" ? probe_threads(n) : probe_channels(n);
  }
  std::cout << fmt::format("vm.max_map_count {}; limits: {} processes, {} channels\n",
                           max_map_count(), network::kMaxProcesses, network::kMaxChannels);
  std::cout << fmt::format("{:<9} {:>10} {:>9} {:>10}  {}\n", "probe", "n", "wall_s", "peak_MiB",
                           "outcome");
  for (long n : threads) report("threads", n);
  for (long n : channels) report("channels", n);
  return 0;
}
