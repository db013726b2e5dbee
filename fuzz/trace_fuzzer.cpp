// fuzz_trace: bytes -> parse_trace -> replay with the checker after every command.
//
// - A parse error must be a clean ParseError whose what() is one printable
//   line `file:line:column: message` pointing into the text (never a crash,
//   a hang or a huge allocation: TraceLimits caps the initial lattice).
// - What parses must print back (format_trace) to a text that parses to the
//   same trace.
// - The first kMaxCommands commands are replayed with replay<Graph> (the
//   one replay of bccmis/trace.h); after every command find_violation must find nothing.
//   Refusals are ordinary results. A violation or an exception aborts with
//   the trace replayed so far.
#include <cstddef>
#include <cstdint>
#include <exception>
#include <string>
#include <string_view>

#include "bccmis/format.h"
#include "bccmis/invariants/invariants.h"
#include "bccmis/trace.h"
#include "fuzz_util.h"

namespace {

using namespace bccmis;

constexpr std::string_view kTarget = "fuzz_trace";
constexpr std::string_view kFile = "fuzz.trace";
constexpr std::size_t kMaxCommands = 400;

TraceLimits limits() {
  TraceLimits l;
  l.max_vertices = 200;
  return l;
}

bool same_commands(const Trace& a, const Trace& b) {
  if (!(a.size == b.size) || a.commands.size() != b.commands.size()) return false;
  for (std::size_t i = 0; i < a.commands.size(); ++i)
    if (a.commands[i].kind != b.commands[i].kind || !(a.commands[i].at == b.commands[i].at)) return false;
  return true;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  Trace trace;
  try {
    trace = parse_trace(text, kFile, limits());
  } catch (const ParseError& e) {
    fuzz::check_parse_error(kTarget, e, kFile, text);
    return 0;
  }
  if (initial_vertex_count(trace.size) > limits().max_vertices)
    fuzz::fail(kTarget, "the parser accepted a lattice above TraceLimits::max_vertices", &trace);

  // Round trip through the printer.
  try {
    const Trace again = parse_trace(format_trace(trace), kFile, limits());
    if (!same_commands(trace, again)) fuzz::fail(kTarget, "format_trace does not print back the same trace", &trace);
  } catch (const ParseError& e) {
    fuzz::fail(kTarget, std::string("format_trace printed a text that does not parse: ") + e.what(), &trace);
  }

  if (trace.commands.size() > kMaxCommands) trace.commands.resize(kMaxCommands);
  Trace so_far;
  so_far.size = trace.size;
  std::string log;
  std::size_t decisions = 0;
  try {
    replay<Graph>(trace, log, [&](const TraceCommand& c, const Graph& g, std::string_view decision) {
      so_far.commands.push_back(c);
      if (!decision.empty()) ++decisions;
      if (auto v = find_violation(g))
        fuzz::fail(kTarget, "invariant violated after '" + command_text(c) + "': " + to_string(*v), &so_far);
    });
  } catch (const std::exception& e) {
    fuzz::fail(kTarget, std::string("exception during replay: ") + e.what(), &so_far);
  }
  std::size_t lines = 0;
  for (char ch : log) lines += ch == '\n';
  if (lines != decisions) fuzz::fail(kTarget, "the decision log does not have one line per refine/coarsen", &trace);
  return 0;
}
