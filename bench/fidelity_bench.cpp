// Run time against error (issue 6), a benchmark program, not a test: for every paper scene (Table
// 4's dynamics farm, Table 6's elimination pipeline, a trajectory) and every fidelity level, the
// wall time, the events per second, the peak memory, the simulated Tp and its error against the
// finest level and against the paper. docs/benchmark.md explains the columns.
//
// Every simulation is a child process of t800sim (`t800sim run SCENE --set ... --json`): SystemC
// runs one simulation per process. The wall time is measured around the child with a steady clock,
// the peak memory is the child's ru_maxrss from wait4().
#include <sys/wait.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <chrono>
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "bench/support/t800sim_path.hpp"

#include "tools/child_run.hpp"
#include "tools/paper_data.hpp"
#include "workloads/pipeline/pipeline.hpp"

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// --- options -------------------------------------------------------------------------------------

struct Options {
  int runs = 5;
  bool quick = false;
  std::string only;  // "", "table4", "table6", "trajectory"
  std::string t800sim;
  std::string csv = "bench-fidelity.csv";
};

// --- what is measured ----------------------------------------------------------------------------

// One scene of the paper, with the overrides `t800sim paper` uses for that row.
struct BenchScene {
  std::string group;  // table4, table6, trajectory
  std::string label;  // e.g. "table4 w=3"
  std::string file;   // the scene file
  std::vector<std::string> overrides;
  std::optional<double> paper_tp_ms;
  bool timing_only;  // Tables 4 and 6: only Tp matters, so numerics may be skipped
};

// One fidelity level: a row of the table for each scene.
struct Level {
  std::string name;
  std::vector<std::string> overrides;
};

struct Row {
  const BenchScene* scene;
  std::string level;
  std::vector<double> wall_s;       // around the child, one per run
  std::vector<double> inprocess_s;  // the report's wall_s, one per run
  std::int64_t events = 0;          // the report's events (the first run's)
  double peak_rss_mib = 0;          // max over runs
  double tp_ms = 0;                 // the first run's
  std::string reported_fidelity;    // as the report states it
  bool tp_varied = false;           // Tp not identical in every run
  double wall_median = 0, wall_min = 0, inprocess_median = 0;
  std::optional<double> err_finest_pct, err_paper_pct, speedup;
};

std::vector<std::string> fidelity(const std::string& links, const std::string& compute,
                                  bool skip_numerics, bool reuse_steps,
                                  const std::string& compute_cost = "instructions") {
  auto flag = [](bool b) { return std::string(b ? "true" : "false"); };
  return {"fidelity.links=" + links, "fidelity.compute=" + compute,
          "fidelity.skip_numerics=" + flag(skip_numerics),
          "fidelity.reuse_steps=" + flag(reuse_steps), "fidelity.compute_cost=" + compute_cost};
}

// The levels, finest first (the reference of every other row). Every key is given explicitly so the
// rows do not depend on the scene's or the program's defaults.
std::vector<Level> levels_for(const BenchScene& s) {
  std::vector<Level> levels{
      {"finest", fidelity("packet", "fine", false, false)},
      {"message-block", fidelity("message", "block", false, false)},
      {"auto", fidelity("auto", "auto", s.timing_only, true)},
  };
  if (s.timing_only)
    levels.push_back({"auto, skip_numerics off", fidelity("auto", "auto", false, true)});
  else
    levels.push_back({"auto, reuse_steps off", fidelity("auto", "auto", false, false)});
  // The op-count model instead of the generated code (fidelity.compute_cost).
  levels.push_back(
      {"auto, compute_cost mix", fidelity("auto", "auto", s.timing_only, true, "mix")});
  return levels;
}

