#include "tools/paper_data.hpp"

#include <cmath>
#include <filesystem>
#include <limits>
#include <stdexcept>
#include <type_traits>

#include <toml++/toml.h>

#include "network/config_error.hpp"
#include "network/toml_util.hpp"
#include "tools/child_run.hpp"

namespace tools {

namespace {

using network::ConfigError;

const toml::table& section(const toml::table& root, const std::string& name, const std::string& file) {
  const toml::table* t = root[name].as_table();
  if (!t) throw ConfigError({file, 0, 0}, "no [" + name + "] table");
  return *t;
}

// A finite number; for T = int also whole and within int's range (a count: workers, m).
template <class T>
T number(const toml::node& n, const std::string& file) {
  const auto v = n.value<double>();
  if (!v || !n.is_number())
    throw ConfigError(network::pos_of(n.source(), file), "expected a number, got " + network::type_name(n));
  if (!std::isfinite(*v)) throw ConfigError(network::pos_of(n.source(), file), "expected a finite number");
  if constexpr (std::is_same_v<T, int>) {
    if (*v != std::floor(*v) || *v < 0 || *v > std::numeric_limits<int>::max())  // found by fuzzing
      throw ConfigError(network::pos_of(n.source(), file),
                        "expected a whole number from 0 to " + std::to_string(std::numeric_limits<int>::max()));
    return static_cast<int>(*v);
  }
  return T(*v);
}

template <class T>
std::vector<T> numbers(const toml::table& t, const std::string& key, const std::string& file) {
  const toml::array* a = t[key].as_array();
  if (!a) throw ConfigError({file, 0, 0}, "'" + key + "' should be an array of numbers");
  std::vector<T> out;
  for (const toml::node& n : *a) out.push_back(number<T>(n, file));
  return out;
}

}  // namespace

PaperTables load_paper_tables(const std::string& path) {
  const toml::table root = network::parse_toml_file(path, "paper data file");
  PaperTables p;
  const toml::table& t4 = section(root, "table4", path);
  p.table4_workers = numbers<int>(t4, "workers", path);
  p.table4_tp_ms = numbers<double>(t4, "tp_ms", path);
  p.text_workers = t4["text_tp_ms"]["workers"].value_or(0);
  p.text_tp_ms = t4["text_tp_ms"]["tp_ms"].value_or(0.0);
  const toml::table& t5 = section(root, "table5", path);
  p.table5_workers = numbers<int>(t5, "workers", path);
  const toml::array* rows = t5["utilisation_pct"].as_array();
  if (!rows) throw ConfigError({path, 0, 0}, "[table5] needs utilisation_pct");
  for (const toml::node& row : *rows) {
    const toml::array* a = row.as_array();
    if (!a)
      throw ConfigError(network::pos_of(row.source(), path),
                        "[table5] utilisation_pct: expected an array of numbers per row, got " +
                            network::type_name(row));
    std::vector<double> r;
    for (const toml::node& n : *a) r.push_back(number<double>(n, path));
    p.table5_utilisation_pct.push_back(r);
  }
  const toml::table& t6 = section(root, "table6", path);
  p.table6_m = numbers<int>(t6, "m", path);
  p.table6_tp_ms = numbers<double>(t6, "tp_ms", path);
  if (p.table4_workers.size() != p.table4_tp_ms.size() || p.table6_m.size() != p.table6_tp_ms.size() ||
      p.table5_workers.size() != p.table5_utilisation_pct.size())
    throw ConfigError({path, 0, 0}, "a table's columns have different lengths");
  return p;
}

std::string find_repository_file(const std::string& relative) {
  namespace fs = std::filesystem;
  if (fs::exists(relative)) return relative;
  // An installed t800sim is PREFIX/bin/t800sim with its data in PREFIX/share/t800sim.
  const fs::path installed = fs::path(self_executable()).parent_path().parent_path() / "share" / "t800sim";
  for (const fs::path& root : {fs::path(T800SIM_SOURCE_DIR), installed})
    if (fs::exists(root / relative)) return (root / relative).string();
  throw std::invalid_argument("cannot find " + relative + " in the working directory, in " +
                              std::string(T800SIM_SOURCE_DIR) + " or in " + installed.string() +
                              "; run from the repository root");
}

}  // namespace tools
