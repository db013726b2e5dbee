// bccmis: the command-line oracle. Subcommands replay traces and check states
// in the version-1 formats of spec/formats.md.
//
// Exit codes (spec/cli.md): 0 success; 1 an invariant is violated; 2 bad input
// (usage, parse error, unreadable file, unwritable output); 3 internal error.
#include <CLI/CLI.hpp>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <system_error>
#include <sys/stat.h>
#include <unistd.h>

#include "bccmis/apps/apps.h"
#include "bccmis/oracle/conformance.h"
#include "bccmis/fast/lattice_interface.h"
#include "bccmis/explore/explore.h"
#include "bccmis/format.h"
#include "bccmis/invariants/invariants.h"
#include "bccmis/oracle/oracle.h"
#include "bccmis/oracle/view.h"
#if BCCMIS_HAVE_TRIANGULATION_CHECK
#include "bccmis/invariants/cgal/triangulation_check.h"
#endif

namespace {

using namespace bccmis;

constexpr int kExitOk = 0;
constexpr int kExitViolation = 1;
constexpr int kExitInput = 2;
constexpr int kExitInternal = 3;

/// An error in the user's input; the message is complete (names file and line).
struct InputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// Reads a whole file, or standard input for "-".
std::string read_input(const std::string& path) {
  if (path == "-") {
    std::ostringstream ss;
    ss << std::cin.rdbuf();
    return ss.str();
  }
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) throw InputError(path + ": is a directory, expected a file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": cannot open for reading");
  std::ostringstream ss;
  ss << in.rdbuf();
  if (in.bad()) throw InputError(path + ": read error");
  return ss.str();
}

/// Writes `content` to `path` atomically: a temporary file in the same
/// directory, flushed, then renamed over the target. "-" means stdout. A
/// target that exists and is not a regular file (a device such as /dev/null,
/// a FIFO) is written directly: renaming over it would replace it. A symbolic
/// link is followed, so the file it points to is replaced, not the link.
void write_output(const std::string& path, const std::string& content) {
  if (path == "-") {
    std::cout << content << std::flush;
    return;
  }
  std::error_code ec;
  const auto st = std::filesystem::status(path, ec);
  if (!ec && std::filesystem::exists(st) && !std::filesystem::is_regular_file(st)) {
    if (std::filesystem::is_directory(st)) throw InputError(path + ": is a directory, cannot write the output there");
    std::ofstream out(path, std::ios::binary);
    out << content;
    out.flush();
    if (!out) throw InputError(path + ": write error");
    return;
  }
  std::filesystem::path target(path);
  for (int hops = 0; std::filesystem::is_symlink(std::filesystem::symlink_status(target, ec)); ++hops) {
    const std::filesystem::path next = std::filesystem::read_symlink(target, ec);
    if (ec || hops == 40) throw InputError(path + ": cannot resolve the symbolic link");
    target = next.is_absolute() ? next : target.parent_path() / next;
  }
  const std::filesystem::path dir = target.has_parent_path() ? target.parent_path() : std::filesystem::path(".");
  std::string tmpl = (dir / ("." + target.filename().string() + ".tmp-XXXXXX")).string();
  const int fd = ::mkstemp(tmpl.data());
  if (fd < 0) throw InputError(path + ": cannot create a temporary file in " + dir.string());
  std::size_t done = 0;
  while (done < content.size()) {
    const ssize_t n = ::write(fd, content.data() + done, content.size() - done);
    if (n <= 0) {
      ::close(fd);
      ::unlink(tmpl.c_str());
      throw InputError(path + ": write error");
    }
    done += static_cast<std::size_t>(n);
  }
  if (::fsync(fd) != 0 || ::close(fd) != 0) {
    ::unlink(tmpl.c_str());
    throw InputError(path + ": write error");
  }
  ::chmod(tmpl.c_str(), 0644);
  if (std::rename(tmpl.c_str(), target.c_str()) != 0) {
    ::unlink(tmpl.c_str());
    throw InputError(path + ": cannot replace the file");
  }
}

std::string display_name(const std::string& path) { return path == "-" ? "<stdin>" : path; }

/// Runs the checker to `depth` (5 adds the CGAL triangulation layer).
std::optional<Violation> check_graph(const Graph& g, int depth) {
  auto v = find_violation(g, depth < 5 ? depth : 4);
#if BCCMIS_HAVE_TRIANGULATION_CHECK
  if (!v && depth >= 5) v = find_triangulation_violation(g);
#endif
  return v;
}

std::string summary(const Graph& g) {
  std::map<int, std::size_t> per_level;
  for (const auto& [c, l] : g.level) ++per_level[l];
  std::string s = std::to_string(g.C.size()) + " cells (";
  bool first = true;
  for (const auto& [l, n] : per_level) {
    s += (first ? "" : ", ") + std::string("level ") + std::to_string(l) + ": " + std::to_string(n);
    first = false;
  }
  return s + "), " + std::to_string(g.N.size()) + " nodes";
}

struct ReplayOptions {
  std::string trace;
  std::string log_file;
  std::string state_file;
  std::string check = "every";
  int depth = 4;
  bool quiet = false;
  std::int64_t max_vertices = TraceLimits{}.max_vertices;
  std::string impl = "reference";
  bool json = false;
};

int run_replay(const ReplayOptions& o) {
  const std::string name = display_name(o.trace);
  TraceLimits limits;
  limits.max_vertices = o.max_vertices;
  const Trace trace = parse_trace(read_input(o.trace), name, limits);
  std::string log;
  std::size_t refines = 0, coarsens = 0, refused = 0, checks = 0;
  std::optional<std::string> failure, limit_error;
  const Graph g = [&] {
    // A violation stops the replay at the command that caused it.
    struct Stop {};
    Graph result;
    // `vertices` is |N| + |C|; `graph()` gives the state as a reference Graph.
    auto observe = [&](const TraceCommand& c, std::size_t vertices, const auto& graph, std::string_view decision) {
      if (c.kind == TraceCommand::Kind::Refine) ++refines;
      if (c.kind == TraceCommand::Kind::Coarsen) ++coarsens;
      if (decision.find(" refused ") != std::string_view::npos) ++refused;
      if (const auto v = static_cast<std::int64_t>(vertices); v > o.max_vertices) {
        limit_error = name + ":" + std::to_string(c.line) + ":1: after '" + command_text(c) + "' the lattice has " +
                      std::to_string(v) + " vertices, above the limit of " + std::to_string(o.max_vertices) +
                      " (--max-vertices)";
        throw Stop{};
      }
      const bool explicit_check = c.kind == TraceCommand::Kind::Check;
      if (explicit_check || o.check == "every") {
        ++checks;
        if (auto v = check_graph(graph(), o.depth)) {
          failure = name + ":" + std::to_string(c.line) + ": invariant violated after '" + command_text(c) +
                    "': " + to_string(*v);
          throw Stop{};
        }
      }
    };
    auto after = [&](const TraceCommand& c, const Graph& now, std::string_view decision) {
      observe(c, now.N.size() + now.C.size(), [&]() -> const Graph& { return now; }, decision);
    };
    auto after_fast = [&](const TraceCommand& c, const LatticeInterface& now, std::string_view decision) {
      observe(c, now.cell_count() + now.node_count(), [&] { return now.to_graph(); }, decision);
    };
    std::unique_ptr<LatticeInterface> fast_result;
    try {
      if (o.impl == "fast") {
        fast_result = replay(Impl::Fast, trace, log, after_fast);
        result = fast_result->to_graph();
      } else {
        result = replay(trace, log, after);
      }
    } catch (const Stop&) {
    }
    return result;
  }();
  if (limit_error) {
    std::cerr << "bccmis: " << *limit_error << "\n";
    return kExitInput;
  }
  if (failure) {
    std::cerr << "bccmis replay: " << *failure << "\n";
    if (!o.log_file.empty()) write_output(o.log_file, log);
    return kExitViolation;
  }
  if (o.check == "end") {
    ++checks;
    if (auto v = check_graph(g, o.depth)) {
      std::cerr << "bccmis replay: " << name << ": invariant violated at the end: " << to_string(*v) << "\n";
      return kExitViolation;
    }
  }
  const std::string state = canonical_state(g);
  if (o.json) {
    // One JSON object on stdout: the decisions, the canonical state and the counts.
    std::string out = "{\"trace\": " + json_string(name) + ", \"impl\": " + json_string(o.impl) + ", \"decisions\": [";
    std::size_t start = 0;
    bool first = true;
    while (start < log.size()) {
      const std::size_t nl = log.find('\n', start);
      out += (first ? "" : ", ") + json_string(std::string_view(log).substr(start, nl - start));
      first = false;
      start = nl + 1;
    }
    out += "], \"refines\": " + std::to_string(refines) + ", \"coarsens\": " + std::to_string(coarsens) +
           ", \"refused\": " + std::to_string(refused) + ", \"checks\": " + std::to_string(checks) +
           ", \"cells\": " + std::to_string(g.C.size()) + ", \"nodes\": " + std::to_string(g.N.size()) +
           ", \"state\": " + json_string(state) + "}\n";
    if (!o.log_file.empty()) write_output(o.log_file, log);
    if (!o.state_file.empty()) write_output(o.state_file, state);
    write_output("-", out);
    return kExitOk;
  }
  if (o.log_file.empty() && o.state_file.empty()) {
    write_output("-", log + state);
  } else {
    if (!o.log_file.empty()) write_output(o.log_file, log);
    write_output(o.state_file.empty() ? "-" : o.state_file, state);
  }
  if (!o.quiet)
    std::cerr << "bccmis replay: " << name << ": " << refines << " refine and " << coarsens << " coarsen commands ("
              << refused << " refused), " << checks << " checks passed (depth " << o.depth << "); final state: "
              << summary(g) << "\n";
  return kExitOk;
}

int run_check(const std::string& path, int depth, bool quiet) {
  const std::string name = display_name(path);
  const Graph g = parse_state(read_input(path), name);
  if (auto v = check_graph(g, depth)) {
    std::cerr << "bccmis check: " << name << ": " << to_string(*v) << "\n";
    return kExitViolation;
  }
  if (!quiet) std::cout << name << ": valid (depth " << depth << "): " << summary(g) << "\n";
  return kExitOk;
}

/// A state from a canonical-state file, or from a trace with --from-trace.
Graph load_state(const std::string& path, bool from_trace) {
  const std::string name = display_name(path);
  const std::string text = read_input(path);
  if (!from_trace) return parse_state(text, name);
  std::string log;
  return replay(parse_trace(text, name), log);
}

int run_diff(const std::string& a, const std::string& b, bool quiet) {
  const std::vector<std::string> d = diff_states(load_state(a, false), load_state(b, false));
  if (!quiet)
    for (const std::string& line : d) std::cout << line << "\n";
  return d.empty() ? kExitOk : kExitViolation;
}

struct ViewCliOptions {
  std::string trace;
  std::vector<std::string> states;
  std::string output;
  std::string check = "every";
  int depth = 4;
  std::int64_t step = -1;
  std::string from_log;
  std::string title;
  std::int64_t max_vertices = TraceLimits{}.max_vertices;
  bool quiet = false;
};

/// `bccmis view`: the page for a trace, or for a sequence of states.
int run_view(const ViewCliOptions& v) {
  ViewOptions o;
  if (v.check != "none") o.check = [depth = v.depth](const Graph& g) { return check_graph(g, depth); };
  o.check_last_only = v.check == "end";
  if (v.step >= 0) o.open_step = static_cast<std::size_t>(v.step);
  ViewResult r;
  if (!v.states.empty()) {
    if (!v.trace.empty()) throw InputError("view: give a trace or --states, not both");
    if (!v.from_log.empty()) throw InputError("view: --from-log needs a trace, not --states");
    std::vector<std::string> files = v.states;
    std::error_code ec;
    if (files.size() == 1 && std::filesystem::is_directory(files[0], ec)) {
      const std::string dir = files[0];
      files.clear();
      for (const auto& e : std::filesystem::directory_iterator(dir))
        if (e.path().extension() == ".state") files.push_back(e.path().string());
      std::sort(files.begin(), files.end());
      if (files.empty()) throw InputError(dir + ": no *.state files in the directory");
    }
    std::vector<std::pair<std::string, Graph>> states;
    for (const std::string& f : files) states.emplace_back(display_name(f), parse_state(read_input(f), display_name(f)));
    o.title = v.title.empty() ? "states: " + display_name(files.front()) + (files.size() > 1 ? " ... " + display_name(files.back()) : "")
                              : v.title;
    try {
      r = view_states(states, o);
    } catch (const std::invalid_argument& e) {
      throw InputError(std::string("view: ") + e.what());
    }
  } else {
    if (v.trace.empty()) throw InputError("view: give a trace file or --states (see 'bccmis view --help')");
    const std::string name = display_name(v.trace);
    o.title = v.title.empty() ? name : v.title;
    TraceLimits limits;
    limits.max_vertices = v.max_vertices;
    o.max_vertices = v.max_vertices;
    const Trace trace = parse_trace(read_input(v.trace), name, limits);
    if (!v.from_log.empty()) {
      // Another implementation's output on the trace (spec/conformance.md).
      ImplRun run;
      run.out = read_input(v.from_log);
      o.side = implementation_side(trace, run, {}, false);
      if (o.side) {
        o.side->title = display_name(v.from_log);
        if (!o.open_step) o.open_step = o.side->step;
      }
    }
    try {
      r = view_trace(trace, o);
    } catch (const ViewLimitError& e) {
      throw InputError(name + ":" + std::to_string(e.line) + ":1: " + e.what());
    } catch (const std::invalid_argument& e) {
      throw InputError(name + ": view: " + e.what());
    }
  }
  write_output(v.output, r.html);
  if (o.side) {
    std::cerr << "bccmis view: " << display_name(v.from_log) << " disagrees with the reference at step " << o.side->step
              << " (the page opens there): " << o.side->message << "\n";
    return kExitViolation;
  }
  if (r.first_violation) {
    std::cerr << "bccmis view: invariant violated at step " << *r.first_violation << " (the page opens there): "
              << r.violation << "\n";
    return kExitViolation;
  }
  if (!v.quiet && v.output != "-")
    std::cerr << "bccmis view: " << v.output << ": " << r.steps << " steps, " << r.html.size() << " bytes\n";
  return kExitOk;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"bccmis: reference implementation and oracle for Erleben's 2009 MIS graph "
               "representation of adaptive 2D BCC lattices."};
  app.set_version_flag("--version", std::string("bccmis ") + BCCMIS_VERSION);
  app.require_subcommand(1);
  app.footer(
      "Exit codes: 0 success, 1 invariant violated, 2 bad input (usage, parse error, file), 3 internal error.\n"
      "Formats: spec/formats.md. Run 'bccmis SUBCOMMAND --help' for examples.");

