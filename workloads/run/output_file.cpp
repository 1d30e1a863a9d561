#include "workloads/run/output_file.hpp"

#include <dirent.h>
#include <fcntl.h>
#include <signal.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/un.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <cerrno>
#include <climits>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <mutex>
#include <stdexcept>
#include <streambuf>

namespace workloads {

namespace {

namespace fs = std::filesystem;

// ---- temporary files removed on every exit the program can catch ----

// Fixed slots, so a signal handler can read them without allocating or locking: a slot's path is
// written before its state becomes kReady, and unlink() is async-signal-safe.
constexpr int kFree = 0, kClaimed = 1, kReady = 2;
struct Slot {
  std::atomic<int> state{kFree};
  char path[PATH_MAX];
};
constexpr std::size_t kSlots = 64;
std::array<Slot, kSlots> g_slots;
constexpr std::array<int, 3> kSignals = {SIGINT, SIGTERM, SIGHUP};

void remove_registered() {
  for (Slot& s : g_slots)
    if (s.state.load(std::memory_order_acquire) == kReady) unlink(s.path);
}

void remove_and_reraise(int signal) {
  remove_registered();
  std::signal(signal, SIG_DFL);
  raise(signal);  // delivered once this handler returns: the program ends by the same signal
}

// Once, at the first temporary file: a handler for each of kSignals nobody has claimed (one that
// is ignored stays ignored; a sweep's own handler, installed later, saves and restores this one).
void install_handlers() {
  static std::once_flag once;
  std::call_once(once, [] {
    std::atexit(remove_registered);
    for (int signal : kSignals) {
      struct sigaction old {};
      if (sigaction(signal, nullptr, &old) != 0) continue;
      if ((old.sa_flags & SA_SIGINFO) || old.sa_handler != SIG_DFL) continue;
      struct sigaction action {};
      action.sa_handler = remove_and_reraise;
      sigemptyset(&action.sa_mask);
      sigaction(signal, &action, nullptr);
    }
  });
}

// The slot now holding `path` (absolute), or -1 when all are taken (then only the destructor
// removes the file).
int register_temporary(const std::string& path) {
  install_handlers();
  if (path.size() >= PATH_MAX) return -1;
  for (std::size_t i = 0; i < kSlots; ++i) {
    int expected = kFree;
    if (g_slots[i].state.compare_exchange_strong(expected, kClaimed)) {
      std::memcpy(g_slots[i].path, path.c_str(), path.size() + 1);
      g_slots[i].state.store(kReady, std::memory_order_release);
      return int(i);
    }
  }
  return -1;
}

void unregister_temporary(int slot) {
  if (slot >= 0) g_slots[std::size_t(slot)].state.store(kFree, std::memory_order_release);
}

// ---- targets ----

std::string error_text(int error) {
  return std::strerror(error);
}

[[noreturn]] void refuse(const std::string& what, const std::string& path, const std::string& why) {
  throw std::invalid_argument(what + " " + path + ": cannot write it (" + why + ")");
}

// `path` with the symbolic links of its last component followed (directories on the way may be
// links too: the kernel follows those, and a rename in the final directory stays there).
std::string follow_links(const std::string& path, const std::string& what) {
  std::string p = path;
  for (int hops = 0; hops < 40; ++hops) {
    struct stat st {};
    if (lstat(p.c_str(), &st) != 0 || !S_ISLNK(st.st_mode)) return p;
    std::string target(std::size_t(PATH_MAX), '\0');
    const ssize_t n = readlink(p.c_str(), target.data(), target.size());
    if (n < 0) refuse(what, path, "cannot read the link " + p + ": " + error_text(errno));
    target.resize(std::size_t(n));
    p = fs::path(target).is_absolute() ? target : (fs::path(p).parent_path() / target).string();
  }
  refuse(what, path, "too many levels of symbolic links");
}

std::string directory_of(const std::string& file) {
  const fs::path parent = fs::path(file).parent_path();
  return parent.empty() ? "." : parent.string();
}

std::string temporary_beside(const std::string& file) {
  static std::atomic<int> counter{0};
  return (fs::path(directory_of(file)) /
          ("." + fs::path(file).filename().string() + "." + std::to_string(getpid()) + "-" +
           std::to_string(counter++) + ".tmp"))
      .string();
}

// A socket is written as a client of whoever listens on it (a stream socket).
int connect_socket(const std::string& file) {
  sockaddr_un address{};
  address.sun_family = AF_UNIX;
  if (file.size() >= sizeof(address.sun_path)) {
    errno = ENAMETOOLONG;
    return -1;
  }
  std::memcpy(address.sun_path, file.c_str(), file.size() + 1);
  const int fd = socket(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0);
  if (fd < 0) return -1;
  if (connect(fd, reinterpret_cast<const sockaddr*>(&address), sizeof(address)) != 0) {
    const int error = errno;
    close(fd);
    errno = error;
    return -1;
  }
  return fd;
}

}  // namespace

// ---- the stream: unbuffered writes of 64 KiB blocks to a file descriptor, keeping errno ----

class OutputFile::Buffer : public std::streambuf {
 public:
  explicit Buffer(int fd) : fd_(fd) { setp(block_.data(), block_.data() + block_.size()); }
  int error() const { return error_; }

