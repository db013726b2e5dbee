// S27's topology of a stuffed mesh (topology.h).
#include "bccmis/stuff/topology.h"

#include <algorithm>
#include <cstdint>
#include <numeric>

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
  // The boundary: V - E + F, and the edges in more than two triangles: the
  // edges as (low, high) keys, sorted, one run of equal keys an edge.
  std::vector<std::uint64_t> edges;
  edges.reserve(3 * boundary.size());
  for (const auto& tri : boundary)
    for (std::size_t i = 0; i < 3; ++i) {
      const std::uint32_t a = tri[i], b = tri[(i + 1) % 3];
      edges.push_back(std::uint64_t{std::min(a, b)} << 32 | std::max(a, b));
    }
  std::sort(edges.begin(), edges.end());
  std::size_t edge_count = 0;
  for (std::size_t e = 0; e < edges.size();) {
    std::size_t end = e + 1;
    while (end < edges.size() && edges[end] == edges[e]) ++end;
    ++edge_count;
    if (end - e > 2) ++t.nonmanifold_edges;
    e = end;
  }
  const auto vertex_count = static_cast<long long>(std::count(used.begin(), used.end(), char{1}));
  t.boundary_euler = vertex_count - static_cast<long long>(edge_count) + static_cast<long long>(boundary.size());
  return t;
}

}  // namespace bccmis::stuff
