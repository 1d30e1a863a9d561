// The one writer of every file the program writes (traces, trajectory CSVs, sweep tables and job
// lists, VCD, reports, boot files), so that nothing it points at is damaged:
// - a regular file, or a missing one, is replaced atomically: the text goes to a temporary file
//   `.NAME.PID-N.tmp` in the same directory, renamed over the target only once it is complete, so
//   a run killed while writing leaves the previous file intact;
// - a symbolic link is followed (through any chain of links) and its target replaced atomically:
//   the link stays a link; a dangling link's target is created;
// - a device, FIFO or socket is written straight through (never renamed over or removed);
// - a directory, or a place that cannot be written, is an error naming the flag or key.
// Every write error (a full disk, /dev/full) is an error. The temporary files are removed on every
// exit the program can catch: an error (the destructor), exit(), SIGINT, SIGTERM, SIGHUP (handlers
// that remove them, then re-raise the signal); one left by a killed run (SIGKILL: `.NAME.PID-N.tmp`
// whose process is gone) is removed by the next write to the same target.
#pragma once

#include <memory>
#include <ostream>
#include <string>

namespace workloads {

// Where a write to a path lands: `file` is the path with every symbolic link of its last component
// followed; `replace` says that file is replaced by a rename (a regular or missing file), else it
// is written through (a device, a FIFO, a socket).
struct OutputTarget {
  std::string file;
  bool replace = true;
};

// Throws std::invalid_argument, naming `what` and the path, for an empty path, a directory or a
// loop of links. Nothing is created.
OutputTarget resolve_output(const std::string& path, const std::string& what);

class OutputFile {
 public:
  // `what` names the file in errors ("--trace-csv", "workload.output_csv"). Throws
  // std::runtime_error when the file cannot be created.
  OutputFile(std::string path, std::string what);
  ~OutputFile();  // without commit(): removes the temporary file, the target is untouched
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;

  std::ostream& out() { return *out_; }
  // Flushes, closes and renames into place; throws std::runtime_error on any write or rename error.
  void commit();
  const OutputTarget& target() const { return target_; }

 private:
  class Buffer;
  [[noreturn]] void fail(const std::string& why) const;
  std::string path_, what_;
  OutputTarget target_;
  std::string temporary_;  // empty: written through
  int fd_ = -1;
  int slot_ = -1;  // in the table of temporary files removed on signals
  std::unique_ptr<Buffer> buffer_;
  std::unique_ptr<std::ostream> out_;
  bool committed_ = false;
};

// Writes `text` to `path` through an OutputFile.
void write_output_file(const std::string& path, const std::string& text, const std::string& what);

// Before a run: throws std::invalid_argument when `path` could not be written at the end (its
// directory is missing or read-only, it is a directory, a device that may not be written), so a
// typo does not cost a simulation. Creates nothing that stays (a probe temporary file at most).
void check_output_path(const std::string& path, const std::string& what);

// A file of the program's own (a scratch VCD, a temporary CSV) removed when this goes out of scope,
// at exit() and on SIGINT, SIGTERM and SIGHUP, like OutputFile's temporary files.
class ScratchFile {
 public:
  explicit ScratchFile(std::string path);
  ~ScratchFile();
  ScratchFile(const ScratchFile&) = delete;
  ScratchFile& operator=(const ScratchFile&) = delete;
  const std::string& path() const { return path_; }

 private:
  std::string path_;
  int slot_;
};

// Removes the `.NAME.PID-N.tmp` files beside `file` whose process PID no longer exists (left by a
// run killed with SIGKILL). OutputFile does this for every target it replaces.
void remove_stale_temporaries(const std::string& file);

}  // namespace workloads
