// bccmis: the one trace stepper, and replay on it.
//
// Every tool that runs a trace (the CLI's replay, the viewer, conformance,
// the fuzz targets, the lock-step twin of tests/testing, the tests) runs it
// through step() and replay() below, on any lattice that models
// AdaptiveLattice (bccmis/lattice.h); explore reports the calls it makes as
// StepResults. The decision-log line of a command is the format of
// spec/formats.md, "Decision log".
#pragma once

#include <concepts>
#include <cstddef>
#include <limits>
#include <string>
#include <string_view>
#include <type_traits>
#include <variant>

#include "bccmis/io/format.h"
#include "bccmis/lattice.h"

namespace bccmis {

/// The trace and command types of lattice L's dimension (Trace and
/// TraceCommand in 2D, d3::Trace and d3::TraceCommand in 3D).
template <AdaptiveLattice L>
using trace_t = BasicTrace<point_type_t<L>, typename L::size_type>;
template <AdaptiveLattice L>
using trace_command_t = BasicTraceCommand<point_type_t<L>>;

/// What one trace command did to a lattice: nothing (check), or the result
/// of refine or coarsen, with the sets it touched.
template <AdaptiveLattice L>
struct StepResult {
  std::variant<std::monostate, refine_result_t<L>, coarsen_result_t<L>> result;

  bool is_check() const { return result.index() == 0; }
  /// The operation was applied (false for a refusal and for check).
  bool applied() const {
    if (const auto* r = std::get_if<1>(&result)) return r->applied();
    if (const auto* r = std::get_if<2>(&result)) return r->applied();
    return false;
  }
  /// The refusal code (spec/formats.md); empty when applied or for check.
  std::string_view refusal() const {
    if (const auto* r = std::get_if<1>(&result)) return r->refused ? code(*r->refused) : std::string_view{};
    if (const auto* r = std::get_if<2>(&result)) return r->refused ? code(*r->refused) : std::string_view{};
    return {};
  }
};

/// Runs one trace command on g: refine or coarsen at its position (a refusal
/// changes nothing), or nothing for check.
template <AdaptiveLattice L>
StepResult<L> step(L& g, const trace_command_t<L>& cmd) {
  switch (cmd.kind) {
    case TraceCommand::Kind::Refine: return {refine(g, cmd.at)};
    case TraceCommand::Kind::Coarsen: return {coarsen(g, cmd.at)};
    case TraceCommand::Kind::Check: break;
  }
  return {};
}

/// Appends the decision-log line of `cmd` and its result, with the newline
/// (nothing for check).
template <AdaptiveLattice L>
void append_decision(std::string& log, const trace_command_t<L>& cmd, const StepResult<L>& r) {
  if (r.is_check()) return;
  append_decision_line(log, cmd, r.refusal());
  log += '\n';
}

/// The most cells g can have while `trace` is replayed on it: its cells now
/// and 3 more per refine command (saturated).
template <AdaptiveLattice L>
std::size_t max_cells(const L& g, const trace_t<L>& trace) {
  std::size_t refines = 0;
  for (const auto& cmd : trace.commands) refines += cmd.kind == CommandKind::Refine ? 1 : 0;
  const std::size_t room = std::numeric_limits<std::size_t>::max() - cell_count(g);
  return cell_count(g) + (refines > room / 3 ? room : 3 * refines);
}

/// An observer that does nothing.
struct NoObserver {
  template <class... A>
  void operator()(const A&...) const {}
};

/// Replays `trace` from its initial lattice: one decision-log line per refine
/// and coarsen appended to `log`. A lattice that can reserve (an optional
/// `reserve(g, cells)` of its vocabulary) is first given room for
/// max_cells(g, trace), so that it does not grow (copying its arrays) on the
/// way. After every command, `after` (if callable)
/// is called with the command, the lattice, the command's decision line
/// (without the newline; empty for check) and, if it takes a fourth
/// argument, the StepResult (what the command touched). Returns the final
/// lattice. An exception from `after` stops the replay.
template <AdaptiveLattice L, class Observer = NoObserver>
L replay(const trace_t<L>& trace, std::string& log, const Observer& after = {}) {
  L g(trace.size);
  if constexpr (requires(std::size_t n) { reserve(g, n); }) reserve(g, max_cells(g, trace));
  for (const trace_command_t<L>& cmd : trace.commands) {
    const StepResult<L> r = step(g, cmd);
    const std::size_t start = log.size();
    append_decision(log, cmd, r);
    const std::string_view decision =
        log.size() == start ? std::string_view{} : std::string_view(log).substr(start, log.size() - start - 1);
    if constexpr (std::is_invocable_v<const Observer&, const trace_command_t<L>&, const L&, std::string_view,
                                      const StepResult<L>&>) {
      after(cmd, g, decision, r);
    } else {
      after(cmd, g, decision);
    }
  }
  return g;
}

}  // namespace bccmis
