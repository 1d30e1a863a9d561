// Speed of the instruction-set simulator (issue 24), a benchmark program, not a test: simulated
// T800 instructions per host second with full timing, on one processor and on chains of 4 and 16
// booted through each other (examples/iss/chain.s: every processor counts down a loop, so all
// compute at once), a link-bound program (examples/iss/pingpong.s, 1000-byte round trips), and two
// processors computing while each watches a link in an ALT (examples/iss/watch.s; running ahead,
// and with the look-ahead alone), with the SystemC synchronisations per instruction. Each run is a
// child `t800sim boot ... --json`; the rate is instructions over the host seconds of the simulation
// (wall_s less elaboration_s).
#include <sys/wait.h>

#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "bench/support/t800sim_path.hpp"
#include "tools/child_run.hpp"
#include "tools/paper_data.hpp"

namespace {

namespace fs = std::filesystem;

struct Options {
  std::string t800sim;
  std::int64_t iterations = 2'000'000;  // per processor: 6 instructions each
  int repeats = 3;
};

std::string read(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// The example's source with `name = value` (or `label: .word value`) set.
std::string with(std::string text, const std::string& key, const std::string& value) {
  const auto at = text.find(key);
  if (at == std::string::npos) throw std::runtime_error("no " + key + " in the example");
  text.replace(at, text.find('\n', at) - at, key + value);
  return text;
}

// A chain of n T800-20s wired Pi.link1 -> P(i+1).link0, the host on P0.link0.
std::string chain_topology(int n) {
  std::string t = fmt::format("name = \"chain-{}\"\nhost = \"P0.link0\"\n", n);
  for (int i = 0; i < n; ++i) t += fmt::format("[[processor]]\nname = \"P{}\"\n", i);
  for (int i = 0; i + 1 < n; ++i)
    t += fmt::format("[[link]]\nfrom = \"P{}.link1\"\nto = \"P{}.link0\"\n", i, i + 1);
  return t;
}

struct Result {
  double instructions = 0, sim_s = 0, host_s = 0, syncs = 0;
};

Result boot(const std::string& exe, const fs::path& dir, const std::string& name,
            const std::string& source, int processors, const std::vector<std::string>& flags) {
  const fs::path s = dir / (name + ".s"), b = dir / (name + ".btl"), t = dir / (name + ".toml");
  std::ofstream(s) << source;
  std::ofstream(t) << chain_topology(processors);
  tools::ChildOutput a = tools::run_program(exe, {"asm", s.string(), "-o", b.string()});
  if (a.exit_code != 0) throw std::runtime_error("asm failed: " + a.err);
  const fs::path json = dir / (name + ".json");
  fs::remove(json);  // a run that fails to write its own must not be read as the last one's
  std::vector<std::string> args{"boot",     b.string(), "--network",
                                t.string(), "--json",   json.string()};
  args.insert(args.end(), flags.begin(), flags.end());
  const tools::ChildOutput c = tools::run_program(exe, args);
  if (!fs::exists(json)) throw std::runtime_error(name + ": no report: " + c.err);
  const auto r = nlohmann::json::parse(read(json));
  Result out;
  out.instructions = r["workload"]["instructions"].get<double>();
  out.syncs = r["workload"]["synchronisations"].get<double>();
  out.sim_s = r["simulated_us"].get<double>() * 1e-6;
  out.host_s = r["wall_s"].get<double>() - r["elaboration_s"].get<double>();
  return out;
}

int measure(const Options& o) {
  const std::string exe = benchmarks::find_t800sim(o.t800sim);
  const fs::path dir = fs::temp_directory_path() / fmt::format("t800sim-iss-bench-{}", getpid());
  fs::create_directories(dir);
  const std::string chain = read(tools::find_repository_file("examples/iss/chain.s"));
  const std::string pingpong = read(tools::find_repository_file("examples/iss/pingpong.s"));
  const std::string watch = read(tools::find_repository_file("examples/iss/watch.s"));
  std::cout << fmt::format("{:<22} {:>5} {:>14} {:>10} {:>9} {:>12} {:>12}\n", "program", "procs",
                           "instructions", "sim_s", "host_s", "M_instr/s", "syncs/instr");
  struct Case {
    std::string name;
    std::string source;
    int processors;
    std::vector<std::string> flags = {};
  };
  const std::string counted = with(chain, "iterations = ", std::to_string(o.iterations));
  const std::vector<Case> cases{
      {"chain (compute)", with(counted, "hops:   .word ", "0"), 1},
      {"chain (compute)", with(counted, "hops:   .word ", "3"), 4},
      {"chain (compute)", with(counted, "hops:   .word ", "15"), 16},
      {"pingpong 1000 B x 2000", with(with(pingpong, "rounds = ", "2000"), "bytes = ", "1000"), 2},
      {"watch (ALT on a link)", with(watch, "iterations = ", std::to_string(o.iterations)), 2},
      // The same with the look-ahead alone: a data packet's time between synchronisations.
      {"watch, --no-run-ahead",
       with(watch, "iterations = ", std::to_string(o.iterations)),
       2,
       {"--no-run-ahead"}},
  };
  for (const Case& c : cases) {
    Result best;
    for (int k = 0; k < o.repeats; ++k) {
      const Result r = boot(exe, dir, "case", c.source, c.processors, c.flags);
      if (k == 0 || r.host_s < best.host_s) best = r;
    }
    std::cout << fmt::format("{:<22} {:>5} {:>14.0f} {:>10.4f} {:>9.3f} {:>12.1f} {:>12.6f}\n",
                             c.name, c.processors, best.instructions, best.sim_s, best.host_s,
                             best.instructions / best.host_s * 1e-6,
                             best.syncs / best.instructions);
  }
  fs::remove_all(dir);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  CLI::App app{"ISS speed: simulated T800 instructions per host second (issue 24)"};
  app.add_option("--t800sim", o.t800sim, "the t800sim to run (default: this build's)");
  app.add_option("--iterations", o.iterations,
                 "loop iterations per processor (6 instructions each)");
  app.add_option("--repeats", o.repeats, "runs per case; the fastest is shown");
  CLI11_PARSE(app, argc, argv);
  try {
    return measure(o);
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 1;
  }
}
