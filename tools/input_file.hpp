// Files the program reads back (sweep tables, trace CSVs, job results) must be regular files: a
// device such as /dev/zero would be read without end, and a FIFO would block until written.
#pragma once

#include <sys/stat.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <string>

namespace tools {

// Throws std::invalid_argument naming `path` (as `what` says it, "-o out.csv") and what is valid,
// unless it is a regular file (links followed). A missing file passes: the caller says what then.
inline void require_regular_input(const std::string& path, const std::string& what,
                                  const std::string& valid) {
  struct stat st {};
  if (stat(path.c_str(), &st) != 0) return;
  if (!S_ISREG(st.st_mode))
    throw std::invalid_argument(what + ": not a regular file (" +
                                (S_ISDIR(st.st_mode)    ? "a directory"
                                 : S_ISFIFO(st.st_mode) ? "a FIFO"
                                 : S_ISSOCK(st.st_mode) ? "a socket"
                                                        : "a device") +
                                "), so it is not read; give " + valid);
}

}  // namespace tools
