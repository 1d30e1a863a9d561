#include "tests/test_paths.hpp"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace test_paths {

namespace fs = std::filesystem;

namespace {

std::string from_environment(const char* name) {
  const char* value = std::getenv(name);
  return value && *value ? std::string(value) : std::string();
}

// The configured source directory, as CMake recorded it in the build tree's cache.
std::string source_dir_of(const std::string& build) {
  std::ifstream cache(fs::path(build) / "CMakeCache.txt");
  const std::string key = "CMAKE_HOME_DIRECTORY:INTERNAL=";
  for (std::string line; std::getline(cache, line);)
    if (line.rfind(key, 0) == 0) return line.substr(key.size());
  throw std::runtime_error("tests: no T800SIM_SOURCE_DIR in the environment and no " + key +
                           " in " + build + "/CMakeCache.txt; run the tests through ctest");
}

}  // namespace

const std::string& binary_dir() {
  static const std::string dir = [] {
    std::string d = from_environment("T800SIM_BINARY_DIR");
    return d.empty() ? fs::read_symlink("/proc/self/exe").parent_path().parent_path().string() : d;
  }();
  return dir;
}

const std::string& source_dir() {
  static const std::string dir = [] {
    std::string d = from_environment("T800SIM_SOURCE_DIR");
    return d.empty() ? source_dir_of(binary_dir()) : d;
  }();
  return dir;
}

const std::string& plugin_dir() {
  static const std::string dir = [] {
    std::string d = from_environment("T800SIM_TEST_PLUGIN_DIR");
    return d.empty() ? binary_dir() + "/tests/plugins" : d;
  }();
  return dir;
}

}  // namespace test_paths
