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

#include "bccmis/io/detail/tokens.h"
#include "bccmis/io/parse_error.h"

namespace bccmis::io {

namespace {

using detail::Tokens;

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
