// A table of numbers written as CSV row by row, as a run produces it, so that a long run's table
// costs no memory (a trajectory of 10^7 steps). The one CSV format of output tables: a header of
// the column names, then one row per line, numbers with 17 significant digits so that they read
// back exactly. The file is an OutputFile: nothing replaces the target until commit(), and a run
// that ends without committing leaves the previous file as it was.
#pragma once

#include <string>
#include <vector>

#include "workloads/run/output_file.hpp"

namespace workloads {

class TableFile {
 public:
  // `param` is the workload's output_file parameter ("output_csv"): errors name workload.<param>.
  TableFile(const std::string& path, const std::string& param,
            const std::vector<std::string>& columns);
  // Throws std::logic_error for a row that is not as long as the header.
  void add(const std::vector<double>& row);
  // Throws std::runtime_error on a write error (a full disk), naming the parameter and the file.
  void commit();

 private:
  OutputFile file_;
  std::size_t columns_;
};

}  // namespace workloads
