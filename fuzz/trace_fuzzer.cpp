// fuzz_trace: bytes -> parse_any_trace -> replay with the checker after every
// command, in either dimension.
//
// - A parse error must be a clean ParseError whose what() is one printable
//   line `file:line:column: message` pointing into the text (never a crash,
//   a hang or a huge allocation: TraceLimits caps the initial lattice).
// - What parses must print back (format_trace) to a text that parses to the
//   same trace, of the same dimension.
// - The first kMaxCommands commands are replayed with the one replay of
//   bccmis/trace.h: replay<Graph> for a 2D trace, replay<d3::Graph> for a
//   3D one (`lattice W H D L`). After every command the checker of that
//   dimension must find nothing: find_violation (2D); find_violation(g, 4)
//   and, while the lattice has at most kMeshCells cells and after the last
//   command, the mesh layer check_mesh(g, tetrahedra(g)) (3D). Refusals are
//   ordinary results. A violation or an exception aborts with the trace
//   replayed so far.
#include <cstddef>
#include <cstdint>
#include <exception>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <variant>

#include "bccmis/d3/lattice.h"
#include "bccmis/invariants/invariants.h"
#include "bccmis/io/format.h"
#include "bccmis/trace.h"
#include "d3/checked.h"
#include "fuzz_util.h"

namespace {

using namespace bccmis;

constexpr std::string_view kTarget = "fuzz_trace";
constexpr std::string_view kFile = "fuzz.trace";
constexpr std::size_t kMaxCommands = 400;
constexpr std::size_t kMeshCells = 64;

TraceLimits limits() {
  TraceLimits l;
  l.max_vertices = 200;
  return l;
}

template <class T>
bool same_commands(const T& a, const T& b) {
  if (!(a.size == b.size) || a.commands.size() != b.commands.size()) return false;
  for (std::size_t i = 0; i < a.commands.size(); ++i)
    if (a.commands[i].kind != b.commands[i].kind || !(a.commands[i].at == b.commands[i].at)) return false;
  return true;
}

/// The first problem of the checker of g's dimension, as one line.
std::optional<std::string> problem(const Graph& g, bool) {
  if (auto v = find_violation(g)) return to_string(*v);
  return std::nullopt;
}
std::optional<std::string> problem(const d3::Graph& g, bool last) {
  return d3::fuzz::problem(g, last || g.C.size() <= kMeshCells);
}

template <AdaptiveLattice L>
void run(trace_t<L>& trace) {
  if (initial_vertex_count(trace.size) > limits().max_vertices)
    fuzz::fail(kTarget, "the parser accepted a lattice above TraceLimits::max_vertices", &trace);

  // Round trip through the printer.
  try {
    const AnyTrace again = parse_any_trace(format_trace(trace), kFile, limits());
    const auto* same = std::get_if<trace_t<L>>(&again);
    if (!same || !same_commands(trace, *same))
      fuzz::fail(kTarget, "format_trace does not print back the same trace", &trace);
  } catch (const ParseError& e) {
    fuzz::fail(kTarget, std::string("format_trace printed a text that does not parse: ") + e.what(), &trace);
  }

  if (trace.commands.size() > kMaxCommands) trace.commands.resize(kMaxCommands);
  trace_t<L> so_far;
  so_far.size = trace.size;
  std::string log;
  std::size_t decisions = 0;
  try {
    replay<L>(trace, log, [&](const trace_command_t<L>& c, const L& g, std::string_view decision) {
      so_far.commands.push_back(c);
      if (!decision.empty()) ++decisions;
      if (auto p = problem(g, so_far.commands.size() == trace.commands.size()))
        fuzz::fail(kTarget, "invariant violated after '" + command_text(c) + "': " + *p, &so_far);
    });
  } catch (const std::exception& e) {
    fuzz::fail(kTarget, std::string("exception during replay: ") + e.what(), &so_far);
  }
  std::size_t lines = 0;
  for (char ch : log) lines += ch == '\n';
  if (lines != decisions) fuzz::fail(kTarget, "the decision log does not have one line per refine/coarsen", &trace);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  AnyTrace trace;
  try {
    trace = parse_any_trace(text, kFile, limits());
  } catch (const ParseError& e) {
    fuzz::check_parse_error(kTarget, e, kFile, text);
    return 0;
  }
  if (auto* t2 = std::get_if<Trace>(&trace))
    run<Graph>(*t2);
  else
    run<d3::Graph>(std::get<d3::Trace>(trace));
  return 0;
}
