// Runs the built t800sim executable and captures what it prints, for end-to-end tests.
#pragma once

#include <array>
#include <cstdio>
#include <string>
#include <sys/wait.h>

namespace cli_test {

struct Output {
  int exit_code = -1;
  std::string out;  // stdout and stderr, in that order when redirected with 2>&1 by the caller
};

inline Output run(const std::string& args) {
  const std::string command = "cd " T800SIM_SOURCE_DIR " && SYSTEMC_DISABLE_COPYRIGHT_MESSAGE=1 timeout 120 " +
                              std::string(T800SIM_BINARY_DIR) + "/t800sim " + args;
  Output o;
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return o;
  std::array<char, 4096> buffer;
  while (std::size_t n = fread(buffer.data(), 1, buffer.size(), pipe)) o.out.append(buffer.data(), n);
  const int status = pclose(pipe);
  o.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return o;
}

// The number after "key": in a JSON text (first occurrence), or NaN.
inline double json_number(const std::string& json, const std::string& key) {
  const auto at = json.find("\"" + key + "\":");
  if (at == std::string::npos) return 0.0 / 0.0;
  return std::stod(json.substr(at + key.size() + 3));
}

}  // namespace cli_test
