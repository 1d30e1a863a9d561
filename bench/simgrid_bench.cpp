// t800sim against SimGrid (issue 14), a benchmark program, not a test: the same work simulated by
// t800sim and by an S4U model in SimGrid (bench/simgrid/simgrid_model.cpp), side by side. Rows: the
// dynamics farm on generated trees of 9, 255 and 1023 workers, 10,000 one-way 4 KB messages with
// `auto` links, and 10,000 64-byte ping-pong messages.
//
// Every simulation is a child process (t800sim and SimGrid alike), timed from fork to exit with a
// steady clock; the rows' runs are interleaved (run 1 of every row and simulator, then run 2, ...),
// so a change in the machine's load falls on both, and the medians are printed. The SimGrid farm is
// fed from t800sim's own network, allocation and costs (a first, untimed t800sim run gives each
// worker's subtasks and compute time), so its Tp can be compared with t800sim's: the table prints
// both. Without the simgrid_model executable (SimGrid not installed, or not built) only the
// t800sim side runs.
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "bench/support/t800sim_path.hpp"
#include "network/machine.hpp"
#include "network/transport/store_and_forward.hpp"
#include "t800/compute_model.hpp"
#include "t800/link_timing.hpp"
#include "t800/timing_table.hpp"
#include "tools/child_run.hpp"
#include "tools/paper_data.hpp"
#include "tools/run_inputs.hpp"
#include "tools/scene.hpp"
#include "workloads/dynamics/worker_input.hpp"

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

struct Options {
  int runs = 5;
  std::vector<int> workers{9, 255, 1023};
  long messages = 10000;
  std::string t800sim, simgrid_model;
  std::string keep_plans;  // a directory to keep the SimGrid plans in, for inspection
};

// The SimGrid model built next to t800sim (BUILD/t800sim -> BUILD/bench/simgrid_model), or the one
// given; empty when it was not built.
std::string find_simgrid_model(const std::string& given, const std::string& t800sim) {
  if (!given.empty()) {
    if (access(given.c_str(), X_OK) != 0 || !fs::is_regular_file(given))
      throw std::invalid_argument("--simgrid-model " + given + ": no such executable file");
    return fs::absolute(given).string();
  }
  const fs::path built = fs::path(t800sim).parent_path() / "bench" / "simgrid_model";
  std::error_code ec;
  return fs::is_regular_file(built, ec) && access(built.c_str(), X_OK) == 0 ? built.string() : "";
}

// --- the SimGrid plans, from t800sim's own inputs ------------------------------------------------

json link_plan(const t800::LinkConfig& config) {
  const t800::LinkTiming t(config);
  // latency + bytes * period = t800sim's arrival time of an uncontended message.
  return {{"latency_s", (t.data_packet_ns - t.byte_period_ns) * 1e-9},
          {"byte_s", t.byte_period_ns * 1e-9}};
}

t800::ComputeModel compute_model(const workloads::RunInputs& in, int node) {
  const network::MachineOptions& o = in.options;
  return t800::ComputeModel(in.topology.processors.at(std::size_t(node)).config,
                            {o.precision, o.code_efficiency, o.fidelity.compute_cost, o.checked});
}

// Cycles of one `in` or `out` of every length the plan uses.
json communication_costs(const t800::ComputeModel& model, const std::vector<long>& lengths) {
  json costs = json::array();
  for (long bytes : lengths)
    for (bool copies : {false, true})
      costs.push_back({bytes, copies, model.communication_cycles(bytes, copies)});
  return costs;
}

// Two neighbours (the scene's pair) exchanging `bytes`-byte messages.
json pair_plan(const std::string& kind, const tools::Scene& scene, long bytes, long messages) {
  const workloads::RunInputs in = tools::inputs_from(scene);
  return {{"kind", kind},
          {"cycle_s", compute_model(in, 0).cycle_ns() * 1e-9},
          {"link", link_plan(in.options.link)},
          {"hosts", 2},
          {"edges", json::array({json::array({0, 1})})},
          {"comm_cycles", communication_costs(compute_model(in, 0), {0, bytes})},
          {"bytes", bytes},
          {"messages", messages}};
}

