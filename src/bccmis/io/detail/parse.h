// bccmis: the tokenizers and the canonical-state parser shared by the 2D
// formats (io/format.cpp) and the 3D ones (io/d3/format.cpp). Internal: include
// bccmis/io/format.h or bccmis/io/d3/format.h instead.
#pragma once

#include <algorithm>
#include <array>
#include <charconv>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "bccmis/d3/point.h"
#include "bccmis/graph.h"
#include "bccmis/io/parse_error.h"

namespace bccmis::detail {

// A word of a line and the 1-based column where it starts.
struct Token {
  std::string_view text;
  int column;
};

// Shows a token in an error message, shortened and with control bytes escaped.
inline std::string shown(std::string_view t) {
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
inline std::vector<std::string_view> split_lines(std::string_view text) {
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
inline std::optional<std::int64_t> to_int(std::string_view t, bool strict, bool& out_of_range) {
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
    LatticeSize size = lattice_numbers(w, h, l, strict);
    try {
      validate_lattice_size(size);
    } catch (const LatticeError& e) {
      fail(keyword, e.what());
    }
    return size;
  }

  // Checks W, H, D, L of a 3D `lattice` line; `keyword` is the column of "lattice".
  d3::LatticeSize lattice3(const Token& w, const Token& h, const Token& d, const Token& l, int keyword,
                           bool strict) const {
    const LatticeSize plane = lattice_numbers(w, h, l, strict);
    d3::LatticeSize size{plane.W, plane.H, integer(d, strict, "lattice depth D"), plane.L};
    if (size.D < 1) fail(d.column, "lattice depth D must be >= 1, got " + std::to_string(size.D));
    try {
      d3::validate_lattice_size(size);
    } catch (const LatticeError& e) {
      fail(keyword, e.what());
    }
    return size;
  }

 private:
  // W, H and L with their own range checks (not yet the extents).
  LatticeSize lattice_numbers(const Token& w, const Token& h, const Token& l, bool strict) const {
    LatticeSize size;
    size.W = integer(w, strict, "lattice width W");
    size.H = integer(h, strict, "lattice height H");
    const std::int64_t L = integer(l, strict, "maximum level L");
    if (size.W < 1) fail(w.column, "lattice width W must be >= 1, got " + std::to_string(size.W));
    if (size.H < 1) fail(h.column, "lattice height H must be >= 1, got " + std::to_string(size.H));
    if (L < 0) fail(l.column, "maximum level L must be >= 0, got " + std::to_string(L));
    if (L > 61) fail(l.column, "maximum level L = " + std::to_string(L) + " is above 61 (cell side 2^(L+1) > 2^62)");
    size.L = static_cast<int>(L);
    return size;
  }

  std::string_view file_;
  int line_;
};

// Trace tokens: separated by spaces or tabs; '#' starts a comment; a trailing
// '\r' (CRLF files) is ignored. Other control bytes are errors.
// A command has at most five tokens (`lattice W H D L`): the first six are
// kept (an arity error names the column of the first extra one), the rest
// only counted.
struct TraceTokens {
  static constexpr std::size_t kKept = 6;
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

inline TraceTokens trace_tokens(std::string_view line, const LineParser& lp) {
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
inline std::vector<Token> state_tokens(std::string_view line, const LineParser& lp) {
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

// ---- Canonical state, either dimension --------------------------------------

/// The strict parser of spec/formats.md, "Canonical state" (and its 3D
/// extension), for a graph type G with the members of Graph / d3::Graph.
template <class G>
G parse_state_as(std::string_view text, std::string_view file) {
  using P = typename G::point_type;
  constexpr bool k3 = G::dimension == 3;
  constexpr std::size_t dim = k3 ? 3 : 2;
  const char* const lattice_usage = k3 ? "lattice W H D L" : "lattice W H L";
  const char* const order = k3 ? "(x, y, z)" : "(x, y)";
  const std::vector<std::string_view> lines = split_lines(text);
  G g;
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
        .fail(static_cast<int>(lines[nlines - 1].size()) + 1,
              std::string("unexpected end of file, expected '") + lattice_usage + "'");
  {
    const LineParser lp = at(1);
    const auto t = state_tokens(lines[1], lp);
    if (t[0].text != "lattice" || t.size() != dim + 2)
      lp.fail(1, std::string("expected '") + lattice_usage + "', got " + shown(lines[1]) +
                     (t[0].text == "lattice" && t.size() == (k3 ? 4 : 5)
                          ? (k3 ? " (a 2D state: three numbers)" : " (a 3D state: four numbers)")
                          : ""));
    if constexpr (k3)
      g.size = lp.lattice3(t[1], t[2], t[3], t[4], 1, true);
    else
      g.size = lp.lattice(t[1], t[2], t[3], 1, true);
  }

  static constexpr const char* kAxis[] = {"x coordinate", "y coordinate", "z coordinate"};
  auto point = [&](const LineParser& lp, const std::vector<Token>& t, std::size_t first) {
    P v{};
    if constexpr (k3)
      v = P{lp.integer(t[first], true, kAxis[0]), lp.integer(t[first + 1], true, kAxis[1]),
            lp.integer(t[first + 2], true, kAxis[2])};
    else
      v = P{lp.integer(t[first], true, kAxis[0]), lp.integer(t[first + 1], true, kAxis[1])};
    return v;
  };

  bool in_nodes = false;
  std::optional<P> previous;
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
    // C x y [z] level : ...   or   N x y [z] : ...
    const std::size_t colon = center ? dim + 2 : dim + 1;
    if (t.size() <= colon || t[colon].text != ":")
      lp.fail(t.size() > colon ? t[colon].column : static_cast<int>(lines[i].size()) + 1,
              center ? (k3 ? "expected 'C x y z level : neighbors'" : "expected 'C x y level : neighbors'")
                     : (k3 ? "expected 'N x y z : neighbors'" : "expected 'N x y : neighbors'"));
    const P v = point(lp, t, 1);
    if (previous && !(*previous < v))
      lp.fail(t[1].column, std::string(center ? "C" : "N") + " lines must be sorted by " + order +
                               " without repeats; " + to_string(v) + " follows " + to_string(*previous));
    previous = v;
    if (!center && g.C.count(v))
      lp.fail(t[1].column, "vertex " + to_string(v) + " is listed both as a center and as a node");
    if (center) {
      const std::int64_t level = lp.integer(t[dim + 1], true, "level");
      if (level < 0 || level > 61) lp.fail(t[dim + 1].column, "level " + std::to_string(level) + " is outside 0..61");
      g.C.insert(v);
      g.level[v] = static_cast<int>(level);
    } else {
      g.N.insert(v);
    }
    if ((t.size() - colon - 1) % dim != 0)
      lp.fail(t.back().column, k3 ? "neighbor list's coordinate count is not a multiple of 3"
                                  : "neighbor list has an odd number of coordinates");
    auto& nbrs = g.neighbors[v];
    std::optional<P> prev_nbr;
    for (std::size_t k = colon + 1; k < t.size(); k += dim) {
      const P w = point(lp, t, k);
      if (prev_nbr && !(*prev_nbr < w))
        lp.fail(t[k].column, std::string("neighbors must be sorted by ") + order + " without repeats; " + to_string(w) +
                                 " follows " + to_string(*prev_nbr));
      prev_nbr = w;
      nbrs.insert(w);
    }
    if (nbrs.empty()) g.neighbors.erase(v);
  }
}

}  // namespace bccmis::detail
