#include "io.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <system_error>

#include "bccmis/d3/lattice.h"
#include "bccmis/io/parse_error.h"
#include "bccmis/trace.h"
#include "temporary_files.h"

namespace bccmis::cli {

namespace fs = std::filesystem;

namespace {

std::string errno_text(int error) { return error != 0 ? std::string(": ") + std::strerror(error) : std::string(); }

bool starts_with_state_header(std::string_view text) { return text.substr(0, 13) == "bccmis-state "; }

// A parse error with `hint` appended to its message (one line still).
ParseError with_hint(const ParseError& e, std::string_view hint) {
  return ParseError(e.file, e.line, e.column, e.message + "; " + std::string(hint));
}

}  // namespace

std::string display_name(const std::string& path) { return path == "-" ? "<stdin>" : path; }

std::string read_input(const std::string& path) {
  std::ostringstream ss;
  if (path == "-") {
    ss << std::cin.rdbuf();
    return std::move(ss).str();
  }
  std::error_code ec;
  if (fs::is_directory(path, ec)) throw InputError(path + ": is a directory, expected a file");
  errno = 0;
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": cannot open for reading" + errno_text(errno));
  ss << in.rdbuf();
  if (in.bad()) throw InputError(path + ": read error");
  return std::move(ss).str();
}

namespace {

// Parses `path` with `parse`; a canonical state given instead gets a hint.
template <class Parse>
auto read_trace_with(const std::string& path, std::string_view state_hint, const Parse& parse) {
  const std::string name = display_name(path);
  const std::string text = read_input(path);
  try {
    return parse(text, name);
  } catch (const ParseError& e) {
    if (e.line == 1 && starts_with_state_header(text))
      throw with_hint(e, "this is a canonical state, not a trace: " + std::string(state_hint));
    throw;
  }
}

// Parses `path` with `parse`; a trace given instead gets a hint.
template <class Parse>
auto read_state_with(const std::string& path, std::string_view trace_hint, const Parse& parse) {
  const std::string name = display_name(path);
  const std::string text = read_input(path);
  try {
    return parse(text, name);
  } catch (const ParseError& e) {
    if (e.line != 1 || starts_with_state_header(text)) throw;
    bool is_trace = false;
    try {
      parse_any_trace(text, name);
      is_trace = true;
    } catch (const ParseError&) {
    }
    if (is_trace) throw with_hint(e, "this is a trace, not a canonical state: " + std::string(trace_hint));
    throw;
  }
}

}  // namespace

Trace read_trace(const std::string& path, const TraceLimits& limits, std::string_view state_hint) {
  return read_trace_with(path, state_hint,
                         [&](std::string_view text, std::string_view name) { return parse_trace(text, name, limits); });
}

AnyTrace read_any_trace(const std::string& path, const TraceLimits& limits, std::string_view state_hint) {
  return read_trace_with(path, state_hint, [&](std::string_view text, std::string_view name) {
    return parse_any_trace(text, name, limits);
  });
}

Graph read_state(const std::string& path, std::string_view trace_hint) {
  return read_state_with(path, trace_hint,
                         [](std::string_view text, std::string_view name) { return parse_state(text, name); });
}

AnyState read_any_state(const std::string& path, std::string_view trace_hint) {
  return read_state_with(path, trace_hint,
                         [](std::string_view text, std::string_view name) { return parse_any_state(text, name); });
}

Graph read_state_or_trace(const std::string& path, bool from_trace) {
  if (!from_trace) return read_state(path, "give --from-trace to replay it first");
  std::string log;
  return replay<Graph>(read_trace(path, {}, "leave out --from-trace"), log);
}

AnyState read_any_state_or_trace(const std::string& path, bool from_trace) {
  if (!from_trace) return read_any_state(path, "give --from-trace to replay it first");
  std::string log;
  return std::visit(
      [&]<class T>(const T& trace) -> AnyState {
        if constexpr (std::is_same_v<T, d3::Trace>)
          return replay<d3::Graph>(trace, log);
        else
          return replay<Graph>(trace, log);
      },
      read_any_trace(path, {}, "leave out --from-trace"));
}

// ---- OutputSet ----------------------------------------------------------------

// One staged output: a temporary file holding its text. For a regular target
// (or a new file) the temporary is beside it and renamed over it at commit;
// for standard output and special files it is in the temporary directory and
// copied to them at commit.
struct OutputSet::Staged {
  std::string path;       // as given, for messages
  fs::path target;        // the file renamed over (symbolic links resolved)
  std::string temporary;  // removed on destruction unless renamed
  bool copied = false;    // copied to `path` at commit instead of renamed
  bool written = false;   // add() has written the text

  ~Staged() {
    if (temporary.empty()) return;
    ::unlink(temporary.c_str());
    untrack_temporary(temporary);
  }
};

OutputSet::OutputSet() = default;
OutputSet::~OutputSet() = default;

