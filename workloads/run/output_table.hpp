// A table of numbers a workload produces for one of its output_file parameters (an SDK program's
// table, a trajectory's rows for workload.output_csv). The workload says what the numbers are;
// tools/ writes them where the parameter says (tools/table_files.hpp), once the run has ended
// well, so every written file goes through one place that checks paths and write errors. A table
// too long to hold (a trajectory's, a row per step) is written as the run goes instead: `streamed`
// holds its rows on their way to the file, and tools/ only commits it.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "workloads/run/table_file.hpp"

namespace workloads {

struct OutputTable {
  std::string param;  // the workload's output_file parameter, e.g. "output_csv"
  std::vector<std::string> columns;
  std::vector<std::vector<double>> rows;  // each as long as columns
  std::shared_ptr<TableFile> streamed;    // else: the rows, written already (columns, rows empty)
};

}  // namespace workloads
