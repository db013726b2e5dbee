// bccmis::io: the parts of a tetrahedral mesh that FEM files label
// (spec/mesh3d.md M23): its connected components (tetrahedra joined through
// shared triangles) and its boundary triangles, each with its component.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

namespace bccmis::io {

/// The components and the boundary of a tetrahedral mesh.
struct Regions {
  /// The component of each tetrahedron, 0 .. count - 1, numbered in the
  /// order of their first tetrahedron.
  std::vector<std::uint32_t> tet_component;
  std::uint32_t count = 0;
  /// The triangles of exactly one tetrahedron, outward (the face opposite
  /// v_i of a positively oriented tetrahedron, counter-clockwise seen from
  /// outside), sorted by component, then by their sorted vertex indices.
  std::vector<std::array<std::uint32_t, 3>> boundary;
  /// The component of each boundary triangle (that of its tetrahedron).
  std::vector<std::uint32_t> boundary_component;
};

/// M23 on the tetrahedra `tets` (indices into any vertex array). With
/// `boundary_by_triple`, also the boundary triangles in the order of their
/// sorted vertex triples (the order of spec/stuffing.md S11's boundary), from
/// the same one grouping of the faces (io/tet_faces.h).
Regions regions_of(const std::vector<std::array<std::uint32_t, 4>>& tets,
                   std::vector<std::array<std::uint32_t, 3>>* boundary_by_triple = nullptr);

}  // namespace bccmis::io