  const int max_depth =
#if BCCMIS_HAVE_TRIANGULATION_CHECK
      5;
#else
      4;
#endif

  ReplayOptions ro;
  CLI::App* replay_cmd = app.add_subcommand("replay", "Replay a trace; print the decision log and the canonical state.");
  replay_cmd->add_option("trace", ro.trace, "Trace file ('-' for stdin)")->required();
  replay_cmd->add_option("--log", ro.log_file, "Write the decision log to this file (atomically) instead of stdout");
  replay_cmd->add_option("--state", ro.state_file, "Write the canonical state to this file (atomically) instead of stdout");
  replay_cmd->add_option("--check", ro.check, "When to run the invariant checker: every (after each command), end, none")
      ->check(CLI::IsMember({"every", "end", "none"}))
      ->capture_default_str();
  replay_cmd->add_option("--depth", ro.depth, "Checker layers to run: 1-4, or 5 for the CGAL triangulation layer")
      ->check(CLI::Range(1, max_depth))
      ->capture_default_str();
  replay_cmd->add_flag("-q,--quiet", ro.quiet, "No summary on stderr");
  replay_cmd->add_flag("--json", ro.json, "Print one JSON object (decisions, counts, canonical state) instead of the text");
  replay_cmd->add_option("--impl", ro.impl, "Implementation to replay with: reference (the transcription) or fast")
      ->check(CLI::IsMember({"reference", "fast"}))
      ->capture_default_str();
  replay_cmd->add_option("--max-vertices", ro.max_vertices, "Refuse a trace whose lattice grows beyond this many vertices (exit 2)")
      ->check(CLI::Range(std::int64_t{1}, std::int64_t{1} << 40))
      ->capture_default_str();
  replay_cmd->footer(
      "Example:\n  bccmis replay spec/examples/fig2.trace\n  bccmis replay run.trace --check=end --log run.log --state run.state");

