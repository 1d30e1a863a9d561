// The tables a workload produced for its output files (workloads/run/output_table.hpp), written as
// CSV where the workload's output_file parameters say, each atomically (workloads/run/
// output_file.hpp): a header of the column names, then one row per line, numbers with 17
// significant digits so that they read back exactly.
#pragma once

#include "workloads/params.hpp"
#include "workloads/run/run.hpp"

namespace tools {

// Throws std::runtime_error naming the parameter (workload.<name>) and the file on a write error.
void write_tables(const workloads::RunReport& report, const workloads::Params& params);

}  // namespace tools