// The farm's static round: the channels the farm declares (to and from every worker, routed unless
// alone on their link direction, as network::Machine decides), the workers t800sim gave subtasks,
// each with the compute time and result size its report states.
json farm_plan(const tools::Scene& scene, const json& report) {
  const workloads::RunInputs in = tools::inputs_from(scene);
  const network::Topology& t = in.topology;
  const long real = in.options.precision == t800::Precision::real32 ? 4 : 8;
  const long input = dynamics::worker_input_reals(*in.robot) * real;
  const long header = network::kRouteHeaderBytes;
  const t800::ComputeModel model = compute_model(in, 0);
  const int workers = int(t.processors.size()) - 1;

  std::vector<std::vector<int>> paths;  // to P1, from P1, to P2, ...
  for (int w = 1; w <= workers; ++w) {
    paths.push_back(t.shortest_path(0, w));
    paths.push_back(t.shortest_path(w, 0));
  }
  std::map<std::pair<int, int>, int> users;
  for (const auto& p : paths)
    for (std::size_t i = 0; i + 1 < p.size(); ++i) ++users[{p[i], p[i + 1]}];
  json channels = json::array();
  for (const auto& p : paths)
    channels.push_back({{"path", p}, {"routed", p.size() > 2 || users[{p[0], p[1]}] > 1}});

  json plan_workers = json::array();
  std::vector<long> lengths{0, input, input + header};
  for (const json& w : report.at("workload").at("per_worker")) {
    const long results = long(w.at("subtasks").size());
    if (results == 0) continue;
    const int node = t.find(w.at("name").get<std::string>());
    const double cycles = w.at("compute_us").get<double>() * 1e3 / model.cycle_ns();
    plan_workers.push_back({{"node", node},
                            {"to", 2 * (node - 1)},
                            {"from", 2 * (node - 1) + 1},
                            {"compute_cycles", cycles},
                            {"input_bytes", input},
                            {"result_bytes", results * real}});
    lengths.push_back(results * real);
    lengths.push_back(results * real + header);
  }
  std::sort(lengths.begin(), lengths.end());
  lengths.erase(std::unique(lengths.begin(), lengths.end()), lengths.end());
  json edges = json::array();
  for (const network::Connection& c : t.connections)
    edges.push_back({c.a.processor, c.b.processor});
  return {{"kind", "farm"},
          {"cycle_s", model.cycle_ns() * 1e-9},
          {"link", link_plan(in.options.link)},
          {"header_bytes", header},
          {"hosts", int(t.processors.size())},
          {"edges", edges},
          {"comm_cycles", communication_costs(model, lengths)},
          {"master", 0},
          {"startp_cycles", t800::timing::start_process_cycles()},
          {"endp_cycles", t800::timing::end_process_cycles()},
          {"channels", channels},
          {"workers", plan_workers}};
}

// --- rows ----------------------------------------------------------------------------------------

struct Row {
  Row(std::string what, std::vector<std::string> args)
      : work(std::move(what)), t800sim_args(std::move(args)) {}
  std::string work;
  std::vector<std::string> t800sim_args;
  std::string plan_file;  // empty: no SimGrid side
  long messages = 0;      // > 0: also print messages per second
  std::vector<double> t800sim_wall, simgrid_wall;
  double t800sim_sim_s = 0, simgrid_sim_s = 0;  // Tp for the farm, else the simulated time
};

json run_t800sim(const std::string& exe, const std::vector<std::string>& args, double* wall) {
  const tools::ChildOutput c = tools::run_program(exe, args);
  if (c.exit_code != 0)
    throw std::runtime_error(
        fmt::format("t800sim {} failed ({}):\n{}", fmt::join(args, " "), c.exit_code, c.err));
  if (wall) *wall = c.wall_s;
  return json::parse(c.out);
}

json run_simgrid(const std::string& exe, const std::string& plan, double* wall) {
  const tools::ChildOutput c =
      tools::run_program(exe, {plan, "--log=root.thres:critical", "--log=xbt_cfg.thres:critical"});
  if (c.exit_code != 0)
    throw std::runtime_error(
        fmt::format("simgrid_model {} failed ({}):\n{}", plan, c.exit_code, c.err));
  if (wall) *wall = c.wall_s;
  return json::parse(c.out);
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : (v[n / 2 - 1] + v[n / 2]) / 2;
}

double simulated_s(const json& report) {
  const json& w = report.at("workload");
  if (w.contains("tp_us")) return w.at("tp_us").get<double>() * 1e-6;
  return report.at("simulated_us").get<double>() * 1e-6;
}

std::vector<Row> make_rows(const Options& o, const std::string& exe, bool simgrid,
                           const fs::path& plans) {
  std::vector<Row> rows;
  auto write_plan = [&](const std::string& name, const json& plan) {
    if (!simgrid) return std::string();
    const fs::path file = plans / (name + ".json");
    std::ofstream(file) << plan.dump(1) << "\n";
    return file.string();
  };
  const std::string farm = tools::find_repository_file("configs/scenes/dynamics-farm.toml");
  for (int w : o.workers) {
    const std::vector<std::string> sets{"network.family=tree",
                                        "network.workers=" + std::to_string(w)};
    Row r(fmt::format("farm, {} workers", w), {"run", farm, "--json"});
    for (const std::string& s : sets) r.t800sim_args.insert(r.t800sim_args.end(), {"--set", s});
    if (simgrid) {
      const json report = run_t800sim(exe, r.t800sim_args, nullptr);
      r.plan_file =
          write_plan(fmt::format("farm-{}", w), farm_plan(tools::load_scene(farm, sets), report));
    }
    rows.push_back(r);
  }
  const std::string stream = tools::find_repository_file("configs/scenes/link-stream.toml");
  const std::vector<std::string> stream_sets{"workload.messages=" + std::to_string(o.messages),
                                             "fidelity.links=auto"};
  Row s(fmt::format("{} one-way 4 KB messages, auto links", o.messages),
        {"run", stream, "--json", "--set", stream_sets[0], "--set", stream_sets[1]});
  const tools::Scene stream_scene = tools::load_scene(stream, stream_sets);
  s.plan_file = write_plan("stream", pair_plan("stream", stream_scene,
                                               stream_scene.workload.integer("bytes"), o.messages));
  s.messages = o.messages;
  rows.push_back(s);
  const std::string pingpong = tools::find_repository_file("configs/scenes/pingpong.toml");
  const std::vector<std::string> ping_sets{"workload.iterations=" + std::to_string(o.messages / 2)};
  Row p(fmt::format("{} 64-byte ping-pong messages", o.messages),
        {"run", pingpong, "--json", "--set", ping_sets[0]});
  const tools::Scene ping_scene = tools::load_scene(pingpong, ping_sets);
  p.plan_file = write_plan(
      "pingpong",
      pair_plan("pingpong", ping_scene, ping_scene.workload.integer("bytes"), o.messages / 2));
  p.messages = o.messages;
  rows.push_back(p);
  return rows;
}