  std::string check_path;
  int check_depth = 4;
  bool check_quiet = false;
  CLI::App* check_cmd = app.add_subcommand("check", "Check a canonical state against every invariant.");
  check_cmd->add_option("state", check_path, "State file ('-' for stdin)")->required();
  check_cmd->add_option("--depth", check_depth, "Checker layers to run: 1-4, or 5 for the CGAL triangulation layer")
      ->check(CLI::Range(1, max_depth))
      ->capture_default_str();
  check_cmd->add_flag("-q,--quiet", check_quiet, "Print nothing when the state is valid");
  check_cmd->footer("Example:\n  bccmis replay spec/examples/fig2.trace --state fig2.state && bccmis check fig2.state");

  std::string diff_a, diff_b;
  bool diff_quiet = false;
  CLI::App* diff_cmd = app.add_subcommand("diff", "Semantic difference of two canonical states, by position.");
  diff_cmd->add_option("a", diff_a, "First state file ('-' for stdin)")->required();
  diff_cmd->add_option("b", diff_b, "Second state file")->required();
  diff_cmd->add_flag("-q,--quiet", diff_quiet, "Only the exit code: 0 equal, 1 different");
  diff_cmd->footer("Exit codes: 0 equal, 1 different, 2 bad input.\nExample:\n  bccmis diff expected.state actual.state");

