// bccmis CLI: reading inputs, writing outputs, exit codes (spec/cli.md).
//
// Every subcommand reads its files through read_input / read_trace /
// read_state and writes them through an OutputSet (or write_atomically for a
// single output), so that the rules below hold for all of them:
//   - "-" is standard input or standard output;
//   - a file that cannot be read is reported with the reason (errno);
//   - outputs are staged: each is written to a temporary file beside its
//     target (or in a staging directory beside it, OutputSet::stage_in)
//     and renamed over it only when the whole run has succeeded; on
//     failure every temporary is removed and no target is touched, and so
//     on SIGINT, SIGTERM or SIGHUP (temporary_files.h);
//   - a command opens its outputs' temporaries before its long work, so that
//     an unwritable output fails at once, with the reason (errno);
//   - a target that exists and is not a regular file (/dev/null, a FIFO) is
//     written directly, at commit; a symbolic link is followed;
//   - a failed write to standard output is an error (exit 2).
#pragma once

#include <functional>
#include <iosfwd>
#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "bccmis/graph.h"
#include "bccmis/io/d3/format.h"
#include "bccmis/io/format.h"

namespace bccmis::cli {

/// The exit codes of every subcommand.
enum Exit : int {
  kExitOk = 0,         ///< success
  kExitViolation = 1,  ///< an invariant is violated, states differ, implementations disagree
  kExitInput = 2,      ///< bad input: usage, parse error, unreadable file, unwritable output
  kExitInternal = 3,   ///< internal error
};

/// Bad input (exit 2). The message is complete: it names the file and why.
struct InputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// A violated invariant found by a check the user asked for (exit 1).
struct CheckFailure : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// "<stdin>" for "-", else the path.
std::string display_name(const std::string& path);

/// The whole file, or standard input for "-". Throws InputError
/// ("PATH: cannot open for reading: No such file or directory").
std::string read_input(const std::string& path);

/// The trace in `path`. A canonical state given instead gets a hint naming
/// the command that takes it; `state_hint` is that hint's tail.
Trace read_trace(const std::string& path, const TraceLimits& limits = {},
                 std::string_view state_hint = "check it with 'bccmis check'");

/// The trace in `path`, of either dimension (read_trace's hints).
AnyTrace read_any_trace(const std::string& path, const TraceLimits& limits = {},
                        std::string_view state_hint = "check it with 'bccmis check'");

/// The canonical state in `path`. A trace given instead gets a hint naming
/// the command that takes it; `trace_hint` is that hint's tail.
Graph read_state(const std::string& path,
                 std::string_view trace_hint = "replay it with 'bccmis replay TRACE --state FILE' first");

/// The canonical state in `path`, of either dimension (read_state's hints).
AnyState read_any_state(const std::string& path,
                        std::string_view trace_hint = "replay it with 'bccmis replay TRACE --state FILE' first");

/// A state from a canonical-state file, or from a trace (replayed) with `from_trace`.
Graph read_state_or_trace(const std::string& path, bool from_trace);
/// The same, of either dimension.
AnyState read_any_state_or_trace(const std::string& path, bool from_trace);

/// Writes the text of one output into the stream it is given.
using Writer = std::function<void(std::ostream& out)>;

/// The outputs of one run, all or nothing. add() writes each output at once
/// into a temporary file (beside the target; for standard output or a
/// target that is not a regular file, an unnamed temporary); commit() makes
/// them visible: it copies the unnamed temporaries to their targets, then
/// renames the others over theirs. Destroying an uncommitted set removes
/// every temporary and touches no target.
class OutputSet {
 public:
  OutputSet();
  ~OutputSet();
  OutputSet(const OutputSet&) = delete;
  OutputSet& operator=(const OutputSet&) = delete;

  /// Makes every later temporary of a regular target in the directory `dir`
  /// (an existing directory on the targets' file system, such as a
  /// StagingDirectory beside them) instead of beside its target.
  void stage_in(const std::string& dir);

  /// Creates the temporary for `path` now, to be written by a later add()
  /// of the same path: an output that cannot be created fails before the
  /// work that makes its text. An empty path or "-" opens nothing. Throws
  /// InputError ("PATH: cannot create a temporary file in DIR: REASON").
  void open(const std::string& path);

  /// Stages `write`'s text for `path` ("-": standard output), in the
  /// temporary open() created for it or in a new one. An empty path
  /// stages nothing. Throws InputError when the temporary cannot be created
  /// or written (the message names `path` and the reason).
  void add(const std::string& path, const Writer& write);
  void add(const std::string& path, std::string_view text);

  /// Makes every staged output visible, in the order they were added
  /// (standard output and special files first). Throws InputError on a write
  /// error.
  void commit();

 private:
  struct Staged;
  /// A new temporary for `path`.
  std::unique_ptr<Staged> create(const std::string& path);
  std::vector<std::unique_ptr<Staged>> staged_;
  std::unordered_map<std::string, Staged*> opened_;  ///< by path: created by open(), not yet written
  std::string staging_;                              ///< stage_in()'s directory, or empty: beside the target
};

/// One output, staged and committed (see OutputSet).
void write_atomically(const std::string& path, const Writer& write);
void write_atomically(const std::string& path, std::string_view text);

/// Flushes standard output. Throws InputError when it cannot be written
/// (e.g. a full disk: "standard output: write error: No space left on device").
void flush_stdout();

/// Runs `body` (which returns an exit code) and turns what it throws into an
/// exit code and one line on stderr, `tool: message`: CheckFailure 1;
/// InputError and ParseError 2; any other exception 3 ("internal error").
template <class Body>
int guarded(const char* tool, Body&& body);

/// At most one of `paths` may be "-" (standard output); `why` says what to do instead.
void require_one_stdout(const std::vector<const std::string*>& paths, const std::string& why);

/// Prints `tool: message` on stderr.
void report(const char* tool, const char* message);

template <class Body>
int guarded(const char* tool, Body&& body) {
  try {
    return body();
  } catch (const CheckFailure& e) {
    report(tool, e.what());
    return kExitViolation;
  } catch (const InputError& e) {
    report(tool, e.what());
  } catch (const ParseError& e) {
    report(tool, e.what());
  } catch (const std::exception& e) {
    report(tool, (std::string("internal error: ") + e.what()).c_str());
    return kExitInternal;
  }
  return kExitInput;
}

}  // namespace bccmis::cli
