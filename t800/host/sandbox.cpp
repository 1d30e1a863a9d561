// The program's files, confined to a directory (sandbox.hpp says how).
#include "t800/host/sandbox.hpp"

#include <fcntl.h>
#include <linux/openat2.h>
#include <sys/stat.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstring>
#include <stdexcept>

namespace t800::host {
namespace {

namespace fs = std::filesystem;

bool within(const fs::path& root, const fs::path& path) {
  return std::mismatch(root.begin(), root.end(), path.begin(), path.end()).first == root.end();
}

// Where a program's file name leads now, confined to the root.
struct Resolution {
  SpResult verdict;  // kOk, kError (not a name), kNoPrivilege (refused)
  fs::path path;     // kOk: relative to the root ("." for the root), every link on the way resolved
};

// Walks the name one component at a time from the canonical root, resolving each symbolic link as
// it is met, so a link anywhere on the way is judged by where it really leads. Refused: an absolute
// name, any "..", a link leading outside the root, and a link leading nowhere (creating a file
// through a dangling link would create its target, wherever that is). What does not exist yet is
// taken as it is spelt; the call then decides. With follow_last false (REMOVE, RENAME, which act
// on a link itself, as C's remove and rename do) a final link is left as it is: it lies in a
// directory inside the root, wherever it points.
Resolution resolve(const fs::path& root, const std::string& name, bool follow_last) {
  // iserver filec.c answers an empty name ER_ERROR; a NUL would cut the name short in C.
  if (name.empty() || name.find('\0') != std::string::npos) return {SpResult::kError, {}};
  const fs::path relative(name);
  if (relative.has_root_name() || relative.has_root_directory())
    return {SpResult::kNoPrivilege, {}};
  // The last component that names something ("a/b/." and "a/b/" end at b).
  auto last = relative.end();
  for (auto it = relative.begin(); it != relative.end(); ++it) {
    if (!it->empty() && it->native() != ".") last = it;
  }
  fs::path at = root;
  for (auto it = relative.begin(); it != relative.end(); ++it) {
    const std::string& part = it->native();
    if (part.empty() || part == ".") continue;
    if (part == "..") return {SpResult::kNoPrivilege, {}};
    fs::path next = at / *it;
    std::error_code error;
    const fs::file_status status = fs::symlink_status(next, error);
    if (!error && fs::is_symlink(status) && (follow_last || it != last)) {
      next = fs::canonical(next, error);  // follows every link; fails on a dangling one or a loop
      if (error) return {SpResult::kNoPrivilege, {}};
    }
    if (!within(root, next)) return {SpResult::kNoPrivilege, {}};
    at = std::move(next);
  }
  return {SpResult::kOk, at.lexically_relative(root)};
}

// openat with the path's resolution held beneath dir: no "..", absolute or magic link leads out,
// whatever the links on the way are when the kernel walks them. Before Linux 5.6 (no openat2), a
// plain openat.
int open_beneath(int dir, const fs::path& path, int flags) {
  static std::atomic<bool> have_openat2{true};
  if (have_openat2) {
    open_how how{};
    how.flags = std::uint64_t(flags | O_CLOEXEC);
    how.mode = (flags & O_CREAT) != 0 ? 0666 : 0;
    how.resolve = RESOLVE_BENEATH | RESOLVE_NO_MAGICLINKS;
    const long fd = ::syscall(SYS_openat2, dir, path.c_str(), &how, sizeof how);
    if (fd >= 0 || errno != ENOSYS) return int(fd);
    have_openat2 = false;
  }
  return ::openat(dir, path.c_str(), flags | O_CLOEXEC, 0666);
}

// What a failed open beneath the root answers: a resolution the kernel stopped is the sandbox's
// refusal (a link swapped in since the name was judged), anything else a plain failure.
SpResult failure(int error) {
  return error == EXDEV || error == ELOOP ? SpResult::kNoPrivilege : SpResult::kError;
}

int open_flags(const std::string& mode) {
  if (mode == "r") return O_RDONLY;
  if (mode == "w") return O_WRONLY | O_CREAT | O_TRUNC;
  if (mode == "a") return O_WRONLY | O_CREAT | O_APPEND;
  if (mode == "r+") return O_RDWR;
  if (mode == "w+") return O_RDWR | O_CREAT | O_TRUNC;
  if (mode == "a+") return O_RDWR | O_CREAT | O_APPEND;
  throw std::invalid_argument("Sandbox::open: '" + mode + "' is not an fopen mode");
}

// A file's directory, opened beneath the root, and its name there; a descriptor < 0 with the
// result when it cannot be.
struct Place {
  int dir = -1;
  std::string leaf;
  SpResult result = SpResult::kOk;
  Place() = default;
  Place(const Place&) = delete;
  Place& operator=(const Place&) = delete;
  ~Place() {
    if (dir >= 0) ::close(dir);
  }
};

void locate(int root_fd, const fs::path& path, Place& place) {
  const fs::path parent = path.has_parent_path() ? path.parent_path() : fs::path(".");
  place.leaf = path.filename().string();
  place.dir = open_beneath(root_fd, parent, O_PATH | O_DIRECTORY);
  if (place.dir < 0) place.result = failure(errno);
}

}  // namespace

Sandbox::Sandbox(const fs::path& root) {
  std::error_code error;
  root_ = fs::canonical(root, error);
  if (error || !fs::is_directory(root_)) {
    throw std::invalid_argument("SP server root '" + root.string() +
                                "' is not an existing directory");
  }
  root_fd_ = ::open(root_.c_str(), O_PATH | O_DIRECTORY | O_CLOEXEC);
  if (root_fd_ < 0) {
    throw std::invalid_argument("SP server root '" + root.string() +
                                "' cannot be opened: " + std::strerror(errno));
  }
}

Sandbox::~Sandbox() {
  ::close(root_fd_);
}

Sandbox::Opened Sandbox::open(const std::string& name, const char* mode) const {
  const Resolution where = resolve(root_, name, true);
  if (where.verdict != SpResult::kOk) return {where.verdict};
  const int fd = open_beneath(root_fd_, where.path, open_flags(mode));
  if (fd < 0) return {failure(errno)};
  std::FILE* file = ::fdopen(fd, mode);
  if (file == nullptr) {
    ::close(fd);
    return {SpResult::kError};
  }
  return {SpResult::kOk, file};
}

SpResult Sandbox::remove(const std::string& name) const {
  const Resolution where = resolve(root_, name, false);
  if (where.verdict != SpResult::kOk) return where.verdict;
  if (where.path == ".") return SpResult::kNoPrivilege;  // the root itself
  Place place;
  locate(root_fd_, where.path, place);
  if (place.result != SpResult::kOk) return place.result;
  struct stat status {};
  if (::fstatat(place.dir, place.leaf.c_str(), &status, AT_SYMLINK_NOFOLLOW) != 0)
    return errno == ENOENT ? SpResult::kNoFile : SpResult::kError;
  // C's remove: a file (or link) with unlink, an empty directory with rmdir.
  const int flags = S_ISDIR(status.st_mode) ? AT_REMOVEDIR : 0;
  return ::unlinkat(place.dir, place.leaf.c_str(), flags) == 0 ? SpResult::kOk : SpResult::kError;
}

SpResult Sandbox::rename(const std::string& from, const std::string& to) const {
  const Resolution old_place = resolve(root_, from, false);
  if (old_place.verdict != SpResult::kOk) return old_place.verdict;
  const Resolution new_place = resolve(root_, to, false);
  if (new_place.verdict != SpResult::kOk) return new_place.verdict;
  if (old_place.path == "." || new_place.path == ".") return SpResult::kNoPrivilege;  // the root
  Place source;
  locate(root_fd_, old_place.path, source);
  if (source.result != SpResult::kOk) return source.result;
  Place target;
  locate(root_fd_, new_place.path, target);
  if (target.result != SpResult::kOk) return target.result;
  const bool ok = ::renameat(source.dir, source.leaf.c_str(), target.dir, target.leaf.c_str()) == 0;
  return ok ? SpResult::kOk : SpResult::kError;
}

}  // namespace t800::host