  std::string stats_path;
  bool stats_json = false, stats_from_trace = false;
  CLI::App* stats_cmd = app.add_subcommand("stats", "Counts of a state: cells per level, nodes, junctions, edges, memory estimate.");
  stats_cmd->add_option("state", stats_path, "State file ('-' for stdin)")->required();
  stats_cmd->add_flag("--json", stats_json, "JSON output");
  stats_cmd->add_flag("--from-trace", stats_from_trace, "The input is a trace: replay it first");
  stats_cmd->footer("Example:\n  bccmis stats --from-trace spec/examples/fig2.trace --json");

  std::string render_path, render_out;
  bool render_from_trace = false;
  CLI::App* render_cmd = app.add_subcommand("render", "Draw a state as SVG: cells by level, stored and hull edges, junctions.");
  render_cmd->add_option("state", render_path, "State file ('-' for stdin)")->required();
  render_cmd->add_option("-o,--output", render_out, "SVG file to write (atomically); '-' for stdout")->required();
  render_cmd->add_flag("--from-trace", render_from_trace, "The input is a trace: replay it first");
  render_cmd->footer("Example:\n  bccmis render --from-trace spec/examples/fig2.trace -o fig2.svg");

  ViewCliOptions vo;
  CLI::App* view_cmd = app.add_subcommand(
      "view", "Write one self-contained HTML page that steps through a trace (or a sequence of states).");
  view_cmd->add_option("trace", vo.trace, "Trace file ('-' for stdin)");
  view_cmd->add_option("--states", vo.states,
                       "Instead of a trace: canonical state files, one per step, or one directory of *.state files "
                       "(taken in name order)");
  view_cmd->add_option("-o,--output", vo.output, "HTML file to write (atomically); '-' for stdout")->required();
  view_cmd->add_option("--check", vo.check, "When to run the invariant checker: every (each state; the page opens at the first violation), end, none")
      ->check(CLI::IsMember({"every", "end", "none"}))
      ->capture_default_str();
  view_cmd->add_option("--depth", vo.depth, "Checker layers to run: 1-4, or 5 for the CGAL triangulation layer")
      ->check(CLI::Range(1, max_depth))
      ->capture_default_str();
  view_cmd->add_option("--step", vo.step, "Open the page at this step (default: the first violation, else step 0)")
      ->check(CLI::Range(std::int64_t{0}, std::int64_t{1} << 40));
  view_cmd->add_option("--from-log", vo.from_log,
                       "Another implementation's output on the trace (decision log, optionally followed by its "
                       "canonical state, spec/conformance.md): mark the first disagreement with the reference");
  view_cmd->add_option("--title", vo.title, "Title of the page (default: the input's name)");
  view_cmd->add_option("--max-vertices", vo.max_vertices,
                       "Refuse a trace whose lattice grows beyond this many vertices (exit 2), as replay does")
      ->check(CLI::Range(std::int64_t{1}, std::int64_t{1} << 40))
      ->capture_default_str();
  view_cmd->add_flag("-q,--quiet", vo.quiet, "No summary on stderr");
  view_cmd->footer(
      "Step k shows the state after the k-th command (step 0: the initial lattice) and what the command\n"
      "touched: the refined cell c, its children Y and new junctions J+; for coarsening the removed Y and\n"
      "J-; or the refusal code. With --states, step k is the k-th state file and the page marks what\n"
      "changed. Every state is checked; the page opens at the first violation with the offending\n"
      "vertices marked. Controls: slider, buttons, arrow keys; the URL fragment #step=K opens step K.\n"
      "With --from-log, the page opens at the first decision that differs from the log (or, when they\n"
      "all agree, at the last step with the log's final state beside the reference's, differences marked).\n"
      "Exit codes: 0 page written, 1 page written and a state violates an invariant or the log\n"
      "disagrees, 2 bad input.\n"
      "The embedded model is specified in spec/viewer.md.\n"
      "Example:\n  bccmis view spec/examples/fig2.trace -o fig2.html\n"
      "  bccmis view --states my-impl-states/ -o states.html   # 0000.state, 0001.state, ...\n"
      "  ./my-lattice run.trace > run.out; bccmis view run.trace --from-log run.out -o run.html");