std::vector<BenchScene> paper_scenes(const Options& o) {
  const tools::PaperTables paper =
      tools::load_paper_tables(tools::find_repository_file("configs/paper/paper.toml"));
  std::vector<BenchScene> scenes;
  if (o.only.empty() || o.only == "table4") {
    const std::string file = tools::find_repository_file("configs/scenes/dynamics-farm.toml");
    for (std::size_t i = 0; i < paper.table4_workers.size(); ++i) {
      const int w = paper.table4_workers[i];
      scenes.push_back({"table4",
                        fmt::format("table4 w={}", w),
                        file,
                        {"network.workers=" + std::to_string(w)},
                        paper.table4_tp_ms[i],
                        true});
    }
  }
  if (o.only.empty() || o.only == "table6") {
    const std::string file = tools::find_repository_file("configs/scenes/elimination.toml");
    for (std::size_t i = 0; i < paper.table6_m.size(); ++i) {
      const int m = paper.table6_m[i];
      scenes.push_back({"table6", fmt::format("table6 m={}", m), file,
                        workloads::table6_overrides(m), paper.table6_tp_ms[i], true});
    }
  }
  if (o.only.empty() || o.only == "trajectory") {
    const int steps = o.quick ? 100 : 1000;
    scenes.push_back({"trajectory",
                      fmt::format("trajectory {} steps", steps),
                      tools::find_repository_file("configs/scenes/trajectory.toml"),
                      {"workload.steps=" + std::to_string(steps)},
                      std::nullopt,
                      false});
  }
  return scenes;
}

// --- child processes -----------------------------------------------------------------------------

std::string command_line(const std::string& exe, const std::vector<std::string>& args) {
  std::string s = exe;
  for (const std::string& a : args) s += " " + a;
  return s;
}

const json& at_path(const json& report, const std::vector<std::string>& path,
                    const std::string& what) {
  const json* j = &report;
  for (const std::string& key : path) {
    if (!j->is_object() || !j->contains(key)) throw std::runtime_error("the report has no " + what);
    j = &(*j)[key];
  }
  return *j;
}

double number_at(const json& report, const std::vector<std::string>& path,
                 const std::string& what) {
  const json& j = at_path(report, path, what);
  if (!j.is_number()) throw std::runtime_error("the report's " + what + " is not a number");
  return j.get<double>();
}

std::string fidelity_text(const json& report) {
  if (!report.contains("fidelity")) return "(not reported)";
  const json& f = report["fidelity"];
  auto text = [&](const char* k) {
    if (!f.contains(k)) return std::string("?");
    return f[k].is_string() ? f[k].get<std::string>() : f[k].dump();
  };
  return fmt::format("links={} compute={} compute_cost={} skip_numerics={} reuse_steps={}",
                     text("links"), text("compute"), text("compute_cost"), text("skip_numerics"),
                     text("reuse_steps"));
}

