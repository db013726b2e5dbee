// bccmis::stuff::topology: what a stuffed mesh is, to compare with what its
// shape is (spec/stuffing.md S27): its boundary's connected components, the Euler
// characteristic of its boundary and the boundary's non-manifold edges.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "bccmis/d3/mesh.h"

namespace bccmis::stuff {

struct MeshTopology {
  std::size_t boundary_components = 0;  ///< boundary triangles joined by shared vertices
  long long boundary_euler = 0;         ///< V - E + F of the boundary triangles
  std::size_t nonmanifold_edges = 0;    ///< boundary edges in more than two boundary triangles
};

/// S27 on `mesh` and its boundary (boundary_triangles(mesh)).
MeshTopology topology(const d3::TetMeshF& mesh, const std::vector<std::array<std::uint32_t, 3>>& boundary);

}  // namespace bccmis::stuff
