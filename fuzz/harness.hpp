// What the fuzz targets feed the readers, shared with the regression test that replays the
// committed corpus (tests/fuzz): one input in, and either the reader's verdict or an exception that
// is a bug.
//
// A reader may accept an input or refuse it with a clean error: a network::ConfigError naming a
// file or a flag, or a std::invalid_argument naming a CSV file and line, each with a bounded
// message. Anything else (another exception type, an unnamed or unbounded error, a crash) is a
// finding: the harness throws it on, so libFuzzer stops there and a test fails.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <system_error>
#include <utility>

namespace fuzz {

enum class Verdict { accepted, refused };

// A configuration file. The first byte picks the reader: a scene (loaded and checked as `t800sim
// check` does: robot file, workload against the network), a topology, a robot file or the paper's
// data; the rest is the file, written into a scratch copy of configs/ so its relative paths
// resolve.
Verdict read_config(const std::uint8_t* data, std::size_t size);

// --set overrides: the first byte picks a shipped scene, the rest is one override per line.
Verdict apply_overrides(const std::uint8_t* data, std::size_t size);

// Thrown for an error that is not clean (see above).
struct Finding : std::logic_error {
  using std::logic_error::logic_error;
};

// A scratch directory of this process's, removed with what it holds when the process exits, so that
// replaying the corpus leaves nothing in /tmp (a crash leaves it, beside libFuzzer's finding).
class ScratchDirectory {
 public:
  explicit ScratchDirectory(std::filesystem::path path) : path_(std::move(path)) {}
  ScratchDirectory(const ScratchDirectory&) = delete;
  ScratchDirectory& operator=(const ScratchDirectory&) = delete;
  ~ScratchDirectory() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

}  // namespace fuzz
