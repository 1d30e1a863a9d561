// Files the program reads (scenes, topologies, traces, tables, boot files, sources) must be regular
// files: a device such as /dev/zero would be read without end, a FIFO would block until written,
// and a file in /proc that cannot be read would look empty. One place says what may be read.
#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>

namespace network {

// What is wrong with reading `path`, without the path itself, so each caller can frame it as its
// own error ("topology file ...", "--set workload.file=..."): "no such file", "not a regular file
// (a FIFO), so it is not read", "it is N bytes; at most M are read", "it cannot be read: ...".
class InputFileError : public std::invalid_argument {
 public:
  InputFileError(const std::string& problem, bool missing)
      : std::invalid_argument(problem), missing(missing) {}
  bool missing;  // nothing is there (the rest: there, but not to be read)
};

// "" when `path` is a regular file (links followed) or missing, else why it is not read.
std::string not_regular_file(const std::string& path);

// Throws std::invalid_argument "WHAT: not a regular file (...), so it is not read; give VALID"
// unless `path` is a regular file or missing (the caller says what a missing file means).
void require_regular_input(const std::string& path, const std::string& what,
                           const std::string& valid);

// The whole text of the regular file `path`, at most `max_bytes` of it (more is an error, not
// truncation); read with read(2) so that a read error is reported, not taken for the end.
// Throws InputFileError.
std::string read_input_file(const std::string& path, std::size_t max_bytes);

}  // namespace network
