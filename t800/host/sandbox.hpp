// The directory a booted program's files are confined to (SpServerOptions::root): SP.OPEN,
// SP.REMOVE and SP.RENAME name files only through it.
#pragma once

#include <cstdio>
#include <filesystem>
#include <string>

#include "t800/host/sp_protocol.hpp"

namespace t800::host {

// A name is judged twice. First by where it leads now (absolute names, "..", and symbolic links
// that lead out of the root or nowhere are refused, with SP's result for each); then it is opened
// by the kernel from a descriptor of the root with the resolution held beneath it (Linux openat2,
// RESOLVE_BENEATH), so that a symbolic link another host process swaps in between the two cannot
// lead out either: the open fails and the program is refused. REMOVE and RENAME act on the name's
// last component itself, in its directory opened the same way. Where the kernel has no openat2
// (before Linux 5.6) the first judgement is the only one, and a swapped link is not caught.
class Sandbox {
 public:
  // Throws std::invalid_argument if root is not an existing directory.
  explicit Sandbox(const std::filesystem::path& root);
  ~Sandbox();
  Sandbox(const Sandbox&) = delete;
  Sandbox& operator=(const Sandbox&) = delete;

  const std::filesystem::path& root() const { return root_; }  // canonical

  struct Opened {
    SpResult result;            // kOk with a file, or why not
    std::FILE* file = nullptr;  // the caller closes it
  };
  // fopen's mode: "r", "w", "a", "r+", "w+" or "a+".
  Opened open(const std::string& name, const char* mode) const;
  SpResult remove(const std::string& name) const;
  SpResult rename(const std::string& from, const std::string& to) const;

 private:
  std::filesystem::path root_;
  int root_fd_ = -1;
};

}  // namespace t800::host