  ConformanceOptions co;
  std::string co_traces;
  CLI::App* conf_cmd = app.add_subcommand(
      "conformance", "Check another implementation against the reference: decisions and final states, with shrinking.");
  conf_cmd->add_option("--impl", co.impl, "Command to run; the trace file path is appended (spec/conformance.md)")->required();
  conf_cmd->add_option("--traces", co_traces, "Directory of bundled *.trace files to run first");
  conf_cmd->add_option("--random", co.random, "Number of random traces")->check(CLI::Range(0, 1000000))->capture_default_str();
  conf_cmd->add_option("--seed", co.seed, "Seed of the random traces")->capture_default_str();
  conf_cmd->add_option("--max-ops", co.max_ops, "Operations per random trace")->check(CLI::Range(1, 100000))->capture_default_str();
  conf_cmd->add_option("--timeout", co.timeout_seconds, "Seconds per run of the implementation")
      ->check(CLI::Range(0.01, 86400.0))
      ->capture_default_str();
  std::string co_view;
  conf_cmd->add_option("--view", co_view,
                       "On a disagreement, write a viewer page (bccmis view) for the minimal trace: the reference "
                       "and the implementation's state side by side at the first disagreement");
  conf_cmd->footer(
      "Exit codes: 0 all agree, 1 disagreement (the minimal trace is printed), 2 harness error.\n"
      "Example:\n  bccmis conformance --impl './my-lattice replay' --traces spec/examples --random 200 --seed 7\n"
      "  bccmis conformance --impl './my-lattice replay' --random 200 --view disagreement.html");

