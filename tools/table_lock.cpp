#include "tools/table_lock.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <stdexcept>

namespace tools {

std::string TableLock::path_for(const std::string& table) {
  const std::filesystem::path t(table);
  return (t.parent_path() / ("." + t.filename().string() + ".lock")).string();
}

TableLock::TableLock(const std::string& table, const std::string& flag, const std::string& holder) {
  const std::string path = path_for(table);
  // Close-on-exec: the points' child processes must not hold the lock.
  fd_ = open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC | O_NOFOLLOW, 0666);
  if (fd_ < 0)
    throw std::invalid_argument(flag + " " + table + ": cannot create its lock file " + path +
                                " (" + std::strerror(errno) + ")");
  if (flock(fd_, LOCK_EX | LOCK_NB) != 0) {
    if (errno != EWOULDBLOCK) {
      const int error = errno;
      close(fd_);
      throw std::invalid_argument(flag + " " + table + ": cannot lock " + path + " (" +
                                  std::strerror(error) + ")");
    }
    char text[512] = {};
    const ssize_t n = pread(fd_, text, sizeof(text) - 1, 0);
    std::string first = n > 0 ? std::string(text, std::size_t(n)) : "another sweep";
    while (!first.empty() && (first.back() == '\n' || first.back() == ' ')) first.pop_back();
    std::cerr << "sweep: " << flag << " " << table << " is in use by " << first
              << "; waiting for it to finish (then its rows are read and its points skipped)\n";
    waited_ = true;
    while (flock(fd_, LOCK_EX) != 0) {
      if (errno == EINTR) continue;
      const int error = errno;
      close(fd_);
      throw std::invalid_argument(flag + " " + table + ": cannot lock " + path + " (" +
                                  std::strerror(error) + ")");
    }
  }
  const std::string me = holder + "\n";
  if (ftruncate(fd_, 0) == 0 && pwrite(fd_, me.data(), me.size(), 0) < 0) {
    // The description is for messages only.
  }
}

TableLock::~TableLock() {
  if (fd_ >= 0) close(fd_);  // releases the lock
}

}  // namespace tools
