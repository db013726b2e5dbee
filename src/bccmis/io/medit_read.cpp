// The Medit reader (medit.h): a tokenizer that knows each token's line
// and column, and one pass over the sections.
#include "bccmis/io/medit.h"

#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <string>
#include <system_error>

#include "bccmis/io/parse_error.h"

namespace bccmis::io {

namespace {

class Tokens {
 public:
  Tokens(std::string_view text, const std::string& name) : text_(text), name_(name) {}

  struct Token {
    std::string_view text;  // empty at the end of the input
    int line = 1, column = 1;
  };

  // The next token; comments (# to the end of the line) and whitespace skipped.
  Token next() {
    skip();
    Token t{{}, line_, column_};
    const std::size_t start = pos_;
    while (pos_ < text_.size() && !space(text_[pos_]) && text_[pos_] != '#') {
      check_byte();
      ++pos_;
      ++column_;
    }
    t.text = text_.substr(start, pos_ - start);
    return t;
  }

  [[noreturn]] void fail(const Token& t, const std::string& message) const {
    throw ParseError(name_, t.line, t.column, message);
  }

  // The next token as an integer in [lo, hi]; `what` names it in messages.
  std::int64_t integer(const char* what, std::int64_t lo, std::int64_t hi) {
    const Token t = next();
    if (t.text.empty()) fail(t, std::string("unexpected end of file: expected ") + what);
    std::int64_t v = 0;
    const auto [end, ec] = std::from_chars(t.text.data(), t.text.data() + t.text.size(), v);
    if (ec == std::errc::result_out_of_range ||
        (ec == std::errc() && end == t.text.data() + t.text.size() && (v < lo || v > hi)))
      fail(t, std::string(what) + " '" + shown(t.text) + "' is out of range [" + std::to_string(lo) + ", " +
                  std::to_string(hi) + "]");
    if (ec != std::errc() || end != t.text.data() + t.text.size())
      fail(t, std::string("expected ") + what + ", got '" + shown(t.text) + "'");
    return v;
  }

  // The next token as a finite double.
  double real(const char* what) {
    const Token t = next();
    if (t.text.empty()) fail(t, std::string("unexpected end of file: expected ") + what);
    double v = 0;
    const auto [end, ec] = std::from_chars(t.text.data(), t.text.data() + t.text.size(), v);
    if (ec != std::errc() || end != t.text.data() + t.text.size())
      fail(t, std::string("expected ") + what + " (a decimal number), got '" + shown(t.text) + "'");
    if (!std::isfinite(v)) fail(t, std::string(what) + " '" + shown(t.text) + "' is not finite");
    return v;
  }

 private:
  static bool space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

  static std::string shown(std::string_view s) {
    return s.size() <= 40 ? std::string(s) : std::string(s.substr(0, 40)) + "...";
  }

  void check_byte() const {
    const auto c = static_cast<unsigned char>(text_[pos_]);
    if (c < 0x20 || c >= 0x7f) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\x%02x", c);
      throw ParseError(name_, line_, column_, std::string("unexpected byte '") + buf + "'");
    }
  }

  void skip() {
    while (pos_ < text_.size()) {
      const char c = text_[pos_];
      if (c == '\n') {
        ++line_;
        column_ = 1;
        ++pos_;
      } else if (space(c)) {
        ++column_;
        ++pos_;
      } else if (c == '#') {
        while (pos_ < text_.size() && text_[pos_] != '\n') {
          ++pos_;
          ++column_;
        }
      } else {
        return;
      }
    }
  }

  std::string_view text_;
  const std::string& name_;
  std::size_t pos_ = 0;
  int line_ = 1, column_ = 1;
};

constexpr std::int64_t kMaxCount = std::numeric_limits<std::uint32_t>::max() - 1;

}  // namespace

