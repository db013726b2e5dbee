// The STL reader (stl.h): ASCII and binary, the repeated corners of the
// triangles merged exactly.
#include "bccmis/io/stl.h"

#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <map>
#include <string_view>

#include "bccmis/io/detail/line_scanner.h"
#include "bccmis/io/surface_format.h"

namespace bccmis::io {

namespace {

/// Exact merging of the STL's repeated corners.
struct Merger {
  TriangleSoup& s;
  std::map<d3::Vec3, std::uint32_t> index;
  std::uint32_t operator()(const d3::Vec3& p) {
    const auto [it, fresh] = index.try_emplace(p, static_cast<std::uint32_t>(s.vertices.size()));
    if (fresh) s.vertices.push_back(p);
    return it->second;
  }
};

/// The rest of a `facet` line: "normal nx ny nz", or anything else (NaN).
d3::Vec3 read_normal(detail::LineScanner& t) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  d3::Vec3 n{nan, nan, nan};
  if (t.token(false) != "normal") {
    while (!t.token(false).empty()) {
    }
    return n;
  }
  for (auto& c : n) {
    const std::string_view w = t.token(false);
    double x = nan;
    const auto [ptr, ec] = std::from_chars(w.data(), w.data() + w.size(), x);
    c = !w.empty() && ec == std::errc() && ptr == w.data() + w.size() ? x : nan;
  }
  while (!t.token(false).empty()) {
  }
  return n;
}

TriangleSoup read_stl_ascii(const std::string& file, const std::string& data) {
  detail::LineScanner t(file, data);
  TriangleSoup s;
  Merger merge{s, {}};
  auto next = [&](const char* what) {
    do {
      if (!t.next_line()) t.fail(std::string("unexpected end of file, expected ") + what);
    } while (t.line_blank());
  };
  auto expect = [&](std::string_view word) {
    const std::string_view w = t.token(false);
    if (w != word) t.fail("expected '" + std::string(word) + "', found '" + std::string(w) + "'");
  };
  next("'solid'");
  expect("solid");
  std::size_t facets = 0;
  for (;;) {
    next("'facet' or 'endsolid'");
    const std::string_view w = t.token(false);
    if (w == "endsolid") break;
    if (w != "facet") t.fail("expected 'facet' or 'endsolid', found '" + std::string(w) + "'");
    const std::size_t line = t.line();
    // The normal is ignored (the vertex order defines the orientation): any
    // tokens after "facet" on its line are accepted, "normal" and its three
    // components included, whatever they are; those that do not read as
    // three finite numbers give a normal of NaN.
    s.normals.push_back(read_normal(t));
    next("'outer loop'");
    expect("outer");
    expect("loop");
    std::array<std::uint32_t, 3> tri{};
    for (auto& v : tri) {
      next("'vertex'");
      expect("vertex");
      const double x = t.number("a coordinate"), y = t.number("a coordinate"), z = t.number("a coordinate");
      v = merge({x, y, z});
    }
    next("'endloop'");
    expect("endloop");
    next("'endfacet'");
    expect("endfacet");
    s.triangles.push_back(tri);
    s.face.push_back(facets++);
    s.line.push_back(line);
  }
  return s;
}

TriangleSoup read_stl_binary(const std::string& file, const std::string& data) {
  auto fail = [&](std::size_t offset, const std::string& what) -> void {
    throw ReadError(file + ": byte " + std::to_string(offset) + ": " + what);
  };
  if (data.size() < 84)
    fail(data.size(), "binary STL truncated in its 84-byte header (" + std::to_string(data.size()) + " bytes)");
  const auto u8 = [&](std::size_t i) { return static_cast<std::uint32_t>(static_cast<unsigned char>(data[i])); };
  const std::uint32_t n = u8(80) | u8(81) << 8 | u8(82) << 16 | u8(83) << 24;
  const std::size_t expected = 84 + 50 * static_cast<std::size_t>(n);
  if (data.size() < expected) {
    const std::size_t whole = (data.size() - 84) / 50;
    fail(84 + 50 * whole, "binary STL truncated in triangle " + std::to_string(whole) + " of " + std::to_string(n) +
                              " (" + std::to_string(expected) + " bytes expected, " + std::to_string(data.size()) +
                              " present)");
  }
  if (data.size() > expected)
    fail(expected, "binary STL has " + std::to_string(data.size() - expected) + " bytes after its " +
                       std::to_string(n) + " triangles");
  TriangleSoup s;
  Merger merge{s, {}};
  for (std::size_t f = 0; f < n; ++f) {
    const std::size_t at = 84 + 50 * f;
    std::array<std::uint32_t, 3> tri{};
    for (int k = 0; k < 3; ++k) {
      d3::Vec3 p{};
      for (int c = 0; c < 3; ++c) {
        const std::size_t off = at + 12 + 12 * static_cast<std::size_t>(k) + 4 * static_cast<std::size_t>(c);
        const std::uint32_t bits = u8(off) | u8(off + 1) << 8 | u8(off + 2) << 16 | u8(off + 3) << 24;
        float x = 0;
        std::memcpy(&x, &bits, sizeof x);
        if (!std::isfinite(x)) fail(off, "binary STL: triangle " + std::to_string(f) + ": coordinate not finite");
        p[static_cast<std::size_t>(c)] = static_cast<double>(x);
      }
      tri[static_cast<std::size_t>(k)] = merge(p);
    }
    d3::Vec3 normal{};
    for (int c = 0; c < 3; ++c) {
      const std::size_t off = at + 4 * static_cast<std::size_t>(c);
      const std::uint32_t bits = u8(off) | u8(off + 1) << 8 | u8(off + 2) << 16 | u8(off + 3) << 24;
      float x = 0;
      std::memcpy(&x, &bits, sizeof x);
      normal[static_cast<std::size_t>(c)] = static_cast<double>(x);
    }
    s.normals.push_back(normal);
    s.triangles.push_back(tri);
    s.face.push_back(f);
    s.line.push_back(0);
  }
  return s;
}

}  // namespace

TriangleSoup read_stl(const std::string& file, const std::string& data) {
  // Binary when the size matches the triangle count at byte 80 (binary
  // headers may start with "solid" too); else ASCII when the file starts with
  // "solid" or is text (the ASCII reader then names what it found instead).
  if (data.size() >= 84) {
    const auto u8 = [&](std::size_t i) { return static_cast<std::uint32_t>(static_cast<unsigned char>(data[i])); };
    const std::uint64_t n = u8(80) | u8(81) << 8 | u8(82) << 16 | u8(83) << 24;
    if (data.size() == 84 + 50 * n) return read_stl_binary(file, data);
  }
  std::size_t i = 0;
  while (i < data.size() && std::isspace(static_cast<unsigned char>(data[i]))) ++i;
  if (data.compare(i, 5, "solid") == 0 || is_text(data)) return read_stl_ascii(file, data);
  return read_stl_binary(file, data);
}

}  // namespace bccmis::io
