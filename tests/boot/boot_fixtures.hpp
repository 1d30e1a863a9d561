// Programs the project assembles itself (examples/iss/*.s, or text a test writes), booted with
// `t800sim boot` as a user would; the reports read back from --json.
#pragma once

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include <nlohmann/json.hpp>

#include "../cli/cli_fixtures.hpp"
#include "tests/test_paths.hpp"

namespace boot_test {

namespace fs = std::filesystem;

// A scratch directory of its own for each test, emptied: build/test-output/boot/NAME, as the cli
// tests' (cli_test::fresh_dir), so that a run leaves nothing in /tmp and a failed one's files stay
// there to look at.
inline fs::path scratch(const std::string& name) {
  const fs::path dir = fs::path(test_paths::binary_dir()) / "test-output" / "boot" / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

inline std::string read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

inline void write_text(const fs::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

// An example's source with `name = value` constants replaced.
inline std::string example_with(const std::string& example,
                                const std::vector<std::pair<std::string, std::string>>& set) {
  std::string text = read_text(fs::path(test_paths::source_dir()) / "examples/iss" / example);
  for (const auto& [name, value] : set) {
    const std::string key = "\n" + name + " = ";
    const auto at = text.find(key);
    if (at == std::string::npos) return {};
    const auto end = text.find('\n', at + 1);
    text.replace(at, end - at, key + value);
  }
  return text;
}

// `t800sim asm SOURCE -o DIR/NAME.btl`; the boot file's path (empty if it failed).
inline std::string assemble(const fs::path& dir, const std::string& name, const std::string& source,
                            const std::string& flags = "") {
  const fs::path s = dir / (name + ".s"), b = dir / (name + ".btl");
  write_text(s, source);
  const auto o = cli_test::run("asm " + s.string() + " -o " + b.string() + " " + flags + " 2>&1");
  return o.exit_code == 0 ? b.string() : std::string();
}

struct Booted {
  cli_test::Output output;
  nlohmann::json report;  // --json, when it was written
};

// Every run is bounded in host time (unless the test sets its own bound), so a program that spins
// fails its test with a report instead of holding the area until its timeout.
inline Booted boot(const fs::path& dir, const std::string& file, const std::string& flags = "") {
  Booted b;
  const fs::path json = dir / "report.json";
  fs::remove(json);
  const std::string bound =
      flags.find("--max-host-s") == std::string::npos ? " --max-host-s 60" : "";
  b.output =
      cli_test::run("boot " + file + " --json " + json.string() + bound + " " + flags + " 2>&1");
  if (fs::exists(json)) b.report = nlohmann::json::parse(read_text(json), nullptr, false);
  return b;
}

}  // namespace boot_test