std::string rate(const Row& r, double wall) {
  return r.messages > 0 ? fmt::format(" ({:.1f} k msg/s)", double(r.messages) / wall / 1e3) : "";
}

int bench(const Options& o) {
  const std::string exe = benchmarks::find_t800sim(o.t800sim);
  const std::string model = find_simgrid_model(o.simgrid_model, exe);
  const bool simgrid = !model.empty();
  std::cout << "t800sim: " << exe << "\nSimGrid model: "
            << (simgrid ? model
                        : "not built (install libsimgrid-dev, then `cmake --build build --target "
                          "simgrid_model`): t800sim only")
            << "\n";
  fs::path plans = o.keep_plans;
  if (plans.empty()) plans = fs::temp_directory_path() / fmt::format("simgrid_bench.{}", getpid());
  fs::create_directories(plans);

  std::vector<Row> rows = make_rows(o, exe, simgrid, plans);
  for (int run = 0; run < o.runs; ++run) {
    std::cerr << fmt::format("run {}/{}\n", run + 1, o.runs);
    for (Row& r : rows) {
      double wall = 0;
      r.t800sim_sim_s = simulated_s(run_t800sim(exe, r.t800sim_args, &wall));
      r.t800sim_wall.push_back(wall);
      if (r.plan_file.empty()) continue;
      r.simgrid_sim_s = run_simgrid(model, r.plan_file, &wall).at("tp_s");
      r.simgrid_wall.push_back(wall);
    }
  }
  if (o.keep_plans.empty()) fs::remove_all(plans);

  std::cout << fmt::format("\nmedians of {} interleaved runs, wall time of each child process\n",
                           o.runs);
  std::cout << fmt::format("{:<44} {:>24} {:>24} {:>9}   {}\n", "work", "t800sim", "SimGrid",
                           "t800/SG", "simulated: t800sim / SimGrid");
  for (const Row& r : rows) {
    const double t = median(r.t800sim_wall);
    std::string sg = "-", ratio = "-", agree;
    if (!r.simgrid_wall.empty()) {
      const double s = median(r.simgrid_wall);
      sg = fmt::format("{:.3f} s{}", s, rate(r, s));
      ratio = fmt::format("{:.2f}", t / s);
      agree = fmt::format("{:.4f} ms / {:.4f} ms ({:+.2f} %)", r.t800sim_sim_s * 1e3,
                          r.simgrid_sim_s * 1e3, (r.simgrid_sim_s / r.t800sim_sim_s - 1) * 100);
    }
    std::cout << fmt::format("{:<44} {:>24} {:>24} {:>9}   {}\n", r.work,
                             fmt::format("{:.3f} s{}", t, rate(r, t)), sg, ratio, agree);
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  CLI::App app{
      "t800sim against SimGrid: the dynamics farm (trees of 9, 255, 1023 workers), 10,000 one-way "
      "4 KB messages and 10,000 64-byte ping-pong messages, each simulated by both in child "
      "processes, interleaved; prints the median wall times and each side's simulated time.",
      "simgrid_bench"};
  app.add_option("--runs", o.runs, "runs of every row; the wall time is their median")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  app.add_option("--workers", o.workers, "farm sizes (generated trees)")->capture_default_str();
  app.add_option("--messages", o.messages, "messages of the stream and the ping-pong")
      ->capture_default_str()
      ->check(CLI::Range(2L, 100000000L));
  app.add_option("--t800sim", o.t800sim, "the t800sim executable (default: BUILD/t800sim)");
  app.add_option("--simgrid-model", o.simgrid_model,
                 "the SimGrid model (default: BUILD/bench/simgrid_model, if built)");
  app.add_option("--keep-plans", o.keep_plans, "a directory to keep the SimGrid plans in");
  CLI11_PARSE(app, argc, argv);
  try {
    return bench(o);
  } catch (const std::invalid_argument& e) {
    std::cerr << "simgrid_bench: error: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "simgrid_bench: error: " << e.what() << "\n";
    return 1;
  }
}
