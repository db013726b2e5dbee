// bccmis CLI: a private hidden directory beside a run's outputs that holds
// their temporaries until the run renames them into place
// (spec/distributed.md D18): what a SIGKILL leaves is this one directory,
// and a later run of the same outputs removes it once its run has ended.
#pragma once

#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace bccmis::cli {

class StagingDirectory {
 public:
  /// Makes `DIR/.NAME.staging-PID@HOST.tmp-XXXXXX` for the outputs
  /// `stem`... (DIR/NAME: `stem`'s directory, "." without one, and file
  /// name; PID and HOST: this process's), registered for removal on a
  /// signal (temporary_files.h) and locked shared while the object lives
  /// (the lock a later run's `clean_stale_staging` looks for). Throws InputError ("DIR: cannot create a
  /// temporary directory: REASON").
  static std::unique_ptr<StagingDirectory> make(const std::string& stem);
  /// Takes the directory `path` another process of the run made: registered
  /// for removal on a signal, locked shared as `make` locks it, removed on
  /// destruction when empty.
  static std::unique_ptr<StagingDirectory> adopt(const std::string& path);
  /// Removes the directory when it is empty (the last of the processes
  /// sharing it removes it).
  ~StagingDirectory();
  StagingDirectory(const StagingDirectory&) = delete;
  StagingDirectory& operator=(const StagingDirectory&) = delete;

  const std::string& path() const { return path_; }

  /// Empty when the shared lock is held; else why it is not, for the run
  /// to print as a warning ("PATH: cannot lock the staging directory (a run
  /// of the same outputs may take it for an interrupted run's and remove
  /// it): REASON", REASON the system's strerror text of open's or flock's
  /// failure). The directory is used all the same (D18).
  const std::string& warning() const { return warning_; }

 private:
  StagingDirectory(std::string path, int lock_fd, std::string warning)
      : path_(std::move(path)), lock_fd_(lock_fd), warning_(std::move(warning)) {}
  std::string path_;
  int lock_fd_;  // holds a shared lock on the directory while the run lasts, or -1
  std::string warning_;
};

/// The staging directories of `stem` (StagingDirectory::make's naming) that
/// earlier runs left: one made on this host on which no process holds a
/// lock (every process of a run holds a shared lock on it, released by the
/// kernel when the process ends) is removed with its contents; any other is
/// left. A line for each:
/// "removed DIR, left by an interrupted run", or "DIR: left by process PID
/// on HOST, which may still be running: remove it once that run has ended".
std::vector<std::string> clean_stale_staging(const std::string& stem);

}  // namespace bccmis::cli
