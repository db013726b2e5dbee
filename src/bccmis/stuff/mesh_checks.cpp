// Checks on a stuffed mesh: its boundary triangles (spec/stuffing.md S11)
// and whether two meshes hold the same tetrahedra (S16).
#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <tuple>
#include <utility>
#include <vector>

#include "bccmis/io/tet_faces.h"
#include "bccmis/stuff/stuff.h"

namespace bccmis::stuff {

std::vector<std::array<std::uint32_t, 3>> boundary_triangles(const d3::TetMeshF& mesh) {
  // A vertex triple met once is a boundary triangle (io/tet_faces.h).
  std::vector<std::array<std::uint32_t, 3>> out;
  io::for_each_face_group(mesh.tets, mesh.vertices.size(), [&](const std::size_t* first, const std::size_t* last) {
    if (last - first == 1) out.push_back(io::outward_face(mesh.tets, *first));
  });
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
