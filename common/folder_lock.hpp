#pragma once
// One run at a time in an output folder. The commands that write a resumable folder (calibrate,
// diagnose, study, coverage, synthesize) hold an exclusive lock on OUT/.lock (flock(2)) for the
// whole run: a second run into the same folder refuses at once and writes nothing. The kernel
// releases the lock when the process ends, however it ends, so a killed run never blocks the
// next one. A run that ends removes OUT/.lock (and OUT itself when it made it and it is empty: a
// run that failed on its input leaves no trace); a killed run leaves it behind, which is harmless.
// Under MPI only the root takes it; every rank learns the outcome (onRoot).
#include <string>

#include "common/distributed.hpp"

namespace dtwin {

class FolderLock {
 public:
  /// Creates `dir` (and OUT/.lock) when missing and locks it. When another process holds the
  /// lock: InputError(`flag` + " " + dir, "in use by another twin run (pid P, started T); wait
  /// for it or choose another folder"), on every rank. `processes` null: this process alone.
  /// An empty `dir` (no output folder) locks nothing; on a filesystem without locks (flock fails
  /// with ENOLCK, ENOSYS, EOPNOTSUPP or EINVAL) a note on stderr says so and the run goes on.
  FolderLock(const std::string& dir, const std::string& flag, const Distributed* processes);
  ~FolderLock();
  FolderLock(const FolderLock&) = delete;
  FolderLock& operator=(const FolderLock&) = delete;
  /// The lock file, OUT/.lock.
  const std::string& path() const { return path_; }

 private:
  std::string dir_, path_;
  bool created_dir_ = false;  ///< the folder did not exist before
  int fd_ = -1;               ///< open on the root while the lock is held; -1 elsewhere
};

}  // namespace dtwin
