// `t800sim stress [--quick] [--json] [--states N] [--seed S] [--robot FILE]`.
#include <iostream>
#include <memory>
#include <stdexcept>

#include <fmt/format.h>

#include "tools/commands.hpp"
#include "tools/stress.hpp"

namespace tools {

namespace {

using workloads::ResultValue;

double num(const ResultValue& v, const char* key) {
  return v.get(key)->number();
}
double num(const ResultValue& v, const char* key, const char* inner) {
  return v.get(key)->get(inner)->number();
}

std::string text_of(const ResultValue& v, const char* key) {
  const std::string json = v.get(key)->to_json();
  return json.size() >= 2 && json.front() == '"' ? json.substr(1, json.size() - 2) : json;
}

void arm_table(std::string& out, const ResultValue& arm) {
  out += fmt::format(
      "(a) Stanford arm, D q'' = -(c + h) at {} states (a fifth of the joints near a limit)\n"
      "    2-norm condition of D: min {:.3g}, median {:.3g}, max {:.3g}\n",
      num(arm, "states"), num(arm, "condition", "min"), num(arm, "condition", "median"),
      num(arm, "condition", "max"));
  out += fmt::format("    {:<17}{:<8}{:>11}{:>11}{:>11}{:>11}{:>10}{:>8}{:>9}{:>12}\n", "strategy",
                     "prec", "fwd med", "fwd max", "bwd max", "growth", "min piv", "swaps",
                     "failed", "inaccurate");
  for (const ResultValue& t : arm.get("strategies")->items()) {
    out += fmt::format(
        "    {:<17}{:<8}{:>11.2e}{:>11.2e}{:>11.2e}{:>11.3g}{:>10.2e}{:>8}{:>9}{:>12}\n",
        text_of(t, "strategy"), text_of(t, "precision"), num(t, "forward_error", "median"),
        num(t, "forward_error", "max"), num(t, "backward_error", "max"), num(t, "growth_max"),
        num(t, "smallest_relative_pivot"), num(t, "interchanges"),
        num(t, "no_pivot") + num(t, "non_finite"), num(t, "inaccurate"));
  }
}

// One cell per strategy: the largest error, and "i/s/m/f" = inaccurate / of them reported ok /
// of them below the growth check's limit / failed (reported) counts.
std::string cell(const ResultValue& t, const char* error) {
  const double failed = num(t, "no_pivot") + num(t, "non_finite");
  return fmt::format("{:8.1e} {}/{}/{}/{}", num(t, error, "max"), num(t, "inaccurate"),
                     num(t, "silent_inaccurate"), num(t, "missed_by_growth_check"), failed);
}

void strategy_header(std::string& out, const ResultValue& row, const char* first) {
  out += fmt::format("    {:<22}", first);
  for (const ResultValue& t : row.get("strategies")->items())
    out += fmt::format("{:>25}", text_of(t, "strategy") + " " + text_of(t, "precision"));
  out += "\n";
}

void sweep_table(std::string& out, const ResultValue& sweep) {
  const ResultValue& first = sweep.items().front();
  out += fmt::format(
      "\n(b) random 6x6 systems with prescribed condition ({} per row): max forward error, and "
      "counts\n"
      "    i/s/m/f: inaccurate (backward error > sqrt(u)) / of those reported ok / of those the "
      "growth\n"
      "    check (growth > 1/sqrt(u)) misses / failures reported (no pivot, non-finite)\n",
      num(first, "matrices"));
  strategy_header(out, first, "kind, condition");
  for (const ResultValue& row : sweep.items()) {
    out += fmt::format("    {:<22}",
                       fmt::format("{} {:.0e}", text_of(row, "kind"), num(row, "condition")));
    for (const ResultValue& t : row.get("strategies")->items())
      out += fmt::format("{:>25}", cell(t, "forward_error"));
    out += "\n";
  }
}

void tiny_table(std::string& out, const ResultValue& tiny) {
  const ResultValue& first = tiny.items().front();
  out += fmt::format(
      "\n(b) condition-10 systems whose k-th pivot without interchanges is delta*max|a| ({} per "
      "row):\n"
      "    max backward error, i/s/m/f as above (simple+threshold: 1e-10 REAL64, 1e-7 REAL32)\n",
      num(first, "matrices"));
  strategy_header(out, first, "step, delta");
  for (const ResultValue& row : tiny.items()) {
    out +=
        fmt::format("    {:<22}", fmt::format("k={} {:.0e}", num(row, "step"), num(row, "delta")));
    for (const ResultValue& t : row.get("strategies")->items())
      out += fmt::format("{:>25}", cell(t, "backward_error"));
    out += "\n";
  }
}

void energy_table(std::string& out, const ResultValue& energy) {
  out += "\n(c) passive trajectory from the reference state, tau = 0, dt = 1 ms: total energy\n";
  out += fmt::format("    {:<7}{:<21}{:<8}{:>6}{:>12}{:>12}{:>12}{:>14}\n", "model", "method",
                     "prec", "s", "E0 J", "max|dE| J", "|dE|/maxT", "limits left s");
  for (const ResultValue& r : energy.items()) {
    out += fmt::format("    {:<7}{:<21}{:<8}{:>6g}{:>12.6g}{:>12.3e}{:>12.3e}{:>14.3g}{}\n",
                       text_of(r, "model"), text_of(r, "method"), text_of(r, "precision"),
                       num(r, "seconds"), num(r, "e0_J"), num(r, "max_abs_drift_J"),
                       num(r, "relative_drift"), num(r, "first_limit_exit_s"),
                       text_of(r, "failure").empty() ? "" : "  FAILED: " + text_of(r, "failure"));
  }
}

}  // namespace

std::string stress_summary(const ResultValue& report) {
  std::string out = fmt::format("t800sim stress (seed {}{})\n\n", num(report, "seed"),
                                report.get("quick")->to_json() == "true" ? ", quick" : "");
  arm_table(out, *report.get("arm"));
  sweep_table(out, *report.get("condition_sweep"));
  tiny_table(out, *report.get("tiny_pivot"));
  energy_table(out, *report.get("energy"));
  out += fmt::format("\n{:.1f} s\n", num(report, "wall_s"));
  return out;
}

void add_stress_command(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "stress",
      "Numerical stability of the paper's elimination and integration: the arm's D over the joint "
      "space, random matrices of prescribed condition, tiny pivots, energy drift");
  auto options = std::make_shared<StressOptions>();
  auto json = std::make_shared<bool>(false);
  cmd->add_flag("--quick", options->quick,
                "fewer states and matrices, 1 s of trajectory (under 30 s)");
  cmd->add_flag("--json", *json, "print the report as JSON");
  cmd->add_option("--states", options->states, "arm states (default 100000, 5000 with --quick)")
      ->check(CLI::Range(1, 100000000));
  cmd->add_option("--seed", options->seed, "random seed")->capture_default_str();
  cmd->add_option("--robot", options->robot, "robot model file")->capture_default_str();
  cmd->callback([options, json] {
    run_command([&] {
      const ResultValue report = run_stress(*options);
      std::cout << (*json ? report.to_json() + "\n" : stress_summary(report));
      return kExitOk;
    });
  });
}

}  // namespace tools
