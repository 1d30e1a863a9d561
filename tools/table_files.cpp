#include "tools/table_files.hpp"

#include "workloads/run/table_file.hpp"

namespace tools {

namespace {

void write_csv(const workloads::OutputTable& table, const std::string& path) {
  if (table.streamed) return table.streamed->commit();
  workloads::TableFile file(path, table.param, table.columns);
  for (const std::vector<double>& row : table.rows) file.add(row);
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
