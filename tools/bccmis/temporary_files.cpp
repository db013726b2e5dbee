#include "temporary_files.h"

#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <new>
#include <vector>

namespace bccmis::cli {

namespace {

// The registered paths, as C strings the handler can read. The list is
// changed only with the handled signals blocked, so the handler never sees
// it half-changed.
std::vector<char*>& registered() {
  static std::vector<char*> paths;
  return paths;
}

// The registered directories, removed after the files.
std::vector<char*>& directories() {
  static std::vector<char*> paths;
  return paths;
}

constexpr int kSignals[] = {SIGINT, SIGTERM, SIGHUP};

extern "C" void remove_temporaries(int sig) {
  for (char* path : registered()) ::unlink(path);
  for (char* path : directories()) ::rmdir(path);
  ::signal(sig, SIG_DFL);
  ::raise(sig);
}

void install_handler() {
  static bool installed = false;
  if (installed) return;
  installed = true;
  for (const int sig : kSignals) {
    struct sigaction old {};
    if (::sigaction(sig, nullptr, &old) != 0 || old.sa_handler == SIG_IGN) continue;
    struct sigaction action {};
    action.sa_handler = remove_temporaries;
    sigemptyset(&action.sa_mask);
    for (const int other : kSignals) sigaddset(&action.sa_mask, other);
    ::sigaction(sig, &action, nullptr);
  }
}

// Blocks the handled signals for its lifetime.
class SignalsBlocked {
 public:
  SignalsBlocked() {
    sigset_t set;
    sigemptyset(&set);
    for (const int sig : kSignals) sigaddset(&set, sig);
    ::pthread_sigmask(SIG_BLOCK, &set, &old_);
  }
  ~SignalsBlocked() { ::pthread_sigmask(SIG_SETMASK, &old_, nullptr); }
  SignalsBlocked(const SignalsBlocked&) = delete;
  SignalsBlocked& operator=(const SignalsBlocked&) = delete;

 private:
  sigset_t old_;
};

}  // namespace

int make_temporary(std::string& name) {
  SignalsBlocked blocked;
  install_handler();
  registered().reserve(registered().size() + 1);
  const int fd = ::mkstemp(name.data());
  if (fd < 0) return fd;
  char* copy = ::strdup(name.c_str());
  if (copy == nullptr) {
    ::close(fd);
    ::unlink(name.c_str());
    throw std::bad_alloc();
  }
  registered().push_back(copy);
  return fd;
}

namespace {

// Removes `path` from `paths` (with the handled signals blocked).
void untrack(std::vector<char*>& paths, const std::string& path) {
  SignalsBlocked blocked;
  const auto it = std::find_if(paths.begin(), paths.end(), [&](const char* p) { return path == p; });
  if (it == paths.end()) return;
  std::free(*it);
  paths.erase(it);
}

}  // namespace

void untrack_temporary(const std::string& path) { untrack(registered(), path); }

namespace {

// Registers the directory `path`; the handled signals are blocked by the caller.
void track_directory(const std::string& path) {
  install_handler();
  directories().reserve(directories().size() + 1);
  char* copy = ::strdup(path.c_str());
  if (copy == nullptr) throw std::bad_alloc();
  directories().push_back(copy);
}

}  // namespace

bool make_temporary_directory(std::string& name) {
  SignalsBlocked blocked;
  directories().reserve(directories().size() + 1);
  if (::mkdtemp(name.data()) == nullptr) return false;
  try {
    track_directory(name);
  } catch (...) {
    ::rmdir(name.c_str());
    throw;
  }
  return true;
}

void track_temporary_directory(const std::string& path) {
  SignalsBlocked blocked;
  track_directory(path);
}

void untrack_temporary_directory(const std::string& path) { untrack(directories(), path); }

}  // namespace bccmis::cli
