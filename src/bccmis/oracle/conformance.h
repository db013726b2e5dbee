// bccmis conformance harness: runs an external implementation on traces of
// either dimension and compares its decision log and final state with the
// reference, shrinking the first disagreement to a minimal trace
// (spec/conformance.md).
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <ostream>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "bccmis/io/format.h"
#include "bccmis/oracle/view.h"

namespace bccmis {

/// The dimension of the random traces: 2D, 3D, or mixed (2D and 3D
/// alternately, the first one 2D).
enum class TraceDimension { Two, Three, Mixed };

/// The files describing a 3D disagreement (the viewer draws 2D lattices only).
struct DisagreementFiles {
  std::string trace;            ///< the minimal trace (format_trace)
  std::string reference_state;  ///< the reference's canonical state after it
  /// The implementation's output on it from its `bccmis-state` line on;
  /// empty when it printed no state (a crash, a timeout, a decision log only).
  std::string impl_state;
};

struct ConformanceOptions {
  std::string impl;                                  ///< shell command; the trace file path is appended
  std::vector<std::string> trace_files;              ///< bundled traces to run first (2D or 3D)
  int random = 0;                                    ///< number of random traces
  TraceDimension dimension = TraceDimension::Mixed;  ///< of the random traces
  std::uint64_t seed = 1;                            ///< seed of the random traces
  int max_ops = 30;                                  ///< operations per random trace
  double timeout_seconds = 10;                       ///< per run of the implementation
  /// If set, called with a viewer page (bccmis view) for the minimal trace of
  /// the first disagreement, when it is 2D: the reference replay, with the
  /// implementation's state beside the reference state at the first
  /// disagreement.
  std::function<void(const std::string& html)> write_view;
  /// If set, called for a 3D disagreement with its minimal trace and the two
  /// states after it.
  std::function<void(const DisagreementFiles& files)> write_files;
};

/// The output of one run of the implementation.
struct ImplRun {
  int exit_code = 0;  ///< exit status when it exited normally
  int signal = 0;     ///< terminating signal, 0 if none
  bool timed_out = false;
  std::string out, err;
};

/// Runs `command 'trace_file'` under /bin/sh with a timeout.
ImplRun run_implementation(const std::string& command, const std::string& trace_file, double timeout_seconds);

/// What the reference prints for a trace (`bccmis replay`, no checks): the
/// decision log followed by the canonical state.
std::string reference_output(const Trace& trace);
std::string reference_output(const d3::Trace& trace);

/// Compares an implementation's run with the reference output. Empty when
/// they agree; otherwise a description of the first difference: the first
/// differing decision, or the semantic diff of the final states, or the
/// crash / timeout / exit status. A 3D trace's states are compared with the
/// 3D diff.
std::string compare_run(const Trace& trace, const ImplRun& run);
std::string compare_run(const d3::Trace& trace, const ImplRun& run);

/// A random trace biased toward legal operations (seeded, deterministic):
/// 1-3 cells per side, max level 1-3, 1..max_ops operations, most on live
/// cells and nodes, some at arbitrary positions.
Trace random_trace(std::mt19937_64& rng, int max_ops);
/// The same in 3D, where coarsen mostly picks centers that were refined (a
/// node picked at random is rarely one).
namespace d3 {
Trace random_trace(std::mt19937_64& rng, int max_ops);
}  // namespace d3

/// Delta debugging: a smallest trace (no single command can be dropped) for
/// which `disagrees` still holds. `disagrees(trace)` must hold for the input.
Trace shrink(const Trace& trace, const std::function<bool(const Trace&)>& disagrees);
d3::Trace shrink(const d3::Trace& trace, const std::function<bool(const d3::Trace&)>& disagrees);

/// The viewer's side panel for an implementation whose output on `trace` was
/// `full` (decision log, then canonical state): empty when it agrees with the
/// reference; otherwise the step of the first differing decision (or the last
/// step when only the states differ), its position marked, and the
/// implementation's state there: from `full`, or for a differing decision
/// from `rerun` on the trace up to that command (if given; may return empty).
/// Without `require_state`, an output without a canonical state is a decision
/// log only, and only the decisions are compared.
std::optional<ViewSide> implementation_side(const Trace& trace, const ImplRun& full,
                                            const std::function<std::optional<ImplRun>(const Trace&)>& rerun,
                                            bool require_state);

/// The viewer page for a disagreement on a 2D `trace` (see ConformanceOptions::write_view).
std::string disagreement_page(const Trace& trace, const ConformanceOptions& options);

/// Thrown by run_conformance when the implementation cannot be run at all:
/// the shell's exit status 126 (not executable) or 127 (not found). A harness
/// error, not a disagreement.
struct ImplementationNotRunnable : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// Runs the harness: the bundled traces (either dimension), then the random
/// ones; reports to `out` (progress and the verdict). Returns the
/// exit code: 0 all agree, 1 a disagreement (minimal trace printed), 2 harness
/// error (bad options, unreadable trace).
int run_conformance(const ConformanceOptions& options, std::ostream& out);

}  // namespace bccmis
