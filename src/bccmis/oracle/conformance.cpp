#include "bccmis/oracle/conformance.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <type_traits>
#include <variant>

#include "bccmis/d3/lattice.h"
#include "bccmis/invariants/invariants.h"
#include "bccmis/io/parse_error.h"
#include "bccmis/oracle/oracle.h"
#include "bccmis/oracle/view.h"
#include "bccmis/trace.h"

namespace bccmis {

namespace {

std::string shell_quote(const std::string& s) {
  std::string r = "'";
  for (char ch : s) r += ch == '\'' ? std::string("'\\''") : std::string(1, ch);
  return r + "'";
}

// Splits implementation output into decision lines and the state text.
void split_output(const std::string& text, std::vector<std::string>& decisions, std::string& state) {
  std::size_t pos = 0;
  while (pos < text.size()) {
    if (text.compare(pos, 13, "bccmis-state ") == 0) {
      state = text.substr(pos);
      return;
    }
    const std::size_t nl = text.find('\n', pos);
    decisions.push_back(text.substr(pos, nl == std::string::npos ? std::string::npos : nl - pos));
    if (nl == std::string::npos) break;
    pos = nl + 1;
  }
}

// A private temporary file that is removed when it goes out of scope.
class TempFile {
 public:
  explicit TempFile(const std::string& content) {
    std::string tmpl = (std::filesystem::temp_directory_path() / "bccmis-conformance-XXXXXX").string();
    const int fd = ::mkstemp(tmpl.data());
    if (fd < 0) throw std::runtime_error("cannot create a temporary trace file");
    path_ = tmpl;
    std::size_t done = 0;
    while (done < content.size()) {
      const ssize_t n = ::write(fd, content.data() + done, content.size() - done);
      if (n <= 0) break;
      done += static_cast<std::size_t>(n);
    }
    ::close(fd);
  }
  ~TempFile() { ::unlink(path_.c_str()); }
  TempFile(const TempFile&) = delete;
  TempFile& operator=(const TempFile&) = delete;
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

template <class T>
std::size_t operations(const T& t) {
  std::size_t n = 0;
  for (const auto& c : t.commands) n += c.kind != CommandKind::Check;
  return n;
}

// The reference lattice that replays a trace of type T.
template <class T>
struct reference_lattice;
template <>
struct reference_lattice<Trace> {
  using type = Graph;
};
template <>
struct reference_lattice<d3::Trace> {
  using type = d3::Graph;
};
template <class T>
using reference_lattice_t = typename reference_lattice<T>::type;

template <class L>
L parse_state_of(std::string_view text, std::string_view file) {
  if constexpr (L::dimension == 3)
    return d3::parse_state(text, file);
  else
    return parse_state(text, file);
}

template <class T>
std::string reference_output_of(const T& trace) {
  std::string log;
  const auto g = replay<reference_lattice_t<T>>(trace, log);
  return log + canonical_text(g);
}

template <class T>
std::string compare_run_of(const T& trace, const ImplRun& run) {
  using L = reference_lattice_t<T>;
  if (run.timed_out) return "the implementation timed out";
  if (run.signal != 0) return "the implementation crashed (signal " + std::to_string(run.signal) + ")";
  if (run.exit_code != 0) {
    std::string first_err = run.err.substr(0, run.err.find('\n'));
    // A shell reports a child killed by signal N as status 128 + N.
    const std::string crash = run.exit_code > 128 && run.exit_code < 160
                                  ? " (crashed: signal " + std::to_string(run.exit_code - 128) + ")"
                                  : "";
    return "the implementation exited with status " + std::to_string(run.exit_code) + crash +
           (first_err.empty() ? "" : ": " + first_err);
  }
  std::string log;
  const L expected = replay<L>(trace, log);
  std::vector<std::string> want, got;
  std::string want_state, got_state;
  split_output(log, want, want_state);
  split_output(run.out, got, got_state);
  for (std::size_t i = 0; i < std::max(want.size(), got.size()); ++i) {
    const std::string w = i < want.size() ? want[i] : "(nothing)";
    const std::string g = i < got.size() ? got[i] : "(nothing)";
    if (w != g) return "decision " + std::to_string(i + 1) + ": reference '" + w + "', implementation '" + g + "'";
  }
  const std::string expected_state = canonical_text(expected);
  if (got_state == expected_state) return "";
  if (got_state.empty()) return "the implementation printed no canonical state";
  L actual;
  try {
    actual = parse_state_of<L>(got_state, "<implementation state>");
  } catch (const ParseError& e) {
    return std::string("the implementation's state does not parse: ") + e.what();
  }
  const std::vector<std::string> d = diff_states(expected, actual);
  std::string text = "final states differ (A = reference, B = implementation):";
  for (const std::string& line : d) text += "\n  " + line;
  if (d.empty()) text += "\n  (same graph, different text: the state is not in canonical form)";
  return text;
}

// A position anywhere in the domain or just outside it.
Point random_position(const LatticeSize& size, const auto& uniform) {
  const std::int64_t S = level0_side(size);
  return {uniform(-1, size.W * S + 1), uniform(-1, size.H * S + 1)};
}
d3::Point random_position(const d3::LatticeSize& size, const auto& uniform) {
  const std::int64_t S = d3::level0_side(size);
  return {uniform(-1, size.W * S + 1), uniform(-1, size.H * S + 1), uniform(-1, size.D * S + 1)};
}

// The random trace generator of both dimensions. In 3D, where the nodes far
// outnumber the refined centers, coarsen picks a center refined earlier in
// the trace and still a node about three times in four; in 2D it picks any node.
template <class T>
T random_trace_of(std::mt19937_64& rng, int max_ops) {
  using L = reference_lattice_t<T>;
  using P = point_type_t<L>;
  auto uniform = [&](std::int64_t lo, std::int64_t hi) {
    return std::uniform_int_distribution<std::int64_t>(lo, hi)(rng);
  };
  T t;
  if constexpr (L::dimension == 3)
    t.size = {uniform(1, 3), uniform(1, 3), uniform(1, 3), static_cast<int>(uniform(1, 3))};
  else
    t.size = {uniform(1, 3), uniform(1, 3), static_cast<int>(uniform(1, 3))};
  L g(t.size);
  std::vector<P> refined;  // refined centers, in order (some may be coarsened or gone since)
  const int ops = static_cast<int>(uniform(1, std::max(1, max_ops)));
  for (int i = 0; i < ops; ++i) {
    typename T::command_type c;
    c.line = i + 2;
    const std::int64_t r = uniform(0, 99);
    auto pick = [&](const auto& s) {
      auto it = s.begin();
      std::advance(it, uniform(0, static_cast<std::int64_t>(s.size()) - 1));
      return *it;
    };
    if (r < 50) {
      c.kind = CommandKind::Refine;
      c.at = pick(cells(g));
    } else if (r < 85) {
      c.kind = CommandKind::Coarsen;
      if constexpr (L::dimension == 3) {
        std::erase_if(refined, [&](const P& p) { return !is_node(g, p); });
        c.at = !refined.empty() && r < 77 ? pick(refined) : pick(nodes(g));
      } else {
        c.at = pick(nodes(g));
      }
    } else {
      c.kind = r < 92 ? CommandKind::Refine : CommandKind::Coarsen;
      c.at = random_position(t.size, uniform);
    }
    const StepResult<L> result = step(g, c);
    if (c.kind == CommandKind::Refine && result.applied()) refined.push_back(c.at);
    t.commands.push_back(c);
  }
  return t;
}

template <class T>
T shrink_of(const T& trace, const std::function<bool(const T&)>& disagrees) {
  T best = trace;
  // Checks carry no decision; drop them first if the disagreement allows.
  {
    T t = best;
    std::erase_if(t.commands, [](const auto& c) { return c.kind == CommandKind::Check; });
    if (t.commands.size() != best.commands.size() && disagrees(t)) best = t;
  }
  // ddmin over the commands (complements of n chunks), then single removals
  // until no single command can be dropped.
  std::size_t n = 2;
  while (best.commands.size() >= 2) {
    const std::size_t len = best.commands.size();
    const std::size_t chunk = (len + n - 1) / n;
    bool reduced = false;
    for (std::size_t start = 0; start < len; start += chunk) {
      T t = best;
      t.commands.erase(t.commands.begin() + static_cast<std::ptrdiff_t>(start),
                       t.commands.begin() + static_cast<std::ptrdiff_t>(std::min(len, start + chunk)));
      if (disagrees(t)) {
        best = t;
        n = std::max<std::size_t>(n - 1, 2);
        reduced = true;
        break;
      }
    }
    if (!reduced) {
      if (n >= len) break;
      n = std::min(2 * n, len);
    }
  }
  for (bool changed = true; changed;) {
    changed = false;
    for (std::size_t i = 0; i < best.commands.size(); ++i) {
      T t = best;
      t.commands.erase(t.commands.begin() + static_cast<std::ptrdiff_t>(i));
      if (disagrees(t)) {
        best = t;
        changed = true;
        break;
      }
    }
  }
  return best;
}

}  // namespace

ImplRun run_implementation(const std::string& command, const std::string& trace_file, double timeout_seconds) {
  ImplRun run;
  int out_pipe[2], err_pipe[2];
  if (::pipe(out_pipe) != 0 || ::pipe(err_pipe) != 0) throw std::runtime_error("pipe() failed");
  const std::string full = command + " " + shell_quote(trace_file);
  const pid_t pid = ::fork();
  if (pid < 0) throw std::runtime_error("fork() failed");
  if (pid == 0) {
    ::setpgid(0, 0);  // its own process group, so a timeout kills its children too
    ::dup2(out_pipe[1], 1);
    ::dup2(err_pipe[1], 2);
    ::close(out_pipe[0]);
    ::close(err_pipe[0]);
    ::close(out_pipe[1]);
    ::close(err_pipe[1]);
    const int devnull = ::open("/dev/null", O_RDONLY);
    if (devnull >= 0) ::dup2(devnull, 0);
    ::execl("/bin/sh", "sh", "-c", full.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  ::setpgid(pid, pid);
  ::close(out_pipe[1]);
  ::close(err_pipe[1]);
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_seconds);
  pollfd fds[2] = {{out_pipe[0], POLLIN, 0}, {err_pipe[0], POLLIN, 0}};
  std::string* sinks[2] = {&run.out, &run.err};
  int open_fds = 2;
  char buf[65536];
  while (open_fds > 0) {
    const auto left =
        std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0) {
      run.timed_out = true;
      ::kill(-pid, SIGKILL);
      break;
    }
    if (::poll(fds, 2, static_cast<int>(left.count())) < 0) continue;
    for (int i = 0; i < 2; ++i) {
      if (fds[i].fd < 0 || !(fds[i].revents & (POLLIN | POLLHUP | POLLERR))) continue;
      const ssize_t n = ::read(fds[i].fd, buf, sizeof buf);
      if (n > 0) {
        sinks[i]->append(buf, static_cast<std::size_t>(n));
      } else {
        ::close(fds[i].fd);
        fds[i].fd = -1;
        --open_fds;
      }
    }
  }
  for (auto& f : fds)
    if (f.fd >= 0) ::close(f.fd);
  int status = 0;
  ::waitpid(pid, &status, 0);
  if (WIFEXITED(status)) run.exit_code = WEXITSTATUS(status);
  if (WIFSIGNALED(status)) run.signal = WTERMSIG(status);
  return run;
}

std::string reference_output(const Trace& trace) { return reference_output_of(trace); }
std::string reference_output(const d3::Trace& trace) { return reference_output_of(trace); }

std::string compare_run(const Trace& trace, const ImplRun& run) { return compare_run_of(trace, run); }
std::string compare_run(const d3::Trace& trace, const ImplRun& run) { return compare_run_of(trace, run); }

Trace random_trace(std::mt19937_64& rng, int max_ops) { return random_trace_of<Trace>(rng, max_ops); }
d3::Trace d3::random_trace(std::mt19937_64& rng, int max_ops) { return random_trace_of<d3::Trace>(rng, max_ops); }

Trace shrink(const Trace& trace, const std::function<bool(const Trace&)>& disagrees) {
  return shrink_of(trace, disagrees);
}
d3::Trace shrink(const d3::Trace& trace, const std::function<bool(const d3::Trace&)>& disagrees) {
  return shrink_of(trace, disagrees);
}

std::optional<ViewSide> implementation_side(const Trace& trace, const ImplRun& full,
                                            const std::function<std::optional<ImplRun>(const Trace&)>& rerun,
                                            bool require_state) {
  ViewSide side;
  side.title = "implementation";
  if (!require_state && full.out.find("bccmis-state ") == std::string::npos) {
    // Decisions only: compare them with the reference's final state appended.
    ImplRun with_state = full;
    std::string log;
    with_state.out += canonical_state(replay<Graph>(trace, log));
    side.message = compare_run(trace, with_state);
  } else {
    side.message = compare_run(trace, full);
  }
  if (side.message.empty()) return std::nullopt;
  side.step = trace.commands.size();
  if (full.timed_out || full.signal != 0 || full.exit_code != 0) return side;
  std::string log;
  replay<Graph>(trace, log);
  std::vector<std::string> want, got;
  std::string want_state, impl_state;
  split_output(log, want, want_state);
  split_output(full.out, got, impl_state);
  std::size_t i = 0;
  while (i < want.size() && i < got.size() && want[i] == got[i]) ++i;
  if (i < want.size() || i < got.size()) {
    // The first differing decision decides the step; the implementation's
    // state there comes from a run on the trace up to that command.
    std::size_t ops = 0;
    for (std::size_t j = 0; j < trace.commands.size(); ++j) {
      if (trace.commands[j].kind == TraceCommand::Kind::Check) continue;
      if (ops++ == i) {
        side.step = j + 1;
        side.marks.push_back(trace.commands[j].at);
        break;
      }
    }
    impl_state.clear();
    if (rerun) {
      Trace prefix = trace;
      prefix.commands.resize(side.step);
      const std::optional<ImplRun> part = rerun(prefix);
      std::vector<std::string> ignored;
      if (part && !part->timed_out && part->signal == 0 && part->exit_code == 0)
        split_output(part->out, ignored, impl_state);
    }
  }
  if (!impl_state.empty()) {
    try {
      side.state = parse_state(impl_state, "<implementation state>");
    } catch (const ParseError& e) {
      side.message += std::string("\nthe implementation's state does not parse: ") + e.what();
    }
  }
  return side;
}

std::string disagreement_page(const Trace& trace, const ConformanceOptions& o) {
  auto run = [&](const Trace& t) {
    TempFile file(format_trace(t));
    return run_implementation(o.impl, file.path(), o.timeout_seconds);
  };
  ViewOptions vo;
  vo.title = "conformance: first disagreement of '" + o.impl + "' with the reference";
  vo.check = [](const Graph& g) { return find_violation(g, 4); };
  vo.side = implementation_side(
      trace, run(trace), [&](const Trace& t) { return std::optional<ImplRun>(run(t)); }, true);
  if (vo.side) vo.open_step = vo.side->step;
  return view_trace(trace, vo).html;
}

int run_conformance(const ConformanceOptions& o, std::ostream& out) {
  if (o.impl.empty()) {
    out << "conformance: no implementation command (--impl)\n";
    return 2;
  }
  std::vector<std::pair<std::string, AnyTrace>> work;
  for (const std::string& f : o.trace_files) {
    std::ifstream in(f, std::ios::binary);
    if (!in) {
      out << "conformance: " << f << ": cannot open for reading\n";
      return 2;
    }
    std::stringstream ss;
    ss << in.rdbuf();
    try {
      work.emplace_back(f, parse_any_trace(ss.str(), f));
    } catch (const ParseError& e) {
      out << "conformance: " << e.what() << "\n";
      return 2;
    }
  }
  std::mt19937_64 rng(o.seed);
  int random3 = 0;
  for (int i = 0; i < o.random; ++i) {
    const bool three = o.dimension == TraceDimension::Three || (o.dimension == TraceDimension::Mixed && i % 2 == 1);
    const std::string name = "random " + std::string(three ? "3D" : "2D") + " trace " + std::to_string(i + 1) +
                             " (seed " + std::to_string(o.seed) + ")";
    if (three) {
      work.emplace_back(name, d3::random_trace(rng, o.max_ops));
      ++random3;
    } else {
      work.emplace_back(name, random_trace(rng, o.max_ops));
    }
  }

  auto run_on = [&](const auto& t) {
    TempFile file(format_trace(t));
    const ImplRun run = run_implementation(o.impl, file.path(), o.timeout_seconds);
    if (!run.timed_out && run.signal == 0 && (run.exit_code == 126 || run.exit_code == 127)) {
      const std::string first_err = run.err.substr(0, run.err.find('\n'));
      throw ImplementationNotRunnable("cannot run the implementation '" + o.impl + "' (exit status " +
                                      std::to_string(run.exit_code) + ", " +
                                      (run.exit_code == 127 ? "command not found" : "not executable") + ")" +
                                      (first_err.empty() ? "" : ": " + first_err));
    }
    return run;
  };
  auto run_trace = [&](const auto& t) { return compare_run(t, run_on(t)); };
  // Reports the disagreement on `trace`, if any, with its minimal trace.
  auto disagrees = [&]<class T>(const std::string& name, const T& trace) {
    const std::string problem = run_trace(trace);
    if (problem.empty()) return false;
    out << "DISAGREE on " << name << " (" << operations(trace) << " operations): " << problem << "\n";
    out << "shrinking...\n";
    const T minimal = shrink(trace, std::function<bool(const T&)>([&](const T& t) { return !run_trace(t).empty(); }));
    const std::size_t ops = operations(minimal);
    out << "minimal trace (" << ops << (ops == 1 ? " operation" : " operations") << "):\n"
        << format_trace(minimal) << "difference on the minimal trace: " << run_trace(minimal) << "\n";
    const std::string reference = reference_output(minimal);
    out << "reference output for it:\n" << reference;
    if constexpr (std::is_same_v<T, Trace>) {
      if (o.write_view) o.write_view(disagreement_page(minimal, o));
    } else if (o.write_files) {
      DisagreementFiles files;
      files.trace = format_trace(minimal);
      files.reference_state = reference.substr(reference.find("bccmis-state "));
      const ImplRun run = run_on(minimal);
      std::vector<std::string> ignored;
      if (!run.timed_out && run.signal == 0 && run.exit_code == 0) split_output(run.out, ignored, files.impl_state);
      o.write_files(files);
    }
    return true;
  };
  std::size_t agreed = 0;
  for (const auto& item : work) {
    if (std::visit([&](const auto& t) { return disagrees(item.first, t); }, item.second)) {
      out << agreed << " of " << work.size() << " traces agreed before the first disagreement\n";
      return 1;
    }
    ++agreed;
  }
  out << "conformance: all " << work.size() << " traces agree (" << o.trace_files.size() << " bundled, " << o.random
      << " random: " << o.random - random3 << " 2D and " << random3 << " 3D, seed " << o.seed << ")\n";
  return 0;
}

}  // namespace bccmis
