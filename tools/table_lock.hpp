// One sweep at a time on a results table: an exclusive flock(2) on `.NAME.lock` beside the table
// (the table itself is replaced by renames, so it cannot carry the lock). A second sweep on the
// same -o waits for the first to end, saying which process holds the table; then it reads what the
// first wrote and skips the points it finished. The lock file holds the holder's pid and command
// and stays beside the table (removing it could let two sweeps hold two locks).
#pragma once

#include <string>

namespace tools {

class TableLock {
 public:
  // `table` is the table's file (links already followed); `flag` names it in messages ("-o").
  // Blocks until the lock is held (a signal ends the wait). Throws std::invalid_argument when the
  // lock file cannot be created.
  TableLock(const std::string& table, const std::string& flag, const std::string& holder);
  ~TableLock();
  TableLock(const TableLock&) = delete;
  TableLock& operator=(const TableLock&) = delete;

  // Whether the table was held by another process when this one asked (it then waited).
  bool waited() const { return waited_; }
  static std::string path_for(const std::string& table);

 private:
  int fd_ = -1;
  bool waited_ = false;
};

}  // namespace tools
