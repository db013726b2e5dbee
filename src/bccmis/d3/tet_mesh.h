// bccmis::d3: the indexed tetrahedral mesh, as the writers and readers of
// bccmis/io/ take and give it: the lattice's mesh (integer vertices) and a
// mesh in space (double vertices, isosurface stuffing).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "bccmis/d3/point.h"

namespace bccmis::d3 {

/// The kind of a mesh vertex (TetMesh::kind).
enum class VertexKind : std::uint8_t { node = 0, center = 1, hull = 2 };

/// A point in space (double coordinates): the vertices of meshes whose
/// vertices are not lattice points (isosurface stuffing, spec/stuffing.md).
using Vec3 = std::array<double, 3>;

/// An indexed mesh for writers: vertices, tets as indices into them, a small
/// integer per vertex (written as the point data "kind") and one per
/// tetrahedron (the cell data "level"). P is Point (lattice coordinates,
/// written as integers) or Vec3 (written as the shortest decimal that reads
/// back to the same double).
template <class P>
struct BasicTetMesh {
  std::vector<P> vertices;
  std::vector<std::array<std::uint32_t, 4>> tets;
  std::vector<std::uint8_t> kind; /* per vertex */
  std::vector<int> level;         /* per tetrahedron */
};

/// The lattice's mesh: vertices sorted by position, kind 0 node, 1 center,
/// 2 hull, level the level of the tetrahedron's leaf v[0].
using TetMesh = BasicTetMesh<Point>;
/// A mesh in space (spec/stuffing.md S11).
using TetMeshF = BasicTetMesh<Vec3>;

}  // namespace bccmis::d3
