// bccmis::d3 invariants, the stuffed-mesh layer (spec/invariants.md, "3D
// stuffed-mesh layer"): the checks of a tetrahedral mesh of a shape made by
// isosurface stuffing (spec/stuffing.md S7, S10-S12), on the mesh as it is
// written (double vertices, tetrahedra as indices).
//
// Written from the spec only: it includes nothing of src/bccmis/stuff/, finds
// the boundary itself (the triangles of exactly one tetrahedron) and computes
// its own exact orientation and dihedral angles, so a bug in the mesher cannot
// hide behind the same bug here. The checks, in this order:
//   stuffed-orientation  every tetrahedron positively oriented, exactly (S12)
//   stuffed-face-count   every triangle in at most two tetrahedra (S7)
//   stuffed-off-surface  every boundary vertex within `tolerance` of the
//                        surface, |distance(p)| <= tolerance (S11)
//   stuffed-open         the boundary closed: every edge crossed by the
//                        boundary triangles as often one way as the other (S11)
//   stuffed-dihedral     every dihedral angle within the claimed interval (S10),
//                        when one is given
// Used by `bccmis stuff --check` and by the stuffing tests.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <string>

#include "bccmis/invariants/d3/invariants.h"

namespace bccmis::d3 {

/// What the stuffed-mesh layer needs besides the mesh.
struct StuffedMeshClaims {
  /// The signed distance to the shape's surface (only |.| is used).
  std::function<double(const std::array<double, 3>&)> distance;
  /// How far a boundary vertex may be from the surface.
  double tolerance = 0;
  /// The dihedral angles claimed (degrees); unchecked when empty.
  std::optional<std::array<double, 2>> dihedral;
};

/// S10's interval (Labelle and Shewchuk's for the BCC lattice, degrees).
inline constexpr std::array<double, 2> kStuffedDihedralBounds{10.7792, 164.8092};

/// The first problem of the mesh (vertices, tetrahedra as indices into
/// them), as a Violation of layer 7 whose message names the tetrahedron,
/// triangle, edge or vertex by index; empty when there is none.
std::optional<Violation> check_stuffed_mesh(std::span<const std::array<double, 3>> vertices,
                                            std::span<const std::array<std::uint32_t, 4>> tets,
                                            const StuffedMeshClaims& claims);

}  // namespace bccmis::d3
