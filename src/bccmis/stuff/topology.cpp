// S27's topology of a stuffed mesh (topology.h).
#include "bccmis/stuff/topology.h"

#include <algorithm>
#include <map>
#include <numeric>
#include <set>
#include <utility>

namespace bccmis::stuff {

MeshTopology topology(const d3::TetMeshF& mesh, const std::vector<std::array<std::uint32_t, 3>>& boundary) {
  MeshTopology t;
  // Components of the boundary: union-find over the vertices of each triangle.
  std::vector<std::uint32_t> parent(mesh.vertices.size());
  std::iota(parent.begin(), parent.end(), 0u);
  const auto find = [&](std::uint32_t v) {
    while (parent[v] != v) v = parent[v] = parent[parent[v]];
    return v;
  };
  std::vector<char> used(mesh.vertices.size(), 0);
  for (const auto& tri : boundary)
    for (std::size_t i = 0; i < 3; ++i) {
      used[tri[i]] = 1;
      parent[find(tri[i])] = find(tri[0]);
    }
  for (std::uint32_t v = 0; v < parent.size(); ++v)
    if (used[v] && find(v) == v) ++t.boundary_components;
  // The boundary: V - E + F, and the edges in more than two triangles.
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> edges;
  std::set<std::uint32_t> vertices;
  for (const auto& tri : boundary)
    for (std::size_t i = 0; i < 3; ++i) {
      vertices.insert(tri[i]);
      const std::uint32_t a = tri[i], b = tri[(i + 1) % 3];
      ++edges[{std::min(a, b), std::max(a, b)}];
    }
  for (const auto& [e, n] : edges)
    if (n > 2) ++t.nonmanifold_edges;
  t.boundary_euler = static_cast<long long>(vertices.size()) - static_cast<long long>(edges.size()) +
                     static_cast<long long>(boundary.size());
  return t;
}

}  // namespace bccmis::stuff
