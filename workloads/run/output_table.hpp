// A table of numbers a workload produces for one of its output_file parameters (a trajectory's
// rows, for workload.output_csv). The workload says what the numbers are; tools/ writes them where
// the parameter says (tools/table_files.hpp), so every written file goes through one place that
// checks paths and write errors.
#pragma once

#include <string>
#include <vector>

namespace workloads {

struct OutputTable {
  std::string param;  // the workload's output_file parameter, e.g. "output_csv"
  std::vector<std::string> columns;
  std::vector<std::vector<double>> rows;  // each as long as columns
};

}  // namespace workloads
