// Helpers for the network tests: scratch files and assertions on ConfigError positions.
#pragma once

#include <gtest/gtest.h>

#include <exception>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <string>

#include "network/config_error.hpp"
#include "tests/test_paths.hpp"

namespace nettest {

// A directory of its own for the running test, so tests can run in parallel processes.
inline std::filesystem::path scratch_dir() {
  const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
  std::filesystem::path dir = std::filesystem::path(::testing::TempDir()) / "t800sim-network" /
                              (std::string(info->test_suite_name()) + "." + info->name());
  std::filesystem::create_directories(dir);
  return dir;
}

// Writes `text` to `name` inside scratch_dir() and returns the full path.
inline std::string write_file(const std::string& name, const std::string& text) {
  const std::filesystem::path path = scratch_dir() / name;
  std::filesystem::create_directories(path.parent_path());
  std::ofstream(path, std::ios::binary) << text;
  return path.string();
}

inline std::string source_dir() {
  return test_paths::source_dir();
}

// Runs f and checks that it throws a ConfigError at (file, line, column) whose message contains
// every one of `parts`.
template <class F>
::testing::AssertionResult fails_at(F&& f, const std::string& file, int line, int column,
                                    std::initializer_list<std::string> parts) {
  try {
    f();
  } catch (const network::ConfigError& e) {
    const network::SourcePos& at = e.where();
    if (at.file != file || at.line != line || at.column != column)
      return ::testing::AssertionFailure()
             << "error at " << at.file << ":" << at.line << ":" << at.column << ", expected "
             << file << ":" << line << ":" << column << "; what(): " << e.what();
    for (const std::string& part : parts)
      if (e.message().find(part) == std::string::npos)
        return ::testing::AssertionFailure()
               << "message lacks \"" << part << "\"; what(): " << e.what();
    return ::testing::AssertionSuccess();
  } catch (const std::exception& e) {
    return ::testing::AssertionFailure() << "threw a non-ConfigError: " << e.what();
  }
  return ::testing::AssertionFailure() << "did not throw";
}

}  // namespace nettest
