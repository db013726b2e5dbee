// The half-edge comparison of the memory benchmark: the lattice's
// triangulation (each cell a fan of triangles around its center, eq. (1)) as
// a CGAL::Surface_mesh. CGAL is confined to halfedge_mesh.cpp.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

namespace bccmis::bench {

/// A triangle mesh as plain arrays (counter-clockwise triangles).
struct Triangulation {
  std::vector<std::array<double, 2>> points;
  std::vector<std::array<std::uint32_t, 3>> triangles;
};

struct HalfedgeMeshStats {
  std::size_t vertices = 0, edges = 0, faces = 0;
  std::size_t bytes = 0;  ///< live_bytes() with the mesh built minus before
  bool ok = false;        ///< every face was added
};

/// Builds CGAL::Surface_mesh<Epick::Point_3> (z = 0) when `point3`, else
/// Surface_mesh<Epick::Point_2>, and measures it with `live_bytes` while it
/// is alive. With `reserve` the element counts are reserved exactly first
/// (the smallest a Surface_mesh of this triangulation can be); without, the
/// property arrays grow as add_vertex / add_face push (as built in practice).
HalfedgeMeshStats surface_mesh_of(const Triangulation& t, bool point3, bool reserve,
                                  const std::function<std::size_t()>& live_bytes);

}  // namespace bccmis::bench
