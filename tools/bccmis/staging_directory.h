// bccmis CLI: a private hidden directory beside a run's outputs that holds
// their temporaries until the run renames them into place
// (spec/distributed.md D18): what a SIGKILL leaves is this one directory,
// and a later run of the same outputs removes it once its run has ended.
#pragma once

#include <memory>
#include <string>
#include <vector>

namespace bccmis::cli {

class StagingDirectory {
 public:
  /// Makes `DIR/.NAME.staging-PID@HOST.tmp-XXXXXX` for the outputs
  /// `stem`... (DIR/NAME: `stem`'s directory, "." without one, and file
  /// name; PID and HOST: this process's), registered for removal on a
  /// signal (temporary_files.h). Throws InputError ("DIR: cannot create a
  /// temporary directory: REASON").
  static std::unique_ptr<StagingDirectory> make(const std::string& stem);
  /// Takes the directory `path` another process of the run made: registered
  /// for removal on a signal, removed on destruction when empty.
  static std::unique_ptr<StagingDirectory> adopt(const std::string& path);
  /// Removes the directory when it is empty (the last of the processes
  /// sharing it removes it).
  ~StagingDirectory();
  StagingDirectory(const StagingDirectory&) = delete;
  StagingDirectory& operator=(const StagingDirectory&) = delete;

  const std::string& path() const { return path_; }

 private:
  explicit StagingDirectory(std::string path) : path_(std::move(path)) {}
  std::string path_;
};

/// The staging directories of `stem` (StagingDirectory::make's naming) that
/// earlier runs left: one made on this host by a process that no longer
/// exists is removed with its contents; any other is left. A line for each:
/// "removed DIR, left by an interrupted run", or "DIR: left by process PID
/// on HOST, which may still be running: remove it once that run has ended".
std::vector<std::string> clean_stale_staging(const std::string& stem);

}  // namespace bccmis::cli
