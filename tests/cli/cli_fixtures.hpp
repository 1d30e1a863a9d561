// Runs the built t800sim executable and captures what it prints, for end-to-end tests.
#pragma once

#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <nlohmann/json.hpp>
#include "tests/test_files.hpp"
#include "tests/test_paths.hpp"

namespace cli_test {

// A directory of its own for the running test, emptied: build/test-output/SUITE/NAME.
inline std::string fresh_dir() {
  namespace fs = std::filesystem;
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const fs::path dir =
      fs::path(test_paths::binary_dir()) / "test-output" / info->test_suite_name() / info->name();
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir.string();
}

using test_files::read_file;

struct Output {
  int exit_code = -1;
  std::string out;  // stdout and stderr, in that order when redirected with 2>&1 by the caller
};

// The --json report a run printed (one line; messages may follow), or a discarded value if none.
inline nlohmann::json report_of(const Output& o) {
  const auto brace = o.out.find('{');
  if (brace == std::string::npos) return nlohmann::json();
  return nlohmann::json::parse(o.out.substr(brace, o.out.find('\n', brace) - brace), nullptr,
                               false);
}

inline Output run(const std::string& args) {
  const std::string command = std::string("cd ") + test_paths::source_dir() +
                              " && SYSTEMC_DISABLE_COPYRIGHT_MESSAGE=1 timeout 120 " +
                              test_paths::binary_dir() + "/t800sim " + args;
  Output o;
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return o;
  std::array<char, 4096> buffer;
  while (std::size_t n = fread(buffer.data(), 1, buffer.size(), pipe))
    o.out.append(buffer.data(), n);
  const int status = pclose(pipe);
  o.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return o;
}

// Starts `t800sim ARGS...` in the background (from the source directory, output to /dev/null) and
// returns its pid, for tests that kill a run.
inline pid_t start(const std::vector<std::string>& args) {
  const pid_t pid = fork();
  if (pid != 0) return pid;
  if (chdir(test_paths::source_dir().c_str()) != 0) _exit(127);
  const int null = open("/dev/null", O_RDWR);
  dup2(null, 0);
  dup2(null, 1);
  dup2(null, 2);
  setenv("SYSTEMC_DISABLE_COPYRIGHT_MESSAGE", "1", 1);
  std::vector<std::string> argv{test_paths::binary_dir() + "/t800sim"};
  argv.insert(argv.end(), args.begin(), args.end());
  std::vector<char*> c_argv;
  for (std::string& a : argv) c_argv.push_back(a.data());
  c_argv.push_back(nullptr);
  execv(c_argv[0], c_argv.data());
  _exit(127);
}

// The pids of a process's children (Linux /proc).
inline std::vector<pid_t> children_of(pid_t pid) {
  std::ifstream in("/proc/" + std::to_string(pid) + "/task/" + std::to_string(pid) + "/children");
  std::vector<pid_t> out;
  for (pid_t child; in >> child;) out.push_back(child);
  return out;
}

// Whether a process is gone (or a zombie nobody has reaped yet: it runs no more).
inline bool ended(pid_t pid) {
  std::ifstream in("/proc/" + std::to_string(pid) + "/stat");
  std::string line;
  if (!std::getline(in, line)) return true;
  const auto paren = line.rfind(')');
  return paren == std::string::npos || line.substr(paren + 2, 1) == "Z";
}

// Waits up to `seconds` for `done()`; returns its last value.
template <class F>
bool wait_until(F&& done, double seconds) {
  const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  while (!done()) {
    if (std::chrono::steady_clock::now() > end) return false;
    std::this_thread::sleep_for(std::chrono::microseconds(200));
  }
  return true;
}

// The number after "key": in a JSON text (first occurrence), or NaN.
inline double json_number(const std::string& json, const std::string& key) {
  const auto at = json.find("\"" + key + "\":");
  if (at == std::string::npos) return 0.0 / 0.0;
  return std::stod(json.substr(at + key.size() + 3));
}

}  // namespace cli_test
