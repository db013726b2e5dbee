#include "staging_directory.h"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <string_view>

#include "io.h"
#include "temporary_files.h"

namespace bccmis::cli {

namespace fs = std::filesystem;

namespace {

// `stem`'s directory and the prefix of its staging directories' names.
struct Naming {
  fs::path parent;     // empty: the working directory
  std::string prefix;  // ".NAME.staging-"
  fs::path dir() const { return parent.empty() ? fs::path(".") : parent; }
};

Naming naming(const std::string& stem) {
  const fs::path p(stem);
  return {p.parent_path(), "." + p.filename().string() + ".staging-"};
}

// A descriptor of the directory `path` holding a shared lock on it, or -1
// with `warning` saying why not: each process of the run holds one while the
// run lasts, and the kernel releases it when the process ends, however it
// ends (D18).
int hold_shared_lock(const std::string& path, std::string& warning) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd >= 0 && ::flock(fd, LOCK_SH) == 0) return fd;
  const int error = errno;
  if (fd >= 0) ::close(fd);
  warning = path + ": cannot lock the staging directory (a run of the same outputs may take it for an " +
            "interrupted run's and remove it): " + std::strerror(error);
  return -1;
}

// True when no process holds a lock on the directory `path`: its run has
// ended. The exclusive lock taken to find out is released at once.
bool unheld(const std::string& path) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) return false;
  const bool free = ::flock(fd, LOCK_EX | LOCK_NB) == 0;
  ::close(fd);
  return free;
}

std::string host_name() {
  char host[256] = {};
  if (::gethostname(host, sizeof host - 1) != 0) return "unknown";
  return host;
}

}  // namespace

std::unique_ptr<StagingDirectory> StagingDirectory::make(const std::string& stem) {
  const Naming n = naming(stem);
  std::string name = (n.parent / (n.prefix + std::to_string(::getpid()) + "@" + host_name() + ".tmp-XXXXXX")).string();
  if (!make_temporary_directory(name))
    throw InputError(n.dir().string() + ": cannot create a temporary directory: " + std::strerror(errno));
  std::string warning;
  const int fd = hold_shared_lock(name, warning);
  return std::unique_ptr<StagingDirectory>(new StagingDirectory(name, fd, warning));
}

std::unique_ptr<StagingDirectory> StagingDirectory::adopt(const std::string& path) {
  track_temporary_directory(path);
  std::string warning;
  const int fd = hold_shared_lock(path, warning);
  return std::unique_ptr<StagingDirectory>(new StagingDirectory(path, fd, warning));
}

StagingDirectory::~StagingDirectory() {
  ::rmdir(path_.c_str());
  untrack_temporary_directory(path_);
  if (lock_fd_ >= 0) ::close(lock_fd_);
}

std::vector<std::string> clean_stale_staging(const std::string& stem) {
  const Naming n = naming(stem);
  const std::string here = host_name();
  std::vector<std::string> lines;
  std::error_code ec;
  for (const fs::directory_entry& e : fs::directory_iterator(n.dir(), ec)) {
    const std::string name = e.path().filename().string();
    const std::size_t at = name.find('@'), tmp = name.rfind(".tmp-");
    if (name.rfind(n.prefix, 0) != 0 || at == std::string::npos || tmp == std::string::npos || tmp < at ||
        !e.is_directory(ec))
      continue;
    const std::string pid = name.substr(n.prefix.size(), at - n.prefix.size());
    const std::string host = name.substr(at + 1, tmp - at - 1);
    if (pid.empty() || pid.size() > 9 || pid.find_first_not_of("0123456789") != std::string::npos) continue;
    const bool ended = host == here && unheld((n.parent / name).string());
    if (!ended) {
      lines.push_back((n.parent / name).string() + ": left by process " + pid + " on " + host +
                      ", which may still be running: remove it once that run has ended");
      continue;
    }
    const std::string shown = (n.parent / name).string();
    std::error_code removed;
    fs::remove_all(e.path(), removed);
    lines.push_back(removed ? shown + ": left by an interrupted run, cannot remove it: " + removed.message()
                            : "removed " + shown + ", left by an interrupted run");
  }
  return lines;
}

}  // namespace bccmis::cli
