// Checks on a stuffed mesh: its boundary triangles (spec/stuffing.md S11)
// and whether two meshes hold the same tetrahedra (S16).
#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <tuple>
#include <utility>
#include <vector>

#include "bccmis/stuff/stuff.h"

namespace bccmis::stuff {

std::vector<std::array<std::uint32_t, 3>> boundary_triangles(const d3::TetMeshF& mesh) {
  // The face opposite v_i of a positive tetrahedron, outward.
  static constexpr int kFaces[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};
  const auto face = [&](std::size_t id) {
    const auto& t = mesh.tets[id / 4];
    const int* f = kFaces[id % 4];
    return std::array<std::uint32_t, 3>{t[static_cast<std::size_t>(f[0])], t[static_cast<std::size_t>(f[1])],
                                        t[static_cast<std::size_t>(f[2])]};
  };
  // Every face filed under its smallest vertex (a counting sort), then each
  // vertex's faces sorted by the other two: the faces in the order of their
  // sorted vertex triples; a triple met once is a boundary triangle.
  struct Filed {
    std::uint32_t mid, high;
    std::size_t id;  ///< 4 t + i: the face opposite v_i of tetrahedron t
  };
  std::vector<std::size_t> start(mesh.vertices.size() + 1, 0);
  for (const auto& t : mesh.tets)
    for (const auto& f : kFaces)
      ++start[std::min({t[static_cast<std::size_t>(f[0])], t[static_cast<std::size_t>(f[1])],
                        t[static_cast<std::size_t>(f[2])]}) +
              1];
  for (std::size_t v = 1; v < start.size(); ++v) start[v] += start[v - 1];
  std::vector<Filed> filed(start.back());
  std::vector<std::size_t> next(start.begin(), start.end() - 1);
  for (std::size_t id = 0; id < 4 * mesh.tets.size(); ++id) {
    std::array<std::uint32_t, 3> key = face(id);
    std::sort(key.begin(), key.end());
    filed[next[key[0]]++] = {key[1], key[2], id};
  }
  std::vector<std::array<std::uint32_t, 3>> out;
  const auto before = [](const Filed& a, const Filed& b) { return std::tie(a.mid, a.high) < std::tie(b.mid, b.high); };
  for (std::size_t v = 0; v + 1 < start.size(); ++v) {
    const auto first = filed.begin() + static_cast<std::ptrdiff_t>(start[v]),
               last = filed.begin() + static_cast<std::ptrdiff_t>(start[v + 1]);
    std::sort(first, last, before);
    for (auto run = first; run != last;) {
      auto end = run + 1;
      while (end != last && !before(*run, *end)) ++end;
      if (end - run == 1) out.push_back(face(run->id));
      run = end;
    }
  }
  return out;
}

namespace {
using Corner = std::tuple<double, double, double, std::uint8_t>;
using Canonical = std::pair<int, std::array<Corner, 4>>;
std::vector<Canonical> canonical(const d3::TetMeshF& m) {
  std::vector<Canonical> out;
  out.reserve(m.tets.size());
  for (std::size_t t = 0; t < m.tets.size(); ++t) {
    Canonical c{m.level.empty() ? 0 : m.level[t], {}};
    for (std::size_t i = 0; i < 4; ++i) {
      const std::uint32_t v = m.tets[t][i];
      c.second[i] = {m.vertices[v][0], m.vertices[v][1], m.vertices[v][2], m.kind.empty() ? 0 : m.kind[v]};
    }
    std::sort(c.second.begin(), c.second.end());
    out.push_back(c);
  }
  std::sort(out.begin(), out.end());
  return out;
}
}  // namespace

bool same_tetrahedra(const d3::TetMeshF& a, const d3::TetMeshF& b) {
  return a.tets.size() == b.tets.size() && canonical(a) == canonical(b);
}

}  // namespace bccmis::stuff
