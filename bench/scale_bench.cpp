// Host memory per simulated transputer (issue 12), a benchmark program, not a test: the dynamics
// farm on generated trees, meshes and hypercubes of 64 to 1024 T800s, tracing off, each run a child
// `t800sim run configs/scenes/dynamics-farm.toml --set network.family=F --set network.workers=N-1
// --json` whose peak resident memory (ru_maxrss from wait4) is measured. Memory per transputer is
// the slope between the smallest and the largest network of a family, so the fixed cost of the
// program (SystemC, the libraries, the robot model) drops out. Also printed: the child's wall time
// and the report's elaboration_s (set-up before simulating), for the scaling curve against N (issue
// 14).
#include <sys/wait.h>

#include <iostream>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "bench/support/t800sim_path.hpp"
#include "tools/child_run.hpp"
#include "tools/paper_data.hpp"

namespace {

struct Options {
  std::vector<std::string> families{"tree", "mesh", "hypercube"};
  std::vector<int> sizes{64, 256, 1024};  // transputers, P0 included
  std::string t800sim;
};

struct Run {
  int transputers = 0;
  double peak_kib = 0, wall_s = 0, elaboration_s = 0, tp_ms = 0;
};

Run run(const std::string& exe, const std::string& scene, const std::string& family,
        int transputers) {
  const std::vector<std::string> args{"run",   scene,
                                      "--set", "network.family=" + family,
                                      "--set", "network.workers=" + std::to_string(transputers - 1),
                                      "--json"};
  const tools::ChildOutput c = tools::run_program(exe, args);
  if (!WIFEXITED(c.status) || WEXITSTATUS(c.status) != 0)
    throw std::runtime_error(fmt::format("{} {} of {} transputers failed (status {}):\n{}", family,
                                         scene, transputers, c.status, c.err));
  const nlohmann::json report = nlohmann::json::parse(c.out);
  if (report["processors"].size() != std::size_t(transputers))
    throw std::runtime_error(
        fmt::format("{}: expected {} processors in the report", family, transputers));
  return {transputers, double(c.maxrss_kib), c.wall_s, report["elaboration_s"].get<double>(),
          report["workload"]["tp_ms"].get<double>()};
}

int measure(const Options& o) {
  const std::string exe = benchmarks::find_t800sim(o.t800sim);
  const std::string scene = tools::find_repository_file("configs/scenes/dynamics-farm.toml");
  std::cout << fmt::format("{:<10} {:>12} {:>10} {:>8} {:>8} {:>10}\n", "family", "transputers",
                           "peak_MiB", "wall_s", "elab_s", "Tp_ms");
  for (const std::string& family : o.families) {
    std::vector<Run> runs;
    for (int n : o.sizes) {
      runs.push_back(run(exe, scene, family, n));
      const Run& r = runs.back();
      std::cout << fmt::format("{:<10} {:>12} {:>10.1f} {:>8.3f} {:>8.3f} {:>10.4f}\n", family,
                               r.transputers, r.peak_kib / 1024.0, r.wall_s, r.elaboration_s,
                               r.tp_ms)
                << std::flush;
    }
    const Run &small = runs.front(), &large = runs.back();
    if (large.transputers > small.transputers)
      std::cout << fmt::format(
          "{:<10} host memory per transputer (slope {} -> {}): {:.1f} KiB\n", family,
          small.transputers, large.transputers,
          (large.peak_kib - small.peak_kib) / (large.transputers - small.transputers));
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  CLI::App app{
      "Host memory per simulated transputer: the dynamics farm on generated networks of 64 to "
      "1024 T800s, tracing off, each a child t800sim run whose peak memory is measured.",
      "scale_bench"};
  app.add_option("--families", o.families, "families to run")->capture_default_str();
  app.add_option("--sizes", o.sizes,
                 "network sizes in transputers (P0 included); hypercubes need powers "
                 "of two")
      ->capture_default_str();
  app.add_option("--t800sim", o.t800sim, "the t800sim executable (default: BUILD/t800sim)");
  CLI11_PARSE(app, argc, argv);
  try {
    return measure(o);
  } catch (const std::exception& e) {
    std::cerr << "scale_bench: error: " << e.what() << "\n";
    return 1;
  }
}
