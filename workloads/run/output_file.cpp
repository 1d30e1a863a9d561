#include "workloads/run/output_file.hpp"

#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <stdexcept>

namespace workloads {

namespace {

namespace fs = std::filesystem;

bool replaceable(const std::string& path) {
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  return !fs::exists(status) || fs::is_regular_file(status);
}

// ".NAME.PID-N.tmp" beside the target: same directory, so the rename cannot cross file systems.
std::string temporary_beside(const std::string& path) {
  static std::atomic<int> counter{0};
  const fs::path target(path);
  return (target.parent_path() /
          ("." + target.filename().string() + "." + std::to_string(getpid()) + "-" +
           std::to_string(counter++) + ".tmp"))
      .string();
}

}  // namespace

OutputFile::OutputFile(std::string path, std::string what)
    : path_(std::move(path)), what_(std::move(what)) {
  if (path_.empty()) fail("no file name");
  if (fs::is_directory(path_)) fail("is a directory");
  if (replaceable(path_)) temporary_ = temporary_beside(path_);
  errno = 0;
  out_.open(temporary_.empty() ? path_ : temporary_, std::ios::binary | std::ios::trunc);
  if (!out_) fail(errno ? std::strerror(errno) : "cannot create it");
}

OutputFile::~OutputFile() {
  if (committed_ || temporary_.empty()) return;
  out_.close();
  std::error_code ignored;
  fs::remove(temporary_, ignored);
}

void OutputFile::fail(const std::string& why) const {
  throw std::runtime_error(what_ + " " + path_ + ": cannot write it (" + why + ")");
}

void OutputFile::commit() {
  errno = 0;
  out_.flush();
  if (!out_) fail(errno ? std::strerror(errno) : "write error");
  out_.close();
  if (!out_) fail(errno ? std::strerror(errno) : "write error on close");
  if (!temporary_.empty()) {
    std::error_code ec;
    fs::rename(temporary_, path_, ec);
    if (ec) fail(ec.message());
  }
  committed_ = true;
}

void write_output_file(const std::string& path, const std::string& text, const std::string& what) {
  OutputFile file(path, what);
  file.out() << text;
  file.commit();
}

void check_output_path(const std::string& path, const std::string& what) {
  if (path.empty()) return;
  if (replaceable(path)) {
    try {
      OutputFile probe(path, what);  // creates the temporary file, removed unused
    } catch (const std::runtime_error& e) {
      throw std::invalid_argument(e.what());
    }
    return;
  }
  // A device or a FIFO: opening a FIFO would wait for a reader, so ask for the permission only.
  if (access(path.c_str(), W_OK) != 0)
    throw std::invalid_argument(what + " " + path + ": cannot write it (" + std::strerror(errno) +
                                ")");
}

}  // namespace workloads
