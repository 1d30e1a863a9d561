// `t800sim sweep`: one scene, many points (the cartesian product of --vary axes), each simulated by
// a child `t800sim run --json` (SystemC runs one simulation per process), N at a time, into a CSV
// table. Or, with
// --emit-jobs, the same points as shell commands for GNU parallel or a SLURM array (merged by
// `merge`).
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <thread>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "network/config_error.hpp"
#include "tools/child_run.hpp"
#include "tools/cli_numbers.hpp"
#include "tools/commands.hpp"
#include "tools/scene.hpp"
#include "tools/scene_faults.hpp"
#include "tools/sweep_csv.hpp"
#include "tools/sweep_progress.hpp"
#include "tools/sweep_result.hpp"
#include "tools/sweep_runner.hpp"
#include "tools/sweep_spec.hpp"
#include "tools/table_lock.hpp"
#include "workloads/run/output_file.hpp"

namespace tools {

namespace {

namespace fs = std::filesystem;

struct SweepArgs {
  std::string scene;
  std::vector<std::string> vary, overrides;
  std::vector<std::string> faults;  // --fault, passed to every point
  int jobs = int(std::max(1u, std::thread::hardware_concurrency()));
  std::string output;
  double timeout_s = 0;
  std::string emit_jobs, jobs_dir;
  int point = -1;  // run only this point (what one emitted job does)
  bool point_given = false;
};

struct Sweep {
  std::vector<std::string> keys;
  std::vector<SweepPoint> points;
};

Sweep plan(const SweepArgs& a) {
  Sweep s;
  std::vector<SweepAxis> axes;
  for (const std::string& flag : a.vary) {
    axes.push_back(parse_vary(flag));
    s.keys.push_back(axes.back().key);
  }
  for (const std::string& o : a.overrides) {
    const std::string key = o.substr(0, o.find('='));
    if (o.find('=') == std::string::npos)
      throw std::invalid_argument("--set " + o + ": expected KEY=VALUE");
    for (const std::string& k : s.keys)
      if (k == key)
        throw std::invalid_argument("--set " + o + " and --vary " + key + "=... set the same key");
  }
  s.points = sweep_points(axes);
  return s;
}

// An error in a varied value, said as the --vary flag that gave it (the scene loader sees a --set).
[[noreturn]] void throw_as_vary(const SweepArgs& a, const network::ConfigError& e) {
  const std::string& where = e.where().file;
  for (const std::string& flag : a.vary) {
    const std::string key = flag.substr(0, flag.find('='));
    if (where.rfind("--set " + key + "=", 0) == 0)
      throw std::invalid_argument("--vary " + flag + ": the value " +
                                  where.substr(6 + key.size() + 1) + ": " + e.message() +
                                  "; valid forms: " + vary_forms());
  }
  throw e;
}

// A scene that no point can load (a broken file, a bad fixed --set, a misspelt --vary key, a
// value no point accepts) would fail every point the same way: say so once, before starting.
// Otherwise an error in a varied value belongs to its point, which reports it in its row. Loading a
// scene is cheap: no simulation.
void check_scene(const SweepArgs& a, const Sweep& s) {
  std::optional<network::ConfigError> first;
  for (const SweepPoint& point : s.points) {
    std::vector<std::string> overrides = a.overrides;
    for (const auto& [key, value] : point) overrides.push_back(key + "=" + value);
    try {
      const Scene scene = load_scene(a.scene, overrides);
      for (const std::string& f : a.faults) parse_fault_flag(f, scene.topology);
      return;
    } catch (const network::ConfigError& e) {
      if (!first) first = e;
    }
  }
  throw_as_vary(a, *first);
}

// A point's result from its child; `report` (if given) receives the child's report.
PointResult judge(const SweepArgs& a, const SweepPoint& point, const ChildOutcome& outcome,
                  nlohmann::json* report) {
  nlohmann::json parsed;
  PointResult r = judge_point(point, outcome, parsed);
  if (outcome.timed_out) r.status = fmt::format("error: timed out after {} s", a.timeout_s);
  // The child saw the point's values as --set flags; the row names them as the varied keys.
  for (const auto& [key, value] : point) {
    const std::string flag = "--set " + key + "=" + value;
    for (auto at = r.status.find(flag); at != std::string::npos; at = r.status.find(flag, at))
      r.status.erase(at, 6);
  }
  if (report) *report = std::move(parsed);
  return r;
}

std::vector<std::string> run_argv(const SweepArgs& a, const SweepPoint& point) {
  std::vector<std::string> argv = {self_executable(), "run", a.scene};
  for (const std::string& o : a.overrides) argv.insert(argv.end(), {"--set", o});
  for (const auto& [key, value] : point) argv.insert(argv.end(), {"--set", key + "=" + value});
  for (const std::string& f : a.faults) argv.insert(argv.end(), {"--fault", f});
  argv.push_back("--json");
  return argv;
}

// Written beside and renamed over (workloads::OutputFile): an interrupted write never leaves half a
// table, a link stays a link, a device is written through.
void write_file(const std::string& flag, const std::string& path, const std::string& text) {
  try {
    workloads::write_output_file(path, text, flag);
  } catch (const std::runtime_error& e) {
    throw std::invalid_argument(e.what());
  }
}

// One finished point's row at the end of the table, opened anew each time: whoever replaced the
// file since (another sweep's final rewrite) is appended to, not an unlinked old copy.
void append_row(const std::string& path, const std::string& row) {
  std::ofstream append(path, std::ios::app);
  append << row << std::flush;
}

// The ok rows of an earlier run into the same file; its points are not run again.
std::vector<PointResult> earlier_results(const std::string& path,
                                         const std::vector<std::string>& keys) {
  if (!fs::exists(path)) return {};
  ResultsTable old = read_results_csv(path);
  std::vector<std::string> a = old.keys, b = keys;
  std::sort(a.begin(), a.end());
  std::sort(b.begin(), b.end());
  if (a != b)
    throw std::invalid_argument(path + " holds a sweep over other parameters (" +
                                fmt::format("{}", fmt::join(old.keys, ", ")) +
                                "); give another -o or remove it");
  std::vector<PointResult> kept;
  for (PointResult& r : old.rows)
    if (r.ok()) kept.push_back(std::move(r));
  return kept;
}

// The table on disk now, with every row it holds (what another writer added since this sweep read
// it included); this sweep's own view when the file is gone or no longer a table of these keys.
std::vector<PointResult> rows_on_disk(const std::string& path, const std::vector<std::string>& keys,
                                      const std::vector<PointResult>& own_view) {
  if (!fs::exists(path)) return own_view;
  try {
    ResultsTable disk = read_results_csv(path);
    std::vector<std::string> a = disk.keys, b = keys;
    std::sort(a.begin(), a.end());
    std::sort(b.begin(), b.end());
    if (a == b) return std::move(disk.rows);
    std::cerr << "sweep: -o " << path << " now holds a sweep over other parameters; rewriting it "
              << "from this sweep's rows\n";
  } catch (const std::invalid_argument& e) {
    std::cerr << "sweep: -o " << path << " cannot be read back (" << e.what()
              << "); rewriting it from this sweep's rows\n";
  }
  return own_view;
}

// Every point of this sweep in order, then the other rows on disk in their order. A point's row is
// this sweep's result unless that failed and the disk has an ok one; among rows on disk for one
// point (two writers), an ok one, else the last.
ResultsTable final_table(const Sweep& s, const std::vector<PointResult>& on_disk,
                         const std::map<std::string, PointResult>& fresh) {
  ResultsTable t{s.keys, {}};
  std::map<std::string, const PointResult*> old;
  std::vector<std::string> order;  // the disk's points, first appearance
  for (const PointResult& r : on_disk) {
    const std::string id = point_id(r.params);
    auto at = old.find(id);
    if (at == old.end()) {
      order.push_back(id);
      old[id] = &r;
    } else if (r.ok() || !at->second->ok()) {
      at->second = &r;
    }
  }
  for (const SweepPoint& p : s.points) {
    const std::string id = point_id(p);
    const auto mine = fresh.find(id);
    const auto theirs = old.find(id);
    if (mine != fresh.end() && (mine->second.ok() || theirs == old.end() || !theirs->second->ok()))
      t.rows.push_back(mine->second);
    else if (theirs != old.end())
      t.rows.push_back(*theirs->second);
    old.erase(id);
  }
  for (const std::string& id : order)
    if (old.count(id)) t.rows.push_back(*old.at(id));
  for (PointResult& r : t.rows) {  // in this sweep's column order
    SweepPoint ordered;
    for (const std::string& k : s.keys)
      for (const auto& kv : r.params)
        if (kv.first == k) ordered.push_back(kv);
    r.params = ordered;
  }
  return t;
}

// What a sweep's table is told about who holds it: its pid and command.
std::string holder_text(const SweepArgs& a) {
  std::string text = fmt::format("the sweep pid {} (t800sim sweep {}", getpid(), a.scene);
  for (const std::string& v : a.vary) text += " --vary " + v;
  return text + ")";
}

// A results table that is a device, a FIFO or a socket (-o /dev/stdout) is not read back (no points
// are skipped) nor appended to: the whole table is written through once, at the end.
int run_sweep(const SweepArgs& a, const Sweep& s) {
  const workloads::OutputTarget target = workloads::resolve_output(a.output, "-o");
  std::unique_ptr<TableLock> lock;
  if (target.replace)
    lock = std::make_unique<TableLock>(target.file, "-o", holder_text(a));
  else
    std::cerr << "sweep: -o " << a.output
              << " is not a regular file: the table is written to it once, at the end, and no "
                 "points are skipped\n";
  const std::vector<PointResult> earlier =
      target.replace ? earlier_results(target.file, s.keys) : std::vector<PointResult>{};
  std::set<std::string> done;
  for (const PointResult& r : earlier) done.insert(point_id(r.params));
  std::vector<SweepPoint> todo;
  for (const SweepPoint& p : s.points)
    if (!done.count(point_id(p))) todo.push_back(p);
  if (todo.size() < s.points.size())
    std::cerr << fmt::format("sweep: {} of {} points already in {}; running the other {}\n",
                             s.points.size() - todo.size(), s.points.size(), a.output, todo.size());

  // Rows are appended as points finish, so an interrupted sweep keeps them; the end rewrites the
  // table from what is on disk then, merged with this sweep's results.
  std::map<std::string, PointResult> fresh;
  if (target.replace) write_file("-o", a.output, results_csv(final_table(s, earlier, fresh)));
  std::vector<std::vector<std::string>> commands;
  for (const SweepPoint& p : todo) commands.push_back(run_argv(a, p));
  SweepProgress progress(todo.size(), isatty(STDERR_FILENO));
  ChildPool pool;
  pool.parallel = a.jobs;
  pool.timeout_s = a.timeout_s;
  pool.tick = [&] { progress.tick(); };
  pool.done = [&](std::size_t i, const ChildOutcome& outcome) {
    const PointResult r = judge(a, todo[i], outcome, nullptr);
    if (target.replace) append_row(target.file, results_row(r));
    progress.finished(r);
    fresh[point_id(r.params)] = r;
  };
  auto final_rows = [&] {
    std::vector<PointResult> own = earlier;
    for (const auto& kv : fresh) own.push_back(kv.second);
    return target.replace ? rows_on_disk(target.file, s.keys, own) : earlier;
  };
  const auto start = std::chrono::steady_clock::now();
  try {
    run_children(commands, pool);
  } catch (const Interrupted& e) {
    // The points that finished are in the file; the running ones were ended and will run again
    // when the same sweep is rerun.
    progress.end();
    write_file("-o", a.output, results_csv(final_table(s, final_rows(), fresh)));
    std::cerr << fmt::format(
        "sweep: {}; {} of {} points finished, in {}; rerun with the same -o to run "
        "the others\n",
        e.what(), fresh.size(), todo.size(), a.output);
    return 128 + e.signal;
  }
  progress.end();
  const ResultsTable table = final_table(s, final_rows(), fresh);
  write_file("-o", a.output, results_csv(table));
  const double took =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::cerr << fmt::format("sweep: {} points run ({} failed) in {}; {} rows in {}\n", todo.size(),
                           progress.failed(), clock_text(took), table.rows.size(), a.output);
  return progress.failed() ? kExitFailure : kExitOk;
}

// One emitted job: run one point and write its result (with the full report) as JSON.
int run_point(const SweepArgs& a, const Sweep& s) {
  if (a.point < 0 || std::size_t(a.point) >= s.points.size())
    throw std::invalid_argument(
        fmt::format("--point {}: this sweep has points 0 to {}", a.point, s.points.size() - 1));
  const SweepPoint& point = s.points[std::size_t(a.point)];
  // The job's directory is made here (emit_jobs names it); the file is checked before the point
  // runs.
  if (fs::path(a.output).has_parent_path())
    fs::create_directories(fs::path(a.output).parent_path());
  workloads::check_output_path(a.output, "-o");
  PointResult r;
  nlohmann::json report;
  ChildPool pool;
  pool.timeout_s = a.timeout_s;
  pool.done = [&](std::size_t, const ChildOutcome& o) { r = judge(a, point, o, &report); };
  run_children({run_argv(a, point)}, pool);
  write_file("-o", a.output, point_to_json(r, report).dump() + "\n");
  std::cerr << fmt::format("point {}: {}  {}\n", a.point, point_text(point), r.status);
  return r.ok() ? kExitOk : kExitFailure;
}

std::string shell_quote(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

// One line per point, absolute paths, so the lines run from any directory (a SLURM job, another
// host).
int emit_jobs(const SweepArgs& a, const Sweep& s) {
  const fs::path dir = fs::absolute(
      a.jobs_dir.empty() ? fs::path(a.emit_jobs).replace_extension("").string() + "-results"
                         : a.jobs_dir);
  workloads::check_output_path(a.emit_jobs, "--emit-jobs");
  fs::create_directories(dir);
  // The variable keeps SystemC's banner out of the job logs.
  std::string common = "SYSTEMC_DISABLE_COPYRIGHT_MESSAGE=1 " + shell_quote(self_executable()) +
                       " sweep " + shell_quote(fs::absolute(a.scene));
  for (const std::string& v : a.vary) common += " --vary " + shell_quote(v);
  for (const std::string& o : a.overrides) common += " --set " + shell_quote(o);
  for (const std::string& f : a.faults) common += " --fault " + shell_quote(f);
  if (a.timeout_s > 0) common += fmt::format(" --timeout {}", a.timeout_s);
  const int width = int(std::to_string(s.points.size()).size());
  std::string lines;
  for (std::size_t i = 0; i < s.points.size(); ++i)
    lines += fmt::format("{} --point {} -o {}\n", common, i,
                         shell_quote((dir / fmt::format("point-{:0{}}.json", i, width)).string()));
  write_file("--emit-jobs", a.emit_jobs, lines);
  std::cerr << fmt::format(
      "sweep: wrote {} commands to {} (results into {}/). Run them with\n"
      "  parallel -j 8 < {}            (add --sshloginfile HOSTS for machines sharing this "
      "directory)\n"
      "  or a SLURM array: sbatch --array=1-{} --wrap 'sed -n \"${{SLURM_ARRAY_TASK_ID}}p\" {} | "
      "sh'\n"
      "then: t800sim merge {} -o results.csv\n",
      s.points.size(), a.emit_jobs, dir.string(), a.emit_jobs, s.points.size(), a.emit_jobs,
      dir.string());
  return kExitOk;
}

int sweep(const SweepArgs& a) {
  if (!fs::exists(a.scene)) throw std::invalid_argument(a.scene + ": no such scene file");
  if (a.jobs < 1) throw std::invalid_argument("-j " + std::to_string(a.jobs) + ": give at least 1");
  if (a.emit_jobs.empty() && a.output.empty())
    throw std::invalid_argument(
        "-o FILE is required (or --emit-jobs FILE to write the jobs instead)");
  if (!a.emit_jobs.empty() && a.point_given)
    throw std::invalid_argument("--emit-jobs and --point exclude each other");
  // An output that cannot be written is found before any point runs.
  if (!a.emit_jobs.empty())
    workloads::check_output_path(a.emit_jobs, "--emit-jobs");
  else if (!a.point_given)
    workloads::check_output_path(a.output, "-o");
  const Sweep s = plan(a);
  check_scene(a, s);
  // Children print their reports on stdout, which must be pure JSON.
  setenv("SYSTEMC_DISABLE_COPYRIGHT_MESSAGE", "1", 1);
  if (!a.emit_jobs.empty()) return emit_jobs(a, s);
  if (a.point_given) return run_point(a, s);
  return run_sweep(a, s);
}

}  // namespace

void add_sweep_command(CLI::App& app) {
  auto a = std::make_shared<SweepArgs>();
  auto* cmd = app.add_subcommand(
      "sweep", "Run a scene over a grid of parameters, each point in its own process");
  cmd->add_option("scene", a->scene, "scene TOML file")->required();
  cmd->add_option(
         "--vary", a->vary,
         std::string("a key and its values; several --vary give their cartesian product. ") +
             vary_forms())
      ->type_name("KEY=VALUES")
      ->required();
  cmd->add_option("--set", a->overrides, "a fixed override for every point")
      ->type_name("KEY=VALUE");
  cmd->add_option("--fault", a->faults, "a fault injected into every point (as run --fault)")
      ->type_name("KEY=VALUE,...");
  cmd->add_option("-j,--jobs", a->jobs, "points run at a time (default: the number of CPUs)");
  cmd->add_option(
      "-o,--output", a->output,
      "results CSV; points already in it with status ok are not run again (with --point: the "
      "point's JSON result)");
  cmd->add_option("--timeout", a->timeout_s,
                  "seconds a point may run before it is stopped (0: no limit)")
      ->check(seconds_limit());
  cmd->add_option(
      "--emit-jobs", a->emit_jobs,
      "write one shell command per point to this file instead of running (for GNU parallel or a "
      "SLURM array); combine their results with `t800sim merge`");
  cmd->add_option("--jobs-dir", a->jobs_dir,
                  "where the emitted jobs write their JSON results (default: "
                  "the --emit-jobs file's name + -results)");
  auto* point = cmd->add_option("--point", a->point,
                                "run only point I (0-based; what each emitted job does) and write "
                                "its JSON result to -o")
                    ->check(index_from_zero());
  cmd->callback([a, point] {
    a->point_given = point->count() > 0;
    run_command([&] { return sweep(*a); });
  });
}

}  // namespace tools
