// bccmis::d3: the graded BCC tetrahedral mesh of a 3D lattice
// (spec/mesh3d.md), its exact orientation and volume, its dihedral angles and
// quality. The mesh types are in d3/tet_mesh.h, their writers in bccmis/io/.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "bccmis/d3/graph.h"
#include "bccmis/d3/tet_mesh.h"

namespace bccmis::d3 {

/// One tetrahedron by its 4 vertex positions, positively oriented:
/// det[v1-v0, v2-v0, v3-v0] > 0.  v[0] is the leaf center u, v[1] the apex.
using Tet = std::array<Point, 4>;

/// Every tetrahedron of the graded BCC mesh of g (spec/mesh3d.md), each once,
/// positively oriented, sorted (std::sort on Tet). Hull vertices (centers of
/// domain-boundary faces) appear as vertices that are in neither g.N nor g.C.
/// Throws std::logic_error if g is not a reachable state (an apex the graph
/// does not have, or a degenerate tetrahedron).
std::vector<Tet> tetrahedra(const Graph& g);

/// A signed 128-bit integer (a GNU extension that g++ and clang++ provide).
__extension__ typedef __int128 Int128;

/// det[b - a, c - a, d - a] computed exactly: its sign (-1, 0 or 1), for
/// coordinates up to 2^62 (spec/mesh3d.md M3).
int orientation(const Point& a, const Point& b, const Point& c, const Point& d);

/// det[t1 - t0, t2 - t0, t3 - t0] = 6 times the signed volume, exactly, when
/// it fits in a signed 128-bit integer (every coordinate difference below 2^41);
/// throws std::overflow_error otherwise.
Int128 six_volume(const Tet& t);

/// The vertices of `tets` (sorted, each once, with their kind in g) and the
/// tetrahedra as indices into them, in the order of `tets`.
TetMesh index_mesh(const Graph& g, const std::vector<Tet>& tets);

/// The 6 dihedral angles of t in degrees (long double arithmetic, so within
/// about 1e-12 degrees of the exact values), in the order of the edges
/// v0v1, v0v2, v0v3, v1v2, v1v3, v2v3.
std::array<double, 6> dihedral_angles(const Tet& t);
/// The same for a tetrahedron in space.
std::array<double, 6> dihedral_angles(const std::array<Vec3, 4>& t);
/// The cosines of those angles, in the same order, clamped to [-1, 1]:
/// dihedral_angles(t)[e] is dihedral_angle(dihedral_cosines(t)[e]) exactly.
std::array<long double, 6> dihedral_cosines(const std::array<Vec3, 4>& t);
/// The angle in degrees of a cosine in [-1, 1], as dihedral_angles rounds it.
double dihedral_angle(long double cosine);

/// What `bccmis mesh --stats` reports of a mesh (spec/mesh3d.md §6).
struct MeshQuality {
  std::size_t vertices = 0, tetrahedra = 0;
  std::size_t boundary_triangles = 0;  ///< triangles of exactly one tetrahedron
  double min_dihedral = 0, max_dihedral = 0;
  /// Dihedral angles per 15-degree bin centered on 0, 15, ..., 180 degrees
  /// (bin k holds [15k - 7.5, 15k + 7.5)), so the exact angles 45, 60, 90
  /// and 120 of the lattice's shapes fall in the middle of their bins.
  std::array<std::size_t, 13> histogram{};
};
MeshQuality mesh_quality(const std::vector<Tet>& tets);

}  // namespace bccmis::d3
