#include "tools/table_files.hpp"

#include <ostream>

#include "workloads/run/output_file.hpp"

namespace tools {

namespace {

void write_csv(const workloads::OutputTable& table, const std::string& path) {
  workloads::OutputFile file(path, "workload." + table.param);
  std::ostream& out = file.out();
  out.precision(17);
  for (std::size_t c = 0; c < table.columns.size(); ++c) out << (c ? "," : "") << table.columns[c];
  out << '\n';
  for (const std::vector<double>& row : table.rows) {
    for (std::size_t c = 0; c < row.size(); ++c) out << (c ? "," : "") << row[c];
    out << '\n';
  }
  file.commit();
}

}  // namespace

void write_tables(const workloads::RunReport& report, const workloads::Params& params) {
  for (const workloads::OutputTable& table : report.tables) {
    const std::string& path = params.text(table.param);
    if (!path.empty()) write_csv(table, path);
  }
}

}  // namespace tools
