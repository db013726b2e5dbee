#include "bccmis/io/format.h"

#include <ostream>

#include "bccmis/io/detail/parse.h"
#include "bccmis/io/detail/state_writer.h"
#include "bccmis/lattice.h"
#include "bccmis/text_writer.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <optional>
#include <type_traits>
#include <utility>

namespace bccmis {

using detail::LineParser;
using detail::shown;
using detail::split_lines;
using detail::state_tokens;
using detail::trace_tokens;

// ---- JSON ---------------------------------------------------------------------

std::string json_string(std::string_view text, bool html_safe) {
  std::string r = "\"";
  for (const char ch : text) {
    const auto u = static_cast<unsigned char>(ch);
    switch (ch) {
      case '"': r += "\\\""; break;
      case '\\': r += "\\\\"; break;
      case '\n': r += "\\n"; break;
      case '\t': r += "\\t"; break;
      case '\r': r += "\\r"; break;
      default:
        if (u < 0x20 || (html_safe && (ch == '<' || ch == '>' || ch == '&'))) {
          char buf[8];
          std::snprintf(buf, sizeof buf, "\\u%04x", static_cast<unsigned>(u));
          r += buf;
        } else {
          r += ch;
        }
    }
  }
  r += '"';
  return r;
}

// ---- Canonical state ---------------------------------------------------------

void write_canonical_state(std::ostream& out, const Graph& g) { detail::write_state_as(out, g); }

std::string canonical_state(const Graph& g) { return canonical_text(g); }

Graph parse_state(std::string_view text, std::string_view file) { return detail::parse_state_as<Graph>(text, file); }

// ---- Traces -----------------------------------------------------------------

std::int64_t initial_vertex_count(const LatticeSize& size) {
  const std::int64_t big = INT64_MAX / 4;
  if (size.W <= 0 || size.H <= 0) return 0;
  if (size.W > big / size.H) return INT64_MAX;  // (W+1)(H+1) + WH < 4 W H for W, H >= 2
  return (size.W + 1) * (size.H + 1) + size.W * size.H;
}

std::int64_t initial_vertex_count(const d3::LatticeSize& size) {
  if (size.W <= 0 || size.H <= 0 || size.D <= 0) return 0;
  // (W+1)(H+1)(D+1) + WHD <= 9 WHD for W, H, D >= 1; saturate when 9 WHD could overflow.
  const std::int64_t big = INT64_MAX / 9;
  if (size.W > big / size.H || size.W * size.H > big / size.D) return INT64_MAX;
  return (size.W + 1) * (size.H + 1) * (size.D + 1) + size.W * size.H * size.D;
}

namespace {

// "5 x 3 cells" or "5 x 3 x 2 cubes", for messages.
std::string extent_text(const LatticeSize& s) { return std::to_string(s.W) + " x " + std::to_string(s.H) + " cells"; }
std::string extent_text(const d3::LatticeSize& s) {
  return std::to_string(s.W) + " x " + std::to_string(s.H) + " x " + std::to_string(s.D) + " cubes";
}

// The first command of a trace: where it is, and whether it is a `lattice`
// line and with how many numbers. Four or more make the trace 3D; every other
// text, malformed ones included, is read (and reported) as 2D.
struct FirstCommand {
  int line = 1, column = 1;
  bool lattice = false;
  std::size_t numbers = 0;
  bool is_3d() const { return lattice && numbers >= 4; }
};

FirstCommand first_command(std::string_view text, std::string_view file) {
  int line_no = 0;
  for (std::size_t start = 0; start <= text.size();) {
    ++line_no;
    const std::size_t nl = text.find('\n', start);
    const std::string_view line =
        text.substr(start, nl == std::string_view::npos ? std::string_view::npos : nl - start);
    try {
      const auto t = trace_tokens(line, LineParser(file, line_no));
      if (!t.empty()) return {line_no, t[0].column, t[0].text == "lattice", t.size() - 1};
    } catch (const ParseError&) {
      return {};  // the parser reports it
    }
    if (nl == std::string_view::npos) break;
    start = nl + 1;
  }
  return {};
}

// The parser of spec/formats.md, "Trace", for T = Trace (2D) or d3::Trace (3D).
template <class T>
T parse_trace_as(std::string_view text, std::string_view file, const TraceLimits& limits) {
  constexpr bool k3 = std::is_same_v<T, d3::Trace>;
  using Command = typename T::command_type;
  const char* const lattice_usage = k3 ? "lattice W H D L" : "lattice W H L";
  T trace;
  trace.file = std::string(file);
  bool have_lattice = false;
  trace.commands.reserve(static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n')) + 1);
  int line_no = 0;
  auto parse_line = [&](std::string_view line) {
    const LineParser lp(file, line_no);
    const auto t = trace_tokens(line, lp);
    if (t.empty()) return;
    const std::string_view cmd = t[0].text;
    auto arity = [&](std::size_t n, const std::string& usage) {
      if (t.size() != n + 1)
        lp.fail(t.size() > n + 1 ? t[n + 1].column : static_cast<int>(line.size()) + 1,
                std::string(t.size() > n + 1 ? "too many arguments" : "too few arguments") + "; usage: " + usage);
    };
    if (cmd == "lattice") {
      if (have_lattice)
        lp.fail(t[0].column,
                "second 'lattice' command (the first is on line " + std::to_string(trace.lattice_line) + ")");
      if constexpr (k3) {
        arity(4, "lattice W H D L (3D)");
        trace.size = lp.lattice3(t[1], t[2], t[3], t[4], t[0].column, false);
      } else {
        arity(3, "lattice W H L (2D) or lattice W H D L (3D)");
        trace.size = lp.lattice(t[1], t[2], t[3], t[0].column, false);
      }
      if (const std::int64_t v = initial_vertex_count(trace.size); v > limits.max_vertices)
        lp.fail(t[0].column, "lattice of " + extent_text(trace.size) + " exceeds the limit of " +
                                 std::to_string(limits.max_vertices) + " vertices (it has " +
                                 (v == INT64_MAX ? std::string("more than 2^63") : std::to_string(v)) + ")");
      trace.lattice_line = line_no;
      have_lattice = true;
      return;
    }
    Command c;
    c.line = line_no;
    if (cmd == "refine" || cmd == "coarsen") {
      c.kind = cmd == "refine" ? CommandKind::Refine : CommandKind::Coarsen;
      if (!have_lattice) lp.fail(t[0].column, "'" + std::string(cmd) + "' before the '" + lattice_usage + "' command");
      const std::string usage = std::string(cmd) + (k3 ? " X Y Z" : " X Y");
      if (t.size() == (k3 ? 3u : 4u))
        lp.fail(t.size() == 3 ? static_cast<int>(line.size()) + 1 : t[3].column,
                std::string(k3 ? "too few arguments: two" : "too many arguments: three") + " coordinates on a " +
                    (k3 ? "3D" : "2D") + " lattice (line " + std::to_string(trace.lattice_line) + "); usage: " + usage);
      arity(k3 ? 3 : 2, usage);
      if constexpr (k3)
        c.at = {lp.integer(t[1], false, "x coordinate"), lp.integer(t[2], false, "y coordinate"),
                lp.integer(t[3], false, "z coordinate")};
      else
        c.at = {lp.integer(t[1], false, "x coordinate"), lp.integer(t[2], false, "y coordinate")};
    } else if (cmd == "check") {
      arity(0, "check");
    } else {
      lp.fail(t[0].column, "unknown command " + shown(cmd) + " (expected lattice, refine, coarsen or check)");
    }
    if (!have_lattice) lp.fail(t[0].column, "'" + std::string(cmd) + "' before the '" + lattice_usage + "' command");
    trace.commands.push_back(c);
  };
  // Lines end at '\n'; the text after the last one is a line too (empty when
  // the text ends with a newline).
  for (std::size_t start = 0;;) {
    ++line_no;
    const std::size_t nl = text.find('\n', start);
    parse_line(text.substr(start, nl == std::string_view::npos ? std::string_view::npos : nl - start));
    if (nl == std::string_view::npos) break;
    start = nl + 1;
  }
  if (!have_lattice) {
    // Point at the last line of the file (not past a final newline).
    const int last = line_no - (line_no > 1 && text.back() == '\n' ? 1 : 0);
    throw ParseError(std::string(file), std::max(last, 1), 1,
                     std::string("no '") + lattice_usage + "' command (a trace starts with one)");
  }
  trace.commands.shrink_to_fit();
  return trace;
}

}  // namespace

Trace parse_trace(std::string_view text, std::string_view file, const TraceLimits& limits) {
  if (const FirstCommand first = first_command(text, file); first.is_3d() && first.numbers == 4)
    throw ParseError(std::string(file), first.line, first.column,
                     "a 3D trace ('lattice W H D L'), where a 2D trace ('lattice W H L') is expected");
  return parse_trace_as<Trace>(text, file, limits);
}

d3::Trace d3::parse_trace(std::string_view text, std::string_view file, const TraceLimits& limits) {
  if (const FirstCommand first = first_command(text, file); first.lattice && first.numbers == 3)
    throw ParseError(std::string(file), first.line, first.column,
                     "a 2D trace ('lattice W H L'), where a 3D trace ('lattice W H D L') is expected");
  return parse_trace_as<d3::Trace>(text, file, limits);
}

AnyTrace parse_any_trace(std::string_view text, std::string_view file, const TraceLimits& limits) {
  if (first_command(text, file).is_3d()) return parse_trace_as<d3::Trace>(text, file, limits);
  return parse_trace_as<Trace>(text, file, limits);
}

namespace {

void append_size(std::string& out, const LatticeSize& s) {
  out += std::to_string(s.W) + " " + std::to_string(s.H) + " " + std::to_string(s.L);
}
void append_size(std::string& out, const d3::LatticeSize& s) {
  out += std::to_string(s.W) + " " + std::to_string(s.H) + " " + std::to_string(s.D) + " " + std::to_string(s.L);
}

char* write_point(char* buf, const Point& p) { return TextWriter::write_point(buf, p.x, p.y); }
char* write_point(char* buf, const d3::Point& p) { return TextWriter::write_point(buf, p.x, p.y, p.z); }

template <class T>
std::string format_trace_as(const T& trace) {
  std::string out = "lattice ";
  append_size(out, trace.size);
  out += '\n';
  for (const auto& c : trace.commands) {
    append_command_text(out, c);
    out += '\n';
  }
  return out;
}

template <class Command>
void append_command_text_as(std::string& out, const Command& cmd) {
  std::string_view keyword = "check";
  switch (cmd.kind) {
    case CommandKind::Refine: keyword = "refine"; break;
    case CommandKind::Coarsen: keyword = "coarsen"; break;
    case CommandKind::Check: break;
  }
  out += keyword;
  if (cmd.kind == CommandKind::Check) return;
  char buf[TextWriter::kPoint3Bytes];
  out.append(buf, write_point(buf, cmd.at));
}

template <class Command>
void append_decision_line_as(std::string& out, const Command& cmd, std::string_view refusal_code) {
  append_command_text(out, cmd);
  if (refusal_code.empty()) {
    out += " ok";
    return;
  }
  out += " refused ";
  out += refusal_code;
}

}  // namespace

std::string format_trace(const Trace& trace) { return format_trace_as(trace); }
std::string format_trace(const d3::Trace& trace) { return format_trace_as(trace); }

void append_command_text(std::string& out, const TraceCommand& cmd) { append_command_text_as(out, cmd); }
void append_command_text(std::string& out, const d3::TraceCommand& cmd) { append_command_text_as(out, cmd); }

void append_decision_line(std::string& out, const TraceCommand& cmd, std::string_view refusal_code) {
  append_decision_line_as(out, cmd, refusal_code);
}
void append_decision_line(std::string& out, const d3::TraceCommand& cmd, std::string_view refusal_code) {
  append_decision_line_as(out, cmd, refusal_code);
}

std::string command_text(const TraceCommand& cmd) {
  std::string out;
  append_command_text(out, cmd);
  return out;
}
std::string command_text(const d3::TraceCommand& cmd) {
  std::string out;
  append_command_text(out, cmd);
  return out;
}

std::string decision_line(const TraceCommand& cmd, std::string_view refusal_code) {
  std::string out;
  append_decision_line(out, cmd, refusal_code);
  return out;
}
std::string decision_line(const d3::TraceCommand& cmd, std::string_view refusal_code) {
  std::string out;
  append_decision_line(out, cmd, refusal_code);
  return out;
}

}  // namespace bccmis
