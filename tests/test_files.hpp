// Reading a file a test (or the program it runs) wrote.
#pragma once

#include <fstream>
#include <sstream>
#include <string>

namespace test_files {

// The file's bytes ("" when it cannot be read).
inline std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace test_files
