#include "bench/support/t800sim_path.hpp"

#include <unistd.h>

#include <array>
#include <climits>
#include <filesystem>
#include <stdexcept>
#include <vector>

#include <fmt/format.h>

namespace benchmarks {

namespace fs = std::filesystem;

std::string find_t800sim(const std::string& given) {
  auto runnable = [](const fs::path& p) {
    std::error_code ec;
    return fs::is_regular_file(p, ec) && access(p.c_str(), X_OK) == 0;
  };
  if (!given.empty()) {
    if (!runnable(given))
      throw std::invalid_argument("--t800sim " + given + ": no such executable file");
    return fs::absolute(given).string();
  }
  std::array<char, PATH_MAX> buffer{};
  const ssize_t n = readlink("/proc/self/exe", buffer.data(), buffer.size() - 1);
  if (n <= 0)
    throw std::invalid_argument("cannot locate this program (/proc/self/exe); give --t800sim PATH");
  const fs::path self_dir = fs::path(std::string(buffer.data(), std::size_t(n))).parent_path();
  const std::vector<fs::path> candidates{self_dir.parent_path() / "t800sim", self_dir / "t800sim"};
  for (const fs::path& p : candidates)
    if (runnable(p)) return p.string();
  throw std::invalid_argument(
      fmt::format("cannot find t800sim: looked for {} and {} (the build directory this benchmark "
                  "was built in); "
                  "build it with `cmake --build {} --target t800sim`, or give --t800sim PATH",
                  candidates[0].string(), candidates[1].string(), self_dir.parent_path().string()));
}

}  // namespace benchmarks
