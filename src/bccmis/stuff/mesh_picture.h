// bccmis::stuff: pictures of a tetrahedral mesh in space for `bccmis render
// MESH.mesh` (spec/cli.md, render): its boundary triangles in an orthographic
// view, optionally beside a cut-away, and its dihedral-angle histogram.
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <string>

#include "bccmis/d3/mesh.h"

namespace bccmis::stuff {

/// The view of render_mesh_svg: orthographic, the viewer in direction
/// (1, -2, 1.5) from the mesh (in front, to the right, above); screen x along
/// (2, 1, 0), screen y up along (-1.5, 3, 5). A triangle faces the viewer when
/// its outward normal has a positive component along the view direction.
inline constexpr std::array<double, 3> kViewDirection{1, -2, 1.5};

/// A cut-away plane: axis 0, 1 or 2 (x, y, z) at a coordinate. The
/// tetrahedra whose centroid lies strictly on the viewer's side of it
/// (x > value, y < value, z > value: the sign of kViewDirection[axis]) are
/// removed.
struct CutPlane {
  int axis = 2;
  double value = 0;
};

/// The SVG picture: the boundary triangles (faces of exactly one
/// tetrahedron) that face the viewer, drawn far to near, filled with the
/// colour of their tetrahedron's level and shaded by their normal (each a
/// <polygon class="tri" data-level="L">), a legend (<rect class="legend">
/// per level present) and counts. With `cut`, a second panel at the same
/// scale on the right shows the boundary triangles of the tetrahedra left by
/// the cut (class "cut-tri"). Throws std::invalid_argument for a bad axis.
std::string render_mesh_svg(const d3::TetMeshF& mesh, const std::string& title,
                            const std::optional<CutPlane>& cut = std::nullopt);

/// The dihedral angles of every tetrahedron in bins of 5 degrees: bin k holds
/// [5k, 5k + 5), an angle within 1e-9 degrees below a bin's lower edge
/// counting in that bin (the angles are computed to about 1e-12 degrees, so
/// the exact 60 and 90 of the lattice's tetrahedra land in bins 12 and 18),
/// and 180 in bin 35.
struct AngleHistogram {
  std::array<std::size_t, 36> bins{};
  std::size_t angles = 0;
  double min = 0, max = 0;  ///< 0 when there are no tetrahedra
};
AngleHistogram angle_histogram(const d3::TetMeshF& mesh);

/// The histogram as an SVG bar plot: a <rect class="bar" data-bin="k"
/// data-count="n"> per non-empty bin, dashed lines (class "min" and "max") at
/// the extreme angles, axes with ticks and labels.
std::string render_histogram_svg(const d3::TetMeshF& mesh, const std::string& title);

}  // namespace bccmis::stuff