  LatticeSize ex_size;
  bool ex_json = false, ex_no_progress = false;
  ExploreOptions ex;
  CLI::App* explore_cmd = app.add_subcommand(
      "explore", "Breadth-first search over every state reachable from a lattice: check each, try every operation.");
  explore_cmd->add_option("W", ex_size.W, "Level-0 cells across")->required();
  explore_cmd->add_option("H", ex_size.H, "Level-0 cells up")->required();
  explore_cmd->add_option("L", ex_size.L, "Maximum level")->required();
  explore_cmd->add_option("--depth", ex.check_depth, "Checker layers on every state (0-4)")
      ->check(CLI::Range(0, 4))
      ->capture_default_str();
  explore_cmd->add_option("--max-states", ex.max_states, "Stop after this many states (0: no limit)")->capture_default_str();
  explore_cmd->add_option("--threads", ex.threads, "Worker threads (0: one per core)")->capture_default_str();
  explore_cmd->add_flag("--json", ex_json, "One line of JSON instead of the summary");
  explore_cmd->add_flag("--no-progress", ex_no_progress, "No progress line on stderr");
  explore_cmd->footer(
      "Exit codes: 0 every state valid and every inverse exact, 1 a failure (a reproducing trace is printed), "
      "2 bad input.\nExample:\n  bccmis explore 1 1 2        # 17 states\n  bccmis explore 2 2 2 --json");

