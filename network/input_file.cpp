#include "network/input_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace network {

namespace {

const char* kind_of(mode_t mode) {
  return S_ISDIR(mode)    ? "a directory"
         : S_ISFIFO(mode) ? "a FIFO"
         : S_ISSOCK(mode) ? "a socket"
                          : "a device";
}

// Closes the descriptor on every way out of read_input_file.
struct Descriptor {
  int fd;
  ~Descriptor() {
    if (fd >= 0) ::close(fd);
  }
};

}  // namespace

std::string not_regular_file(const std::string& path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0 || S_ISREG(st.st_mode)) return "";
  return std::string("not a regular file (") + kind_of(st.st_mode) + "), so it is not read";
}

void require_regular_input(const std::string& path, const std::string& what,
                           const std::string& valid) {
  const std::string problem = not_regular_file(path);
  if (!problem.empty()) throw std::invalid_argument(what + ": " + problem + "; give " + valid);
}

std::string read_input_file(const std::string& path, std::size_t max_bytes) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) throw InputFileError("no such file", true);
  if (!S_ISREG(st.st_mode)) throw InputFileError(not_regular_file(path), false);
  const auto too_long = [&](std::size_t bytes) {
    return InputFileError("it is " + std::to_string(bytes) + " bytes; at most " +
                              std::to_string(max_bytes) + " are read",
                          false);
  };
  if (std::size_t(st.st_size) > max_bytes) throw too_long(std::size_t(st.st_size));
  // The size is read again from the file itself: files in /proc report 0 and may hold more.
  const Descriptor in{::open(path.c_str(), O_RDONLY | O_CLOEXEC)};
  if (in.fd < 0)
    throw InputFileError(std::string("it cannot be opened: ") + std::strerror(errno), false);
  std::string text;
  char buffer[1 << 16];
  for (;;) {
    const ssize_t got = ::read(in.fd, buffer, sizeof buffer);
    if (got == 0) return text;
    if (got < 0) {
      if (errno == EINTR) continue;
      throw InputFileError(std::string("it cannot be read: ") + std::strerror(errno), false);
    }
    text.append(buffer, std::size_t(got));
    if (text.size() > max_bytes) throw too_long(text.size());
  }
}

}  // namespace network
