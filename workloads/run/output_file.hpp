// A file a run writes (a trace, a trajectory CSV), written so that nothing is lost: the text goes
// to a temporary file in the same directory, which replaces the target by a rename only once it is
// complete, so a run killed while writing leaves the previous file intact (and at worst a stray
// temporary file). Every write error (a full disk, /dev/full) is an error. A target that is not a
// regular file (a device such as /dev/stdout, a FIFO) is written in place, since it cannot be
// replaced.
#pragma once

#include <fstream>
#include <string>

namespace workloads {

class OutputFile {
 public:
  // `what` names the file in errors ("--trace-csv", "workload.output_csv"). Throws
  // std::runtime_error when the file cannot be created.
  OutputFile(std::string path, std::string what);
  ~OutputFile();  // without commit(): removes the temporary file, the target is untouched
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;

  std::ostream& out() { return out_; }
  // Flushes, closes and renames into place; throws std::runtime_error on any write or rename error.
  void commit();

 private:
  [[noreturn]] void fail(const std::string& why) const;
  std::string path_, what_, temporary_;  // temporary_ empty: written in place
  std::ofstream out_;
  bool committed_ = false;
};

// Writes `text` to `path` through an OutputFile.
void write_output_file(const std::string& path, const std::string& text, const std::string& what);

// Before a run: throws std::invalid_argument when `path` could not be written at the end (its
// directory is missing or read-only, it is a directory), so a typo does not cost a simulation.
void check_output_path(const std::string& path, const std::string& what);

}  // namespace workloads
