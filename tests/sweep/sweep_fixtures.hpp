// Helpers for the sweep tests: a clean output directory per test, files in and out.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "../cli/cli_fixtures.hpp"
#include "tests/test_paths.hpp"
#include "tools/sweep_csv.hpp"

namespace sweep_test {

// An empty directory for one test's files (under the build tree, so nothing escapes it).
inline std::string fresh_dir() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const std::filesystem::path dir = std::filesystem::path(test_paths::binary_dir()) /
                                    "test-output" / info->test_suite_name() / info->name();
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir.string();
}

inline std::string read_file(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

inline void write_file(const std::string& path, const std::string& text) {
  std::ofstream(path) << text;
}

inline std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::stringstream s(text);
  for (std::string line; std::getline(s, line);)
    if (!line.empty()) out.push_back(line);
  return out;
}

// The table as rows of fields (header first).
inline std::vector<std::vector<std::string>> table(const std::string& path) {
  std::vector<std::vector<std::string>> rows;
  for (const std::string& line : lines(read_file(path)))
    rows.push_back(tools::parse_csv_line(line));
  return rows;
}

inline std::size_t column(const std::vector<std::vector<std::string>>& t, const std::string& name) {
  for (std::size_t i = 0; i < t.at(0).size(); ++i)
    if (t[0][i] == name) return i;
  ADD_FAILURE() << "no column " << name;
  return 0;
}

// Whether a command exits 0 (for optional tools: GNU parallel, matplotlib).
inline bool available(const std::string& command) {
  return std::system((command + " >/dev/null 2>&1").c_str()) == 0;
}

}  // namespace sweep_test
