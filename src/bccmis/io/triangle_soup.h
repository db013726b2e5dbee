// bccmis::io: a triangle soup as the surface readers (.off, .obj, .ply, .stl)
// give it, with what messages about it need.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "bccmis/d3/tet_mesh.h"

namespace bccmis::io {

/// Vertices and triangles as read; for each triangle the face of the input
/// it comes from (a polygon is fanned into several) and that face's line (0
/// when there is none: binary STL and PLY), and the number the input gives its first vertex (1
/// for OBJ, 0 otherwise).
struct TriangleSoup {
  std::vector<d3::Vec3> vertices;
  std::vector<std::array<std::uint32_t, 3>> triangles;
  std::vector<std::size_t> face;
  std::vector<std::size_t> line;
  std::uint32_t vertex_base = 0;
  /// STL only: the facet normals as written (NaN where an ASCII file has no
  /// three numbers there), one per triangle; empty for OFF and OBJ. Ignored
  /// but for the report of bad normals.
  std::vector<d3::Vec3> normals;
};

}  // namespace bccmis::io
