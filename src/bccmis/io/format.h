// bccmis: the version-1 interchange formats of spec/formats.md: traces,
// decision logs and canonical states. Parsers report the first error as
// `file:line:column: message`.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "bccmis/d3/point.h"
#include "bccmis/graph.h"
#include "bccmis/io/parse_error.h"
#include "bccmis/ops.h"

namespace bccmis {

// ---- Canonical state (spec/formats.md, "Canonical state") ------------------

/// The canonical text of g. Two graphs are equal iff their texts are equal.
std::string canonical_state(const Graph& g);

/// Parses a canonical state. The parser is strict: it accepts exactly the
/// texts canonical_state can print (up to the validity of the graph itself,
/// which is the checker's job), so a parsed state prints back byte-identically.
Graph parse_state(std::string_view text, std::string_view file = "<state>");

// ---- Traces (spec/formats.md, "Trace"; "3D extension") ---------------------

/// What a trace command does.
enum class CommandKind { Refine, Coarsen, Check };

/// One trace command on a lattice whose positions are P (Point in 2D,
/// d3::Point in 3D).
template <class P>
struct BasicTraceCommand {
  using Kind = CommandKind;
  Kind kind = Kind::Check;
  P at;          ///< the cell center (refine) or node (coarsen)
  int line = 0;  ///< 1-based line in the trace file
};

/// A parsed trace: the initial lattice and the commands.
template <class P, class S>
struct BasicTrace {
  using command_type = BasicTraceCommand<P>;
  std::string file;  ///< the name given to the parser, for messages
  S size;
  int lattice_line = 0;
  std::vector<command_type> commands;
};

using TraceCommand = BasicTraceCommand<Point>;
using Trace = BasicTrace<Point, LatticeSize>;
namespace d3 {
using TraceCommand = BasicTraceCommand<Point>;
using Trace = BasicTrace<Point, LatticeSize>;
}  // namespace d3
/// A trace of either dimension, as its `lattice` line says (3 or 4 numbers).
using AnyTrace = std::variant<Trace, d3::Trace>;

/// Limits that keep a hostile trace from exhausting memory (about 250 bytes
/// per vertex in the reference, so the default bounds a replay near 250 MB).
struct TraceLimits {
  std::int64_t max_vertices = 1'000'000;  ///< |N| + |C| of the initial lattice (callers check growth)
};

/// The number of vertices |N| + |C| of the initial lattice, saturated at
/// INT64_MAX: (W+1)(H+1) + WH in 2D, (W+1)(H+1)(D+1) + WHD in 3D.
std::int64_t initial_vertex_count(const LatticeSize& size);
std::int64_t initial_vertex_count(const d3::LatticeSize& size);

/// Parses a 2D trace; throws ParseError on the first malformed line (a 3D
/// trace is one: this reader takes 2D traces only).
Trace parse_trace(std::string_view text, std::string_view file = "<trace>", const TraceLimits& limits = {});
/// Parses a 3D trace (`lattice W H D L`); a 2D trace is a ParseError.
namespace d3 {
Trace parse_trace(std::string_view text, std::string_view file = "<trace>", const TraceLimits& limits = {});
}  // namespace d3
/// Parses a trace of either dimension: four numbers on its `lattice` line
/// make it 3D, three 2D.
AnyTrace parse_any_trace(std::string_view text, std::string_view file = "<trace>", const TraceLimits& limits = {});

/// Prints a trace in the format the parsers read (used to print reproducers).
std::string format_trace(const Trace& trace);
std::string format_trace(const d3::Trace& trace);

// ---- Decision log (spec/formats.md, "Decision log") ------------------------

/// A command as trace text without the newline: `refine 4 4`, `check`.
std::string command_text(const TraceCommand& cmd);
std::string command_text(const d3::TraceCommand& cmd);
/// command_text(cmd) appended to `out`.
void append_command_text(std::string& out, const TraceCommand& cmd);
void append_command_text(std::string& out, const d3::TraceCommand& cmd);

/// One decision-log line without the newline, e.g. `refine 4 4 ok` or
/// `coarsen 8 8 refused not-a-refined-center` (`refine 2 2 2 ok` in 3D).
std::string decision_line(const TraceCommand& cmd, std::string_view refusal_code);
std::string decision_line(const d3::TraceCommand& cmd, std::string_view refusal_code);
/// decision_line(cmd, refusal_code) appended to `out`.
void append_decision_line(std::string& out, const TraceCommand& cmd, std::string_view refusal_code);
void append_decision_line(std::string& out, const d3::TraceCommand& cmd, std::string_view refusal_code);

/// `text` as a JSON string literal (RFC 8259), quotes included: `"`, `\`,
/// newline, tab and carriage return get their short escapes, other control
/// bytes \u00XX. With `html_safe`, `<`, `>` and `&` are \u escapes too, so the
/// literal can stand inside an HTML <script> element (no "</script>").
/// Other bytes are copied as they are (UTF-8 stays UTF-8).
std::string json_string(std::string_view text, bool html_safe = false);

}  // namespace bccmis
