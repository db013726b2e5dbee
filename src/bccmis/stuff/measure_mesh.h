// bccmis::stuff::measure_mesh: S13's and S33's measures of any tetrahedral
// mesh of a shape, in world coordinates: what `bccmis stuff --stats
// --hausdorff` reports of its own mesh, for another mesher's mesh of the
// same input (bench/stuff_peers), computed by the same functions.
//
//   const auto shape = bccmis::stuff::load_mesh_file("fandisk.off");
//   const auto m = bccmis::stuff::measure_mesh(*shape, tetgen_mesh, 60);
//   // m.statistics.hausdorff.max(), m.feature_distance
#pragma once

#include <optional>

#include "bccmis/d3/tet_mesh.h"
#include "bccmis/stuff/shape.h"
#include "bccmis/stuff/statistics.h"

namespace bccmis::stuff {

/// What measure_mesh found: S13's statistics with the sampled Hausdorff
/// distance, and with a feature angle S29's features of the shape and S33's
/// largest feature-point distance, all in world units.
struct MeshMeasures {
  Statistics statistics;
  std::size_t feature_curves = 0, feature_corners = 0;
  double feature_distance = -1;  ///< -1 without a feature angle
};

/// S13 (with the Hausdorff distance) and, when `feature_angle` is given,
/// S29 and S33 on `mesh` (world coordinates, positively oriented
/// tetrahedra) as a mesh of `world`: the mesh is taken to S24's local
/// coordinates of `world`, measured there as mesh_shape measures its own,
/// and the lengths and volumes scaled back.
MeshMeasures measure_mesh(const Shape& world, d3::TetMeshF mesh, std::optional<double> feature_angle);

}  // namespace bccmis::stuff
