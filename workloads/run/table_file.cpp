#include "workloads/run/table_file.hpp"

#include <ostream>
#include <stdexcept>

namespace workloads {

TableFile::TableFile(const std::string& path, const std::string& param,
                     const std::vector<std::string>& columns)
    : file_(path, "workload." + param), columns_(columns.size()) {
  std::ostream& out = file_.out();
  out.precision(17);
  for (std::size_t c = 0; c < columns.size(); ++c) out << (c ? "," : "") << columns[c];
  out << '\n';
}

void TableFile::add(const std::vector<double>& row) {
  if (row.size() != columns_)
    throw std::logic_error("a table row of " + std::to_string(row.size()) + " numbers under " +
                           std::to_string(columns_) + " columns");
  std::ostream& out = file_.out();
  for (std::size_t c = 0; c < row.size(); ++c) out << (c ? "," : "") << row[c];
  out << '\n';
}

void TableFile::commit() {
  file_.commit();
}

}  // namespace workloads