  HeightfieldOptions hf;
  CLI::App* hf_cmd = app.add_subcommand("heightfield", "Tessellate a height-field image adaptively (the paper's §3, Fig. 4-5).");
  hf_cmd->add_option("input", hf.input, "PGM (P2/P5, 8/16-bit) or PNG image; '-' for stdin")->required();
  hf_cmd->add_option("-W,--width", hf.width, "Initial lattice width in level-0 cells")->capture_default_str();
  hf_cmd->add_option("-H,--height", hf.height, "Initial lattice height in level-0 cells")->capture_default_str();
  hf_cmd->add_option("-L,--max-level", hf.max_level, "Maximum refinement level")->capture_default_str();
  hf_cmd->add_option("--vertical-scale", hf.vertical_scale, "Height of a full-scale pixel")->capture_default_str();
  hf_cmd->add_option("-t,--tolerance", hf.tolerance, "Refine cells whose error is above this")->capture_default_str();
  hf_cmd->add_option("--measure", hf.measure, "Cell error: max (every pixel, exact) or samples (the paper's)")
      ->check(CLI::IsMember({"max", "samples"}))
      ->capture_default_str();
  hf_cmd->add_option("--samples", hf.samples, "Random points per cell for --measure=samples")->capture_default_str();
  hf_cmd->add_option("--seed", hf.seed, "Seed of --measure=samples")->capture_default_str();
  hf_cmd->add_option("--balance", hf.balance, "2:1 rule: edge (the core's) or corner")
      ->check(CLI::IsMember({"edge", "corner"}))
      ->capture_default_str();
  hf_cmd->add_option("--impl", hf.impl, "Lattice implementation: reference or fast (same output, faster)")
      ->check(CLI::IsMember({"reference", "fast"}))
      ->capture_default_str();
  hf_cmd->add_option("--sweeps", hf.sweeps, "Number of sweeps; 0 = until nothing changes")->capture_default_str();
  hf_cmd->add_option("--from", hf.from, "Start from this canonical state (incremental re-tessellation)");
  hf_cmd->add_option("--obj", hf.obj, "Write a Wavefront OBJ mesh");
  hf_cmd->add_option("--ply", hf.ply, "Write an ASCII PLY mesh");
  hf_cmd->add_option("--vtu", hf.vtu, "Write a VTK .vtu (level and error as cell data)");
  hf_cmd->add_option("--svg", hf.svg, "Write an SVG top view");
  hf_cmd->add_option("--state", hf.state, "Write the final canonical state");
  hf_cmd->add_option("--stats", hf.stats, "Where the statistics go ('-' = stdout)")->capture_default_str();
  hf_cmd->add_flag("--json", hf.json, "Statistics as JSON");
  hf_cmd->add_flag("--check", hf.check, "Run the invariant checker after every sweep");
  hf_cmd->add_option("--progress", hf.progress, "Progress lines on stderr: auto, always, never")
      ->check(CLI::IsMember({"auto", "always", "never"}))
      ->capture_default_str();
  hf_cmd->add_flag("-q,--quiet", hf.quiet, "No summary line on stderr");
  hf_cmd->footer("Example:\n  bccmis heightfield apps/samples/terrain128.pgm --tolerance 0.02 --obj terrain.obj --svg terrain.svg");