// One run of one row. Throws std::runtime_error with the command and the child's stderr on failure.
void run_once(const std::string& exe, const BenchScene& s, const Level& level, Row& row) {
  std::vector<std::string> args{"run", s.file, "--json"};
  for (const auto* list : {&s.overrides, &level.overrides})
    for (const std::string& o : *list) {
      args.push_back("--set");
      args.push_back(o);
    }
  const tools::ChildOutput c = tools::run_program(exe, args);
  const std::string cmd = command_line(exe, args);
  if (!WIFEXITED(c.status) || WEXITSTATUS(c.status) != 0) {
    const std::string how = WIFEXITED(c.status)
                                ? fmt::format("exited with code {}", WEXITSTATUS(c.status))
                                : fmt::format("was killed by signal {} ({})", WTERMSIG(c.status),
                                              strsignal(WTERMSIG(c.status)));
    throw std::runtime_error(fmt::format("the simulation {}:\n  {}\nits stderr:\n{}", how, cmd,
                                         c.err.empty() ? "(empty)\n" : c.err));
  }
  json report;
  try {
    report = json::parse(c.out);
  } catch (const json::exception& e) {
    throw std::runtime_error(fmt::format("unreadable JSON report ({}) from\n  {}\nits stderr:\n{}",
                                         e.what(), cmd, c.err.empty() ? "(empty)\n" : c.err));
  }
  try {
    const double tp_ms =
        s.timing_only
            ? number_at(report, {"workload", "tp_ms"}, "workload.tp_ms")
            : number_at(report, {"workload", "mean_step_us"}, "workload.mean_step_us") / 1000.0;
    const double inprocess = number_at(report, {"wall_s"}, "wall_s");
    const double events = number_at(report, {"events"}, "events");
    if (row.wall_s.empty()) {
      row.tp_ms = tp_ms;
      row.events = std::int64_t(events);
      row.reported_fidelity = fidelity_text(report);
    } else if (tp_ms != row.tp_ms) {
      row.tp_varied = true;
    }
    row.wall_s.push_back(c.wall_s);
    row.inprocess_s.push_back(inprocess);
    row.peak_rss_mib = std::max(row.peak_rss_mib, double(c.maxrss_kib) / 1024.0);
  } catch (const std::runtime_error& e) {
    throw std::runtime_error(fmt::format("{}, from\n  {}", e.what(), cmd));
  }
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

double error_pct(double value, double reference) {
  return 100.0 * (value - reference) / reference;
}

// The progress line (on a terminal only) is rewritten in place; this blanks it.
void clear_progress() {
  if (isatty(STDERR_FILENO)) std::cerr << "\r" << std::string(90, ' ') << "\r" << std::flush;
}

// --- output --------------------------------------------------------------------------------------

std::string opt(const std::optional<double>& v, const char* format) {
  return v ? fmt::format(fmt::runtime(format), *v) : std::string("-");
}

std::string csv_number(double v) {
  return fmt::format("{:.9g}", v);
}
std::string csv_opt(const std::optional<double>& v) {
  return v ? csv_number(*v) : std::string();
}

std::string csv_text(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string q = "\"";
  for (char ch : s) q += ch == '"' ? std::string("\"\"") : std::string(1, ch);
  return q + "\"";
}

void print_table(const std::vector<Row>& rows) {
  std::cout << fmt::format(
      "{:<22} {:<24} {:>4} {:>9} {:>9} {:>8} {:>10} {:>11} {:>7} {:>8} {:>11} "
      "{:>10} {:>9}\n",
      "scene", "level", "runs", "wall_med", "wall_min", "speedup", "sim_wall", "events", "Mev/s",
      "peak_MiB", "Tp_ms", "err_fine_%", "err_pap_%");
  std::string last;
  for (const Row& r : rows) {
    if (!last.empty() && last != r.scene->label) std::cout << "\n";
    last = r.scene->label;
    const double mev = r.inprocess_median > 0 ? r.events / r.inprocess_median / 1e6 : 0;
    std::cout << fmt::format(
        "{:<22} {:<24} {:>4} {:>9.4f} {:>9.4f} {:>8} {:>10.4f} {:>11} {:>7.2f} {:>8.1f} {:>11.6f} "
        "{:>10} {:>9}{}\n",
        r.scene->label, r.level, r.wall_s.size(), r.wall_median, r.wall_min,
        opt(r.speedup, "{:.2f}"), r.inprocess_median, r.events, mev, r.peak_rss_mib, r.tp_ms,
        opt(r.err_finest_pct, "{:+.4f}"), opt(r.err_paper_pct, "{:+.2f}"),
        r.tp_varied ? "  (Tp varied between runs)" : "");
  }
}

void write_csv(const std::string& path, const std::vector<Row>& rows) {
  std::ofstream f(path);
  if (!f) throw std::runtime_error("cannot write " + path);
  f << "scene,level,runs,wall_median_s,wall_min_s,speedup_vs_finest,sim_wall_median_s,events,"
       "events_per_s,peak_rss_mib,tp_ms,paper_tp_ms,error_vs_finest_pct,error_vs_paper_pct,"
       "fidelity\n";
  for (const Row& r : rows) {
    const double eps = r.inprocess_median > 0 ? r.events / r.inprocess_median : 0;
    f << csv_text(r.scene->label) << ',' << csv_text(r.level) << ',' << r.wall_s.size() << ','
      << csv_number(r.wall_median) << ',' << csv_number(r.wall_min) << ',' << csv_opt(r.speedup)
      << ',' << csv_number(r.inprocess_median) << ',' << r.events << ',' << csv_number(eps) << ','
      << csv_number(r.peak_rss_mib) << ',' << csv_number(r.tp_ms) << ','
      << csv_opt(r.scene->paper_tp_ms) << ',' << csv_opt(r.err_finest_pct) << ','
      << csv_opt(r.err_paper_pct) << ',' << csv_text(r.reported_fidelity) << '\n';
  }
  if (!f) throw std::runtime_error("cannot write " + path);
}

int bench(const Options& o) {
  const std::string exe = benchmarks::find_t800sim(o.t800sim);
  const std::vector<BenchScene> scenes = paper_scenes(o);
  std::size_t total = 0;
  for (const BenchScene& s : scenes) total += levels_for(s).size();

  std::cout << fmt::format("t800sim: {}\n", exe);
  std::cout
      << fmt::format("{} run(s) per row.\n", o.runs)
      << "wall_med / wall_min: median / minimum wall seconds of the whole child process (start, "
         "elaboration, simulation, report), steady clock\n"
         "speedup: finest's wall_med / this row's; sim_wall: median of the report's in-process "
         "wall_s\n"
         "events: SystemC delta cycles (the report's events); Mev/s: events / sim_wall, millions "
         "per second\n"
         "peak_MiB: max over the runs of the child's ru_maxrss (wait4)\n"
         "Tp_ms: Tables 4, 6: workload.tp_ms; trajectory: workload.mean_step_us / 1000\n"
         "err_fine_%: (Tp - finest's Tp) / finest's Tp; err_pap_%: against "
         "configs/paper/paper.toml\n\n";

  const bool progress = isatty(STDERR_FILENO);
  std::vector<Row> rows;
  std::size_t done = 0;
  for (const BenchScene& s : scenes) {
    const std::size_t first = rows.size();
    for (const Level& level : levels_for(s)) {
      Row row;
      row.scene = &s;
      row.level = level.name;
      ++done;
      for (int k = 0; k < o.runs; ++k) {
        if (progress)
          std::cerr << fmt::format("\r[{}/{}] {} / {}: run {}/{}   ", done, total, s.label,
                                   level.name, k + 1, o.runs)
                    << std::flush;
        run_once(exe, s, level, row);
      }
      row.wall_median = median(row.wall_s);
      row.wall_min = *std::min_element(row.wall_s.begin(), row.wall_s.end());
      row.inprocess_median = median(row.inprocess_s);
      if (s.paper_tp_ms) row.err_paper_pct = error_pct(row.tp_ms, *s.paper_tp_ms);
      rows.push_back(row);
    }
    const Row& finest = rows[first];  // levels_for puts the finest first
    for (std::size_t i = first; i < rows.size(); ++i) {
      rows[i].err_finest_pct = error_pct(rows[i].tp_ms, finest.tp_ms);
      rows[i].speedup = finest.wall_median / rows[i].wall_median;
    }
  }
  clear_progress();

  print_table(rows);
  write_csv(o.csv, rows);
  std::cout << fmt::format("\nwrote {}\n", o.csv);

  // What each level ran at, as the reports state it (the first scene of each group), and which rows
  // gave exactly the finest level's Tp, so a level that changed nothing is visible.
  std::cout << "\nfidelity as the reports state it (first scene of each group):\n";
  std::vector<std::string> groups_seen;
  const BenchScene* shown = nullptr;
  for (const Row& r : rows) {
    const bool seen =
        std::find(groups_seen.begin(), groups_seen.end(), r.scene->group) != groups_seen.end();
    if (seen && r.scene != shown) continue;
    if (!seen) groups_seen.push_back(r.scene->group);
    shown = r.scene;
    std::cout << fmt::format("  {:<22} {:<24} {}\n", r.scene->label, r.level, r.reported_fidelity);
  }
  int same = 0, others = 0;
  for (const Row& r : rows)
    if (r.level != "finest") {
      ++others;
      if (r.err_finest_pct && *r.err_finest_pct == 0.0) ++same;
    }
  std::cout << fmt::format("{} of {} non-finest rows give exactly the finest level's Tp.\n", same,
                           others);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  CLI::App app{
      "Run time against error for every paper scene and fidelity level (issue 6): wall time, "
      "events "
      "per second, peak memory, simulated Tp, error against the finest level and against the "
      "paper. "
      "Each simulation is a child `t800sim run SCENE --set ... --json`. See docs/benchmark.md.",
      "fidelity_bench"};
  app.add_option("--runs", o.runs, "runs per row; the wall time is their median")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  app.add_flag("--quick", o.quick,
               "Tables 4 and 6, and the trajectory at 100 steps instead of 1000");
  app.add_option("--only", o.only, "one group of scenes")
      ->check(CLI::IsMember({"table4", "table6", "trajectory"}));
  app.add_option("--t800sim", o.t800sim,
                 "the t800sim executable (default: BUILD/t800sim, next to BUILD/bench/ where this "
                 "program is)");
  app.add_option("--csv", o.csv, "where to write the CSV")->capture_default_str();
  CLI11_PARSE(app, argc, argv);
  try {
    return bench(o);
  } catch (const std::invalid_argument& e) {
    clear_progress();
    std::cerr << "fidelity_bench: error: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    clear_progress();
    std::cerr << "fidelity_bench: error: " << e.what() << "\n";
    return 1;
  }
}
