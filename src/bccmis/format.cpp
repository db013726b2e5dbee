#include "bccmis/format.h"

#include <ostream>

#include "bccmis/text_writer.h"
#include "bccmis/trace.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <optional>

namespace bccmis {

ParseError::ParseError(std::string file_, int line_, int column_, std::string message_)
    : std::runtime_error(file_ + ":" + std::to_string(line_) + ":" + std::to_string(column_) + ": " + message_),
      file(std::move(file_)),
      line(line_),
      column(column_),
      message(std::move(message_)) {}

namespace {

// A word of a line and the 1-based column where it starts.
struct Token {
  std::string_view text;
  int column;
};

// Shows a token in an error message, shortened and with control bytes escaped.
std::string shown(std::string_view t) {
  std::string r;
  for (char ch : t.substr(0, 40)) {
    const auto u = static_cast<unsigned char>(ch);
    if (u < 0x20 || u >= 0x7f) {
      static const char* hex = "0123456789abcdef";
      r += "\\x";
      r += hex[u >> 4];
      r += hex[u & 15];
    } else {
      r += ch;
    }
  }
  if (t.size() > 40) r += "...";
  return "'" + r + "'";
}

// Splits a text into lines at '\n'. The last element is what follows the final
// newline (empty for a text that ends with a newline).
std::vector<std::string_view> split_lines(std::string_view text) {
  std::vector<std::string_view> lines;
  std::size_t start = 0;
  for (;;) {
    const std::size_t nl = text.find('\n', start);
    if (nl == std::string_view::npos) {
      lines.push_back(text.substr(start));
      return lines;
    }
    lines.push_back(text.substr(start, nl - start));
    start = nl + 1;
  }
}

// Parses a decimal int64. `strict` rejects leading zeros and "-0" (the
// canonical form); otherwise they are accepted.
std::optional<std::int64_t> to_int(std::string_view t, bool strict, bool& out_of_range) {
  out_of_range = false;
  if (t.empty()) return std::nullopt;
  std::string_view digits = t[0] == '-' ? t.substr(1) : t;
  if (digits.empty()) return std::nullopt;
  for (char ch : digits)
    if (ch < '0' || ch > '9') return std::nullopt;
  if (strict && digits.size() > 1 && digits[0] == '0') return std::nullopt;
  if (strict && t == "-0") return std::nullopt;
  std::int64_t v = 0;
  const auto [ptr, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
  if (ec == std::errc::result_out_of_range) {
    out_of_range = true;
    return std::nullopt;
  }
  if (ec != std::errc() || ptr != t.data() + t.size()) return std::nullopt;
  return v;
}

class LineParser {
 public:
  LineParser(std::string_view file, int line) : file_(file), line_(line) {}

  [[noreturn]] void fail(int column, const std::string& message) const {
    throw ParseError(std::string(file_), line_, column, message);
  }

  std::int64_t integer(const Token& t, bool strict, std::string_view what) const {
    bool out_of_range = false;
    const auto v = to_int(t.text, strict, out_of_range);
    if (out_of_range) fail(t.column, std::string(what) + " " + shown(t.text) + " is out of range (64-bit signed)");
    if (!v) fail(t.column, "expected " + std::string(what) + " (a decimal integer), got " + shown(t.text));
    return *v;
  }

  // Checks W, H, L of a `lattice` line; `keyword` is the column of "lattice".
  LatticeSize lattice(const Token& w, const Token& h, const Token& l, int keyword, bool strict) const {
    LatticeSize size;
    size.W = integer(w, strict, "lattice width W");
    size.H = integer(h, strict, "lattice height H");
    const std::int64_t L = integer(l, strict, "maximum level L");
    if (size.W < 1) fail(w.column, "lattice width W must be >= 1, got " + std::to_string(size.W));
    if (size.H < 1) fail(h.column, "lattice height H must be >= 1, got " + std::to_string(size.H));
    if (L < 0) fail(l.column, "maximum level L must be >= 0, got " + std::to_string(L));
    if (L > 61) fail(l.column, "maximum level L = " + std::to_string(L) + " is above 61 (cell side 2^(L+1) > 2^62)");
    size.L = static_cast<int>(L);
    try {
      validate_lattice_size(size);
    } catch (const LatticeError& e) {
      fail(keyword, e.what());
    }
    return size;
  }

 private:
  std::string_view file_;
  int line_;
};

// Trace tokens: separated by spaces or tabs; '#' starts a comment; a trailing
// '\r' (CRLF files) is ignored. Other control bytes are errors.
// A command has at most four tokens: the first five are kept (an arity error
// names the column of the first extra one), the rest only counted.
struct TraceTokens {
  static constexpr std::size_t kKept = 5;
  std::array<Token, kKept> kept{};
  std::size_t count = 0;
  bool empty() const { return count == 0; }
  std::size_t size() const { return count; }
  const Token& operator[](std::size_t i) const { return kept[i]; }
  void push_back(const Token& t) {
    if (count < kKept) kept[count] = t;
    ++count;
  }
};

TraceTokens trace_tokens(std::string_view line, const LineParser& lp) {
  if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
  TraceTokens tokens;
  std::size_t i = 0;
  while (i < line.size()) {
    const char ch = line[i];
    if (ch == '#') break;
    if (ch == ' ' || ch == '\t') {
      ++i;
      continue;
    }
    const std::size_t start = i;
    while (i < line.size() && line[i] != ' ' && line[i] != '\t' && line[i] != '#') {
      const auto u = static_cast<unsigned char>(line[i]);
      if (u < 0x20 || u >= 0x7f)
        lp.fail(static_cast<int>(i) + 1,
                "unexpected byte " + shown(line.substr(i, 1)) + " (traces are plain ASCII text)");
      ++i;
    }
    tokens.push_back({line.substr(start, i - start), static_cast<int>(start) + 1});
  }
  return tokens;
}

// State tokens: exactly one space between tokens, none at either end.
std::vector<Token> state_tokens(std::string_view line, const LineParser& lp) {
  std::vector<Token> tokens;
  if (line.empty()) lp.fail(1, "empty line (canonical states have no blank lines)");
  std::size_t start = 0;
  for (std::size_t i = 0; i <= line.size(); ++i) {
    if (i < line.size()) {
      const auto u = static_cast<unsigned char>(line[i]);
      if (u == '\r') lp.fail(static_cast<int>(i) + 1, "carriage return (canonical states use '\\n' line ends)");
      if (u != ' ' && (u < 0x20 || u >= 0x7f))
        lp.fail(static_cast<int>(i) + 1, "unexpected byte " + shown(line.substr(i, 1)));
      if (u != ' ') continue;
    }
    if (i == start) {
      if (i == line.size()) lp.fail(static_cast<int>(i), "trailing space");
      lp.fail(static_cast<int>(i) + 1, "expected a single space between fields");
    }
    tokens.push_back({line.substr(start, i - start), static_cast<int>(start) + 1});
    start = i + 1;
  }
  return tokens;
}

// A position in an error message.
std::string shown(const Point& p) { return to_string(p); }

}  // namespace

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

void write_canonical_state(std::ostream& out, const Graph& g) {
  TextWriter w(out);
  w.put("bccmis-state 1\nlattice ");
  w.put_int(g.size.W);
  w.put(' ');
  w.put_int(g.size.H);
  w.put(' ');
  w.put_int(g.size.L);
  w.put('\n');
  auto neighbors = [&](const Point& v) {
    w.put(" :");
    for (const Point& b : g.nbr(v)) w.put_point(b.x, b.y);
    w.put('\n');
  };
  // g.level holds the levels of the centers (and, in a graph built by hand,
  // maybe of other points): walked beside g.C, both sorted.
  auto level = g.level.begin();
  for (const Point& c : g.C) {
    w.put('C');
    w.put_point(c.x, c.y);
    w.put(' ');
    while (level != g.level.end() && level->first < c) ++level;
    if (level != g.level.end() && level->first == c) {
      w.put_int(level->second);
    } else {
      w.put('?');
    }
    neighbors(c);
  }
  for (const Point& n : g.N) {
    w.put('N');
    w.put_point(n.x, n.y);
    neighbors(n);
  }
  w.put("end ");
  w.put_int(static_cast<std::int64_t>(g.C.size()));
  w.put(' ');
  w.put_int(static_cast<std::int64_t>(g.N.size()));
  w.put('\n');
  w.flush();
}

std::string canonical_state(const Graph& g) { return canonical_text(g); }

Graph parse_state(std::string_view text, std::string_view file) {
  const std::vector<std::string_view> lines = split_lines(text);
  Graph g;
  const int nlines = static_cast<int>(lines.size());

  auto at = [&](int index) { return LineParser(file, index + 1); };

  // Line 1: header.
  if (text.empty()) at(0).fail(1, "empty file, expected 'bccmis-state 1'");
  {
    const LineParser lp = at(0);
    const auto t = state_tokens(lines[0], lp);
    if (t[0].text != "bccmis-state") lp.fail(1, "expected 'bccmis-state 1', got " + shown(lines[0]));
    if (t.size() != 2) lp.fail(1, "expected 'bccmis-state 1', got " + shown(lines[0]));
    if (t[1].text != "1")
      lp.fail(t[1].column, "unsupported state format version " + shown(t[1].text) + " (this reader knows version 1)");
  }
  // Line 2: lattice.
  if (nlines < 3)
    at(nlines - 1)
        .fail(static_cast<int>(lines[nlines - 1].size()) + 1, "unexpected end of file, expected 'lattice W H L'");
  {
    const LineParser lp = at(1);
    const auto t = state_tokens(lines[1], lp);
    if (t[0].text != "lattice" || t.size() != 4) lp.fail(1, "expected 'lattice W H L', got " + shown(lines[1]));
    g.size = lp.lattice(t[1], t[2], t[3], 1, true);
  }

  bool in_nodes = false;
  std::optional<Point> previous;
  for (int i = 2;; ++i) {
    if (i == nlines - 1) {
      // The text after the last newline: either the unterminated last line or
      // nothing at all; in both cases the 'end' line was not seen.
      if (lines[i].empty()) at(i).fail(1, "unexpected end of file, expected 'end <#C> <#N>'");
      at(i).fail(static_cast<int>(lines[i].size()) + 1, "missing newline at end of line");
    }
    const LineParser lp = at(i);
    const auto t = state_tokens(lines[i], lp);
    const std::string_view kind = t[0].text;
    if (kind == "end") {
      if (t.size() != 3) lp.fail(1, "expected 'end <#C> <#N>', got " + shown(lines[i]));
      const std::int64_t nc = lp.integer(t[1], true, "center count");
      const std::int64_t nn = lp.integer(t[2], true, "node count");
      if (nc != static_cast<std::int64_t>(g.C.size()))
        lp.fail(t[1].column, "center count " + std::to_string(nc) + " does not match the " +
                                 std::to_string(g.C.size()) + " C lines");
      if (nn != static_cast<std::int64_t>(g.N.size()))
        lp.fail(t[2].column,
                "node count " + std::to_string(nn) + " does not match the " + std::to_string(g.N.size()) + " N lines");
      if (i + 1 != nlines - 1) at(i + 1).fail(1, "text after the 'end' line");
      if (!lines[i + 1].empty()) at(i + 1).fail(1, "text after the 'end' line");
      return g;
    }
    if (kind != "C" && kind != "N") lp.fail(1, "expected a 'C', 'N' or 'end' line, got " + shown(t[0].text));
    const bool center = kind == "C";
    if (center && in_nodes) lp.fail(1, "C line after an N line (all C lines come first)");
    if (!center && !in_nodes) {
      in_nodes = true;
      previous.reset();
    }
    // C x y level : ...   or   N x y : ...
    const std::size_t colon = center ? 4 : 3;
    if (t.size() <= colon || t[colon].text != ":")
      lp.fail(t.size() > colon ? t[colon].column : static_cast<int>(lines[i].size()) + 1,
              center ? "expected 'C x y level : neighbors'" : "expected 'N x y : neighbors'");
    const Point v{lp.integer(t[1], true, "x coordinate"), lp.integer(t[2], true, "y coordinate")};
    if (previous && !(*previous < v))
      lp.fail(t[1].column, std::string(center ? "C" : "N") + " lines must be sorted by (x, y) without repeats; " +
                               shown(v) + " follows " + shown(*previous));
    previous = v;
    if (!center && g.C.count(v))
      lp.fail(t[1].column, "vertex " + shown(v) + " is listed both as a center and as a node");
    if (center) {
      const std::int64_t level = lp.integer(t[3], true, "level");
      if (level < 0 || level > 61) lp.fail(t[3].column, "level " + std::to_string(level) + " is outside 0..61");
      g.C.insert(v);
      g.level[v] = static_cast<int>(level);
    } else {
      g.N.insert(v);
    }
    if ((t.size() - colon - 1) % 2 != 0) lp.fail(t.back().column, "neighbor list has an odd number of coordinates");
    PointSet& nbrs = g.neighbors[v];
    std::optional<Point> prev_nbr;
    for (std::size_t k = colon + 1; k < t.size(); k += 2) {
      const Point w{lp.integer(t[k], true, "x coordinate"), lp.integer(t[k + 1], true, "y coordinate")};
      if (prev_nbr && !(*prev_nbr < w))
        lp.fail(t[k].column,
                "neighbors must be sorted by (x, y) without repeats; " + shown(w) + " follows " + shown(*prev_nbr));
      prev_nbr = w;
      nbrs.insert(w);
    }
    if (nbrs.empty()) g.neighbors.erase(v);
  }
}

// ---- Traces -----------------------------------------------------------------

std::int64_t initial_vertex_count(const LatticeSize& size) {
  const std::int64_t big = INT64_MAX / 4;
  if (size.W <= 0 || size.H <= 0) return 0;
  if (size.W > big / size.H) return INT64_MAX;  // (W+1)(H+1) + WH < 4 W H for W, H >= 2
  return (size.W + 1) * (size.H + 1) + size.W * size.H;
}

Trace parse_trace(std::string_view text, std::string_view file, const TraceLimits& limits) {
  Trace trace;
  trace.file = std::string(file);
  bool have_lattice = false;
  trace.commands.reserve(static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n')) + 1);
  int line_no = 0;
  auto parse_line = [&](std::string_view line) {
    const LineParser lp(file, line_no);
    const auto t = trace_tokens(line, lp);
    if (t.empty()) return;
    const std::string_view cmd = t[0].text;
    auto arity = [&](std::size_t n, const char* usage) {
      if (t.size() != n + 1)
        lp.fail(t.size() > n + 1 ? t[n + 1].column : static_cast<int>(line.size()) + 1,
                std::string(t.size() > n + 1 ? "too many arguments" : "too few arguments") + "; usage: " + usage);
    };
    if (cmd == "lattice") {
      if (have_lattice)
        lp.fail(t[0].column,
                "second 'lattice' command (the first is on line " + std::to_string(trace.lattice_line) + ")");
      arity(3, "lattice W H L");
      trace.size = lp.lattice(t[1], t[2], t[3], t[0].column, false);
      if (const std::int64_t v = initial_vertex_count(trace.size); v > limits.max_vertices)
        lp.fail(t[0].column, "lattice of " + std::to_string(trace.size.W) + " x " + std::to_string(trace.size.H) +
                                 " cells exceeds the limit of " + std::to_string(limits.max_vertices) +
                                 " vertices (it has " +
                                 (v == INT64_MAX ? std::string("more than 2^63") : std::to_string(v)) + ")");
      trace.lattice_line = line_no;
      have_lattice = true;
      return;
    }
    TraceCommand c;
    c.line = line_no;
    if (cmd == "refine" || cmd == "coarsen") {
      c.kind = cmd == "refine" ? TraceCommand::Kind::Refine : TraceCommand::Kind::Coarsen;
      arity(2, cmd == "refine" ? "refine X Y" : "coarsen X Y");
      c.at = {lp.integer(t[1], false, "x coordinate"), lp.integer(t[2], false, "y coordinate")};
    } else if (cmd == "check") {
      arity(0, "check");
    } else {
      lp.fail(t[0].column, "unknown command " + shown(cmd) + " (expected lattice, refine, coarsen or check)");
    }
    if (!have_lattice) lp.fail(t[0].column, "'" + std::string(cmd) + "' before the 'lattice W H L' command");
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
    throw ParseError(std::string(file), std::max(last, 1), 1, "no 'lattice W H L' command (a trace starts with one)");
  }
  trace.commands.shrink_to_fit();
  return trace;
}

std::string format_trace(const Trace& trace) {
  std::string out = "lattice " + std::to_string(trace.size.W) + " " + std::to_string(trace.size.H) + " " +
                    std::to_string(trace.size.L) + "\n";
  for (const TraceCommand& c : trace.commands) {
    append_command_text(out, c);
    out += '\n';
  }
  return out;
}

void append_command_text(std::string& out, const TraceCommand& cmd) {
  std::string_view keyword = "check";
  switch (cmd.kind) {
    case TraceCommand::Kind::Refine: keyword = "refine"; break;
    case TraceCommand::Kind::Coarsen: keyword = "coarsen"; break;
    case TraceCommand::Kind::Check: break;
  }
  out += keyword;
  if (cmd.kind == TraceCommand::Kind::Check) return;
  char buf[TextWriter::kPointBytes];
  out.append(buf, TextWriter::write_point(buf, cmd.at.x, cmd.at.y));
}

void append_decision_line(std::string& out, const TraceCommand& cmd, std::string_view refusal_code) {
  append_command_text(out, cmd);
  if (refusal_code.empty()) {
    out += " ok";
    return;
  }
  out += " refused ";
  out += refusal_code;
}

std::string command_text(const TraceCommand& cmd) {
  std::string out;
  append_command_text(out, cmd);
  return out;
}

std::string decision_line(const TraceCommand& cmd, std::string_view refusal_code) {
  std::string out;
  append_decision_line(out, cmd, refusal_code);
  return out;
}

}  // namespace bccmis