  AnimateOptions an;
  CLI::App* an_cmd = app.add_subcommand("animate", "A disk moves along a path; the lattice adapts around it (the paper's Fig. 6).");
  an_cmd->add_option("-W,--width", an.width, "Lattice width in level-0 cells")->capture_default_str();
  an_cmd->add_option("-H,--height", an.height, "Lattice height in level-0 cells")->capture_default_str();
  an_cmd->add_option("-L,--max-level", an.max_level, "Maximum refinement level")->capture_default_str();
  an_cmd->add_option("--target-level", an.target_level, "Level of the cells the feature meets; -1 = L")->capture_default_str();
  an_cmd->add_option("--radius", an.radius, "Feature radius in level-0 cell units")->capture_default_str();
  an_cmd->add_option("--path", an.path, "Path 'x,y;x,y;...' in level-0 cell units")->capture_default_str();
  an_cmd->add_option("--balance", an.balance, "2:1 rule: edge or corner")
      ->check(CLI::IsMember({"edge", "corner"}))
      ->capture_default_str();
  an_cmd->add_option("--frames", an.frames, "Number of frames")->capture_default_str();
  an_cmd->add_option("--impl", an.impl, "Lattice implementation: reference or fast (same output, faster)")
      ->check(CLI::IsMember({"reference", "fast"}))
      ->capture_default_str();
  an_cmd->add_flag("--lift", an.lift, "One more frame without the feature at the end");
  an_cmd->add_option("--svg-dir", an.svg_dir, "Write frame_NNNN.svg into this existing directory");
  an_cmd->add_option("--state", an.state, "Write the final canonical state");
  an_cmd->add_option("--stats", an.stats, "Where the per-frame statistics go ('-' = stdout)")->capture_default_str();
  an_cmd->add_flag("--json", an.json, "Statistics as JSON");
  an_cmd->add_flag("--check", an.check, "Run the invariant checker after every frame");
  an_cmd->add_flag("-q,--quiet", an.quiet, "No summary line on stderr");
  an_cmd->footer("Example:\n  mkdir frames && bccmis animate --frames 60 --svg-dir frames --check");

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::cerr << "bccmis: " << e.what() << "\nRun 'bccmis --help' for usage.\n";
    return kExitInput;
  }

  try {
    if (*replay_cmd) return run_replay(ro);
    if (*check_cmd) return run_check(check_path, check_depth, check_quiet);
    if (*view_cmd) return run_view(vo);
    if (*diff_cmd) return run_diff(diff_a, diff_b, diff_quiet);
    if (*hf_cmd) return run_heightfield(hf, std::cout, std::cerr);
    if (*an_cmd) return run_animate(an, std::cout, std::cerr);
    if (*explore_cmd) {
      try {
        validate_lattice_size(ex_size);
      } catch (const LatticeError& e) {
        throw InputError(std::string("explore: ") + e.what());
      }
      if (!ex_no_progress && ::isatty(2)) {
        ex.progress = [](const ExploreProgress& p) {
          std::fprintf(stderr, "\r%lld states, %lld queued, %lld ops tried, %.1f s   ",
                       static_cast<long long>(p.states), static_cast<long long>(p.queued),
                       static_cast<long long>(p.ops_tried), p.seconds);
        };
      }
      const ExploreResult r = explore(ex_size, ex);
      if (ex.progress) std::fprintf(stderr, "\n");
      std::cout << (ex_json ? to_json(r) : summary(r)) << "\n";
      if (r.first_failure && !ex_json)
        std::cout << "first failure: " << r.first_failure->message << "\nreproducing trace:\n" << r.first_failure->trace;
      return r.ok() ? kExitOk : kExitViolation;
    }
    if (*stats_cmd) {
      std::cout << format_stats(stats(load_state(stats_path, stats_from_trace)), stats_json);
      return kExitOk;
    }
    if (*render_cmd) {
      const Graph g = load_state(render_path, render_from_trace);
      write_output(render_out, render_svg(g, display_name(render_path)));
      return kExitOk;
    }
    if (*conf_cmd) {
      if (!co_traces.empty()) {
        std::error_code ec;
        if (!std::filesystem::is_directory(co_traces, ec)) throw InputError(co_traces + ": not a directory");
        for (const auto& e : std::filesystem::directory_iterator(co_traces))
          if (e.path().extension() == ".trace") co.trace_files.push_back(e.path().string());
        std::sort(co.trace_files.begin(), co.trace_files.end());
      }
      if (!co_view.empty())
        co.write_view = [&](const std::string& html) {
          write_output(co_view, html);
          std::cout << "viewer page of the disagreement: " << co_view << "\n";
        };
      return run_conformance(co, std::cout);
    }
  } catch (const ParseError& e) {
    std::cerr << "bccmis: " << e.what() << "\n";
    return kExitInput;
  } catch (const InputError& e) {
    std::cerr << "bccmis: " << e.what() << "\n";
    return kExitInput;
  } catch (const std::exception& e) {
    std::cerr << "bccmis: internal error: " << e.what() << "\n";
    return kExitInternal;
  }
  return kExitInternal;
}
