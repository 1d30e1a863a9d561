// The paper's reported tables (configs/paper/paper.toml), for comparison with simulated values.
#pragma once

#include <string>
#include <vector>

namespace tools {

struct PaperTables {
  std::vector<int> table4_workers;
  std::vector<double> table4_tp_ms;
  int text_workers = 0;  // the text's alternative value for one row of Table 4
  double text_tp_ms = 0;
  std::vector<int> table5_workers;
  std::vector<std::vector<double>> table5_utilisation_pct;
  std::vector<int> table6_m;
  std::vector<double> table6_tp_ms;
};

// Throws network::ConfigError on a missing or malformed file.
PaperTables load_paper_tables(const std::string& path);

// A repository file (e.g. "configs/paper/paper.toml") from the working directory, or else from the source
// tree t800sim was built from, or else from the installed data (share/t800sim); throws std::invalid_argument
// naming the places when none has it.
std::string find_repository_file(const std::string& relative);

}  // namespace tools