 protected:
  int_type overflow(int_type c) override {
    if (!drain()) return traits_type::eof();
    if (!traits_type::eq_int_type(c, traits_type::eof())) {
      *pptr() = traits_type::to_char_type(c);
      pbump(1);
    }
    return traits_type::not_eof(c);
  }
  int sync() override { return drain() ? 0 : -1; }
  std::streamsize xsputn(const char* s, std::streamsize n) override {
    if (n < std::streamsize(block_.size())) return std::streambuf::xsputn(s, n);
    return drain() && write_all(s, std::size_t(n)) ? n : 0;
  }

 private:
  bool drain() {
    const bool ok = write_all(pbase(), std::size_t(pptr() - pbase()));
    setp(block_.data(), block_.data() + block_.size());
    return ok;
  }
  bool write_all(const char* p, std::size_t n) {
    while (n > 0 && error_ == 0) {
      const ssize_t written = ::write(fd_, p, n);
      if (written < 0 && errno == EINTR) continue;
      if (written <= 0) {
        error_ = written < 0 ? errno : EIO;
        break;
      }
      p += written;
      n -= std::size_t(written);
    }
    return error_ == 0;
  }
  int fd_;
  int error_ = 0;
  std::array<char, 65536> block_;
};

OutputTarget resolve_output(const std::string& path, const std::string& what) {
  if (path.empty()) throw std::invalid_argument(what + ": no file name given");
  OutputTarget t;
  t.file = follow_links(path, what);
  struct stat st {};
  if (stat(t.file.c_str(), &st) != 0) return t;  // missing (or unreachable: creating it says why)
  if (S_ISDIR(st.st_mode))
    refuse(what, path,
           (t.file == path ? "it is a directory" : "it links to the directory " + t.file) +
               "; give a file's path");
  t.replace = S_ISREG(st.st_mode);
  return t;
}

OutputFile::OutputFile(std::string path, std::string what)
    : path_(std::move(path)), what_(std::move(what)) {
  try {
    target_ = resolve_output(path_, what_);
  } catch (const std::invalid_argument& e) {
    throw std::runtime_error(e.what());
  }
  if (target_.replace) {
    remove_stale_temporaries(target_.file);
    struct stat old {};
    const bool existed = stat(target_.file.c_str(), &old) == 0;
    temporary_ = temporary_beside(target_.file);
    slot_ = register_temporary(fs::absolute(temporary_).string());
    fd_ = open(temporary_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd_ < 0) {
      const int error = errno;
      unregister_temporary(slot_);
      fail(error_text(error));
    }
    if (existed) fchmod(fd_, old.st_mode & 07777);  // the replacement keeps the file's permissions
  } else {
    struct stat st {};
    stat(target_.file.c_str(), &st);
    fd_ = S_ISSOCK(st.st_mode) ? connect_socket(target_.file)
                               : open(target_.file.c_str(), O_WRONLY | O_CLOEXEC | O_NOCTTY);
    if (fd_ < 0) fail(error_text(errno));
  }
  buffer_ = std::make_unique<Buffer>(fd_);
  out_ = std::make_unique<std::ostream>(buffer_.get());
}

OutputFile::~OutputFile() {
  if (fd_ >= 0) close(fd_);
  if (!committed_ && !temporary_.empty()) unlink(temporary_.c_str());
  unregister_temporary(slot_);
}

void OutputFile::fail(const std::string& why) const {
  throw std::runtime_error(what_ + " " + path_ + ": cannot write it (" + why + ")");
}

void OutputFile::commit() {
  out_->flush();
  if (buffer_->error()) fail(error_text(buffer_->error()));
  if (!*out_) fail("write error");
  const int fd = fd_;
  fd_ = -1;
  if (close(fd) != 0) fail(error_text(errno));
  if (!temporary_.empty() && rename(temporary_.c_str(), target_.file.c_str()) != 0)
    fail(error_text(errno));
  unregister_temporary(slot_);
  slot_ = -1;
  committed_ = true;
}

void write_output_file(const std::string& path, const std::string& text, const std::string& what) {
  OutputFile file(path, what);
  file.out() << text;
  file.commit();
}

void check_output_path(const std::string& path, const std::string& what) {
  if (path.empty()) return;
  const OutputTarget t = resolve_output(path, what);
  if (t.replace) {
    // A read-only file is not replaced behind its owner's back.
    if (access(t.file.c_str(), F_OK) == 0 && access(t.file.c_str(), W_OK) != 0)
      refuse(what, path, error_text(errno) + ": the file is read-only");
    try {
      OutputFile probe(path, what);  // creates the temporary file, removed unused
    } catch (const std::runtime_error& e) {
      throw std::invalid_argument(e.what());
    }
    return;
  }
  // A device, a FIFO or a socket: opening a FIFO would wait for a reader, so ask for the permission
  // only.
  if (access(t.file.c_str(), W_OK) != 0) refuse(what, path, error_text(errno));
}

ScratchFile::ScratchFile(std::string path)
    : path_(std::move(path)), slot_(register_temporary(fs::absolute(path_).string())) {}

ScratchFile::~ScratchFile() {
  unlink(path_.c_str());
  unregister_temporary(slot_);
}

void remove_stale_temporaries(const std::string& file) {
  const std::string prefix = "." + fs::path(file).filename().string() + ".";
  const std::string directory = directory_of(file);
  DIR* dir = opendir(directory.c_str());
  if (!dir) return;
  while (const dirent* entry = readdir(dir)) {
    const std::string name = entry->d_name;
    if (name.size() <= prefix.size() + 4 || name.compare(0, prefix.size(), prefix) != 0 ||
        name.compare(name.size() - 4, 4, ".tmp") != 0)
      continue;
    // PID-N between the prefix and ".tmp", digits only.
    const std::string middle = name.substr(prefix.size(), name.size() - prefix.size() - 4);
    const auto dash = middle.find('-');
    if (dash == 0 || dash == std::string::npos || dash + 1 == middle.size() ||
        middle.find_first_not_of("0123456789-") != std::string::npos ||
        middle.find('-', dash + 1) != std::string::npos || dash > 9)
      continue;
    const pid_t pid = pid_t(std::stol(middle.substr(0, dash)));
    if (pid <= 0 || pid == getpid()) continue;
    if (kill(pid, 0) == 0 || errno != ESRCH) continue;  // alive (or not ours to ask): kept
    unlinkat(dirfd(dir), entry->d_name, 0);
  }
  closedir(dir);
}

}  // namespace workloads