d3::TetMeshF read_medit(std::string_view text, const std::string& name, Orientation orientation) {
  Tokens in(text, name);
  d3::TetMeshF mesh;
  bool version = false, dimension = false, vertices = false, tetrahedra = false, triangles = false;
  for (;;) {
    const Tokens::Token key = in.next();
    if (key.text.empty()) {
      if (!version) in.fail(key, "unexpected end of file: expected 'MeshVersionFormatted'");
      in.fail(key, "unexpected end of file: expected 'End'");
    }
    if (!version && key.text != "MeshVersionFormatted")
      in.fail(key, "expected 'MeshVersionFormatted', got '" + std::string(key.text.substr(0, 40)) + "'");
    const auto once = [&](bool& seen) {
      if (seen) in.fail(key, "a second '" + std::string(key.text) + "' section");
      seen = true;
    };
    if (key.text == "MeshVersionFormatted") {
      once(version);
      in.integer("the version", 1, 2);
    } else if (key.text == "Dimension") {
      once(dimension);
      in.integer("the dimension", 3, 3);
    } else if (key.text == "Vertices") {
      if (!dimension) in.fail(key, "'Vertices' before 'Dimension 3'");
      once(vertices);
      const std::int64_t n = in.integer("the number of vertices", 0, kMaxCount);
      for (std::int64_t i = 0; i < n; ++i) {
        d3::Vec3 p{};
        p[0] = in.real("x coordinate");
        p[1] = in.real("y coordinate");
        p[2] = in.real("z coordinate");
        mesh.vertices.push_back(p);
        mesh.kind.push_back(static_cast<std::uint8_t>(in.integer("the vertex reference", 0, 255)));
      }
    } else if (key.text == "Tetrahedra" || key.text == "Triangles") {
      const bool tets = key.text == "Tetrahedra";
      if (!vertices) in.fail(key, "'" + std::string(key.text) + "' before 'Vertices'");
      once(tets ? tetrahedra : triangles);
      const std::int64_t n = in.integer(tets ? "the number of tetrahedra" : "the number of triangles", 0, kMaxCount);
      const auto nv = static_cast<std::int64_t>(mesh.vertices.size());
      for (std::int64_t i = 0; i < n; ++i) {
        std::array<std::uint32_t, 4> t{};
        std::array<Tokens::Token, 4> at{};
        for (std::size_t k = 0; k < (tets ? 4u : 3u); ++k) {
          Tokens probe = in;  // the index's position, for the messages below
          at[k] = probe.next();
          t[k] = static_cast<std::uint32_t>(in.integer("a vertex index", 1, nv) - 1);
          for (std::size_t j = 0; j < k; ++j)
            if (t[j] == t[k]) in.fail(at[k], "vertex " + std::to_string(t[k] + 1) + " appears twice");
        }
        if (!tets) {
          in.integer("the triangle reference", std::numeric_limits<int>::min(), std::numeric_limits<int>::max());
          continue;
        }
        const int level = static_cast<int>(in.integer("the tetrahedron reference (its level)", 0, 63));
        const auto& v = mesh.vertices;
        if (orientation(v[t[0]], v[t[1]], v[t[2]], v[t[3]]) <= 0)
          in.fail(at[0], "tetrahedron " + std::to_string(i + 1) + " is " +
                             (orientation(v[t[0]], v[t[1]], v[t[2]], v[t[3]]) == 0 ? "flat" : "negatively oriented") +
                             " (det[v1 - v0, v2 - v0, v3 - v0] must be positive)");
        mesh.tets.push_back(t);
        mesh.level.push_back(level);
      }
    } else if (key.text == "End") {
      if (!tetrahedra) in.fail(key, "'End' before a 'Tetrahedra' section");
      const Tokens::Token after = in.next();
      if (!after.text.empty()) in.fail(after, "text after 'End'");
      return mesh;
    } else {
      in.fail(key, "unknown keyword '" + std::string(key.text.substr(0, 40)) +
                       "' (expected Dimension, Vertices, Tetrahedra, Triangles or End)");
    }
  }
}

}  // namespace bccmis::io