namespace {

// The file a path names after following symbolic links.
fs::path resolve_links(const std::string& path) {
  std::error_code ec;
  fs::path target(path);
  for (int hops = 0; fs::is_symlink(fs::symlink_status(target, ec)); ++hops) {
    const fs::path next = fs::read_symlink(target, ec);
    if (ec || hops == 40) throw InputError(path + ": cannot resolve the symbolic link");
    target = next.is_absolute() ? next : target.parent_path() / next;
  }
  return target;
}

// Writes `write`'s text into the file `temporary` (created by mkstemp);
// with `sync`, flushed to the disk. False on a write error.
bool write_file(const std::string& temporary, const Writer& write, bool sync) {
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    if (!out) return false;
    write(out);
    out.close();
    if (!out) return false;
  }
  if (!sync) return true;
  const int fd = ::open(temporary.c_str(), O_RDONLY);
  if (fd < 0) return false;
  const bool synced = ::fsync(fd) == 0;
  return ::close(fd) == 0 && synced;
}

// Copies the file `from` to the stream `to`; false on a read or write error.
bool copy_file_to(const std::string& from, std::ostream& to) {
  std::ifstream in(from, std::ios::binary);
  if (!in) return false;
  char buf[65536];
  while (in.read(buf, sizeof buf) || in.gcount() > 0) {
    to.write(buf, in.gcount());
    if (!to) return false;
  }
  return !in.bad();
}

}  // namespace

void OutputSet::stage_in(const std::string& dir) { staging_ = dir; }

void OutputSet::open(const std::string& path) {
  if (path.empty() || path == "-" || opened_.count(path) > 0) return;
  staged_.push_back(create(path));
  opened_[path] = staged_.back().get();
}

void OutputSet::add(const std::string& path, const Writer& write) {
  if (path.empty()) return;
  Staged* s = nullptr;
  if (const auto it = opened_.find(path); it != opened_.end()) {
    s = it->second;
    opened_.erase(it);
  } else {
    staged_.push_back(create(path));
    s = staged_.back().get();
  }
  errno = 0;
  if (!write_file(s->temporary, write, !s->copied)) throw InputError(path + ": write error" + errno_text(errno));
  if (!s->copied) ::chmod(s->temporary.c_str(), 0644);
  s->written = true;
}

std::unique_ptr<OutputSet::Staged> OutputSet::create(const std::string& path) {
  auto s = std::make_unique<Staged>();
  s->path = path;
  s->copied = path == "-";
  if (!s->copied) {
    std::error_code ec;
    const auto st = fs::status(path, ec);
    if (!ec && fs::exists(st) && !fs::is_regular_file(st)) {
      if (fs::is_directory(st)) throw InputError(path + ": is a directory, cannot write the output there");
      s->copied = true;
    }
  }
  fs::path dir;
  std::string stem;
  if (s->copied) {
    std::error_code ec;
    dir = fs::temp_directory_path(ec);
    if (ec) dir = "/tmp";
    stem = "bccmis-output";
  } else {
    s->target = resolve_links(path);
    dir = !staging_.empty()             ? fs::path(staging_)
          : s->target.has_parent_path() ? s->target.parent_path()
                                        : fs::path(".");
    stem = "." + s->target.filename().string();
  }
  std::string tmpl = (dir / (stem + ".tmp-XXXXXX")).string();
  const int fd = make_temporary(tmpl);
  if (fd < 0) throw InputError(path + ": cannot create a temporary file in " + dir.string() + errno_text(errno));
  ::close(fd);
  s->temporary = tmpl;
  return s;
}

void OutputSet::add(const std::string& path, std::string_view text) {
  add(path, [text](std::ostream& out) { out << text; });
}

void OutputSet::commit() {
  // First the copies (standard output, special files): they can fail late
  // (a full disk, a closed pipe), and nothing has been renamed yet.
  for (const auto& s : staged_) {
    if (!s->copied || !s->written) continue;
    if (s->path == "-") {
      std::cout.flush();
      copy_file_to(s->temporary, std::cout);
      flush_stdout();
      continue;
    }
    errno = 0;
    std::ofstream out(s->path, std::ios::binary);
    if (!copy_file_to(s->temporary, out) || !out.flush())
      throw InputError(s->path + ": write error" + errno_text(errno));
  }
  for (const auto& s : staged_) {
    if (s->copied || !s->written) continue;
    if (std::rename(s->temporary.c_str(), s->target.c_str()) != 0)
      throw InputError(s->path + ": cannot replace the file" + errno_text(errno));
    untrack_temporary(s->temporary);
    s->temporary.clear();
  }
  staged_.clear();
  opened_.clear();
}

void write_atomically(const std::string& path, const Writer& write) {
  OutputSet out;
  out.add(path, write);
  out.commit();
}

void write_atomically(const std::string& path, std::string_view text) {
  OutputSet out;
  out.add(path, text);
  out.commit();
}

void flush_stdout() {
  errno = 0;
  std::cout.flush();
  if (!std::cout) {
    const int error = errno;
    std::cout.clear();
    throw InputError("standard output: write error" + errno_text(error));
  }
}

void report(const char* tool, const char* message) { std::cerr << tool << ": " << message << "\n"; }

void require_one_stdout(const std::vector<const std::string*>& paths, const std::string& why) {
  int dashes = 0;
  for (const std::string* p : paths) dashes += *p == "-" ? 1 : 0;
  if (dashes > 1) throw InputError(why);
}

}  // namespace bccmis::cli
