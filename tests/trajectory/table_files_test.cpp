// Output tables (a trajectory's rows) as tools/ writes them: the header names the columns, every
// number reads back exactly (17 significant digits), a table whose parameter is empty is not
// written, and a write error names the parameter.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

#include "tests/test_files.hpp"
#include "tests/test_paths.hpp"
#include "tools/table_files.hpp"

namespace {

using test_files::read_file;

workloads::RunReport report_with(const std::vector<std::vector<double>>& rows) {
  workloads::RunReport report;
  report.tables.push_back({"output_csv", {"t", "x"}, rows, nullptr});
  return report;
}

TEST(TableFiles, NumbersReadBackExactly) {
  const std::vector<std::vector<double>> rows{{0.1, 1.0 / 3.0}, {1e-300, -2.5e17}};
  const std::string path = test_paths::binary_dir() + "/table-files-test.csv";
  workloads::Params params;
  params.set("output_csv", path);
  tools::write_tables(report_with(rows), params);
  std::istringstream csv(read_file(path));
  std::string line;
  std::getline(csv, line);
  EXPECT_EQ(line, "t,x");
  for (const auto& row : rows) {
    ASSERT_TRUE(std::getline(csv, line));
    const std::size_t comma = line.find(',');
    ASSERT_NE(comma, std::string::npos) << line;
    EXPECT_EQ(std::stod(line.substr(0, comma)), row[0]) << line;
    EXPECT_EQ(std::stod(line.substr(comma + 1)), row[1]) << line;
  }
  EXPECT_FALSE(std::getline(csv, line));
  std::remove(path.c_str());
}

TEST(TableFiles, AnEmptyPathWritesNothingAndAWriteErrorNamesTheParameter) {
  workloads::Params params;
  params.set("output_csv", std::string{});
  EXPECT_NO_THROW(tools::write_tables(report_with({{1, 2}}), params));
  params.set("output_csv", std::string{"/dev/full"});
  try {
    tools::write_tables(report_with({{1, 2}}), params);
    FAIL() << "a write to /dev/full succeeded";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("workload.output_csv /dev/full"), std::string::npos)
        << e.what();
  }
}

}  // namespace
