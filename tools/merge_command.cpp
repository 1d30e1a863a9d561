// `t800sim merge`: the JSON results of emitted sweep jobs (files, or directories of them) -> one
// CSV table, the same as `t800sim sweep -o` writes.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>

#include <fmt/format.h>

#include "tools/commands.hpp"
#include "network/input_file.hpp"
#include "tools/sweep_result.hpp"
#include "workloads/run/output_file.hpp"

namespace tools {

namespace {

namespace fs = std::filesystem;

struct MergeArgs {
  std::vector<std::string> inputs;
  std::string output;
};

std::vector<std::string> result_files(const std::vector<std::string>& inputs) {
  std::vector<std::string> files;
  for (const std::string& in : inputs) {
    if (!fs::exists(in)) throw std::invalid_argument(in + ": no such file or directory");
    if (!fs::is_directory(in)) {
      files.push_back(in);
      continue;
    }
    std::vector<std::string> found;
    for (const auto& entry : fs::directory_iterator(in))
      if (entry.path().extension() == ".json") found.push_back(entry.path().string());
    std::sort(found.begin(),
              found.end());  // point-0001.json, point-0002.json...: the sweep's order
    files.insert(files.end(), found.begin(), found.end());
  }
  if (files.empty()) throw std::invalid_argument("no .json results found in the inputs");
  return files;
}

PointResult read_point(const std::string& file) {
  network::require_regular_input(file, file, "a JSON result written by sweep --point");
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  if (!in) throw std::invalid_argument(file + ": cannot read it");
  try {
    return point_from_json(nlohmann::json::parse(text.str()));
  } catch (const nlohmann::json::exception& e) {
    throw std::invalid_argument(file + ": not JSON (" + std::string(e.what()) + ")");
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(file + ": " + e.what());
  }
}

std::vector<std::string> keys_of(const PointResult& p) {
  std::vector<std::string> keys;
  for (const auto& kv : p.params) keys.push_back(kv.first);
  return keys;
}

int merge(const MergeArgs& a) {
  workloads::check_output_path(a.output, "-o");
  ResultsTable table;
  std::map<std::string, std::size_t>
      row_of;  // a point given twice keeps its ok result, else the last
  for (const std::string& file : result_files(a.inputs)) {
    PointResult p = read_point(file);
    if (table.rows.empty() && row_of.empty()) table.keys = keys_of(p);
    std::vector<std::string> mine = keys_of(p), first = table.keys;
    std::sort(mine.begin(), mine.end());
    std::sort(first.begin(), first.end());
    if (mine != first)
      throw std::invalid_argument(
          file + ": a point of another sweep (its parameters differ from the first file's)");
    const std::string id = point_id(p.params);
    auto at = row_of.find(id);
    if (at == row_of.end()) {
      row_of[id] = table.rows.size();
      table.rows.push_back(std::move(p));
    } else if (p.ok() || !table.rows[at->second].ok()) {
      table.rows[at->second] = std::move(p);
    }
  }
  workloads::write_output_file(a.output, results_csv(table), "-o");
  const auto failed =
      std::count_if(table.rows.begin(), table.rows.end(), [](auto& r) { return !r.ok(); });
  std::cerr << fmt::format("merge: {} points ({} failed) into {}\n", table.rows.size(), failed,
                           a.output);
  return kExitOk;
}

}  // namespace

void add_merge_command(CLI::App& app) {
  auto a = std::make_shared<MergeArgs>();
  auto* cmd =
      app.add_subcommand("merge", "Combine the JSON results of emitted sweep jobs into one CSV");
  cmd->add_option("results", a->inputs, "JSON result files, or directories holding them")
      ->required();
  cmd->add_option("-o,--output", a->output, "the CSV table to write")->required();
  cmd->callback([a] { run_command([&] { return merge(*a); }); });
}

}  // namespace tools
