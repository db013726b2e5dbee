// bccmis viewer: one self-contained HTML page that steps through a trace (or a
// sequence of states) and shows what every operation touched, in the paper's
// terms (spec/viewer.md). The page embeds the initial state and one delta per
// step as JSON and rebuilds the states itself; the HTML/JavaScript template is
// src/oracle/bccmis/view_template.html, embedded at build time.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "bccmis/invariants/invariants.h"
#include "bccmis/io/format.h"

namespace bccmis {

/// The checker run on every state of the page; empty: no checks.
using ViewChecker = std::function<std::optional<Violation>(const Graph&)>;

/// A second state drawn beside the main one (conformance: the other
/// implementation's state at the first disagreement).
struct ViewSide {
  std::size_t step = 0;        ///< the step of the main sequence it belongs to
  std::string title;           ///< e.g. "implementation"
  std::optional<Graph> state;  ///< absent when the other side gave no parsable state
  std::string message;         ///< what differs, shown above both panels
  std::vector<Point> marks;    ///< positions to mark in both panels (e.g. the disagreeing command)
};

struct ViewOptions {
  std::string title;
  ViewChecker check;
  bool check_last_only = false;  ///< run `check` on the last state only (and on the side state)
  /// For view_trace: a second state beside the reference state of side->step;
  /// the positions where the two differ are marked in both panels.
  std::optional<ViewSide> side;
  std::optional<std::size_t> open_step;  ///< the step the page opens at (default: first violation, else 0)
  /// view_trace stops with ViewLimitError when a command leaves the lattice
  /// with more vertices (|N| + |C|) than this (as `bccmis replay --max-vertices`).
  std::int64_t max_vertices = TraceLimits{}.max_vertices;
};

/// Thrown by view_trace when the lattice outgrows ViewOptions::max_vertices.
struct ViewLimitError : std::runtime_error {
  ViewLimitError(int trace_line, const std::string& message) : std::runtime_error(message), line(trace_line) {}
  int line;  ///< the trace line of the command that outgrew the limit
};

struct ViewResult {
  std::string html;                            ///< the page
  std::string json;                            ///< the model embedded in it (spec/viewer.md)
  std::size_t steps = 0;                       ///< steps after the initial state
  std::optional<std::size_t> first_violation;  ///< step of the first violated invariant
  std::string violation;                       ///< its message (to_string of the violation)
};

/// The page for `trace`, replayed with the reference from its initial
/// lattice: step k is the state after the k-th command (step 0: the initial
/// lattice). Each step records the decision, the refined cell c and its new
/// children Y and junctions J+ (refine), or the removed children Y and
/// junctions J- (coarsen), or the refusal code.
ViewResult view_trace(const Trace& trace, const ViewOptions& options);

/// The page for a sequence of states (name, state), e.g. one canonical state
/// per step dumped by another implementation. Step 0 is the first state;
/// each step records what changed. Throws std::invalid_argument when the
/// sequence is empty or the states have different lattices.
ViewResult view_states(const std::vector<std::pair<std::string, Graph>>& states, const ViewOptions& options);

}  // namespace bccmis
