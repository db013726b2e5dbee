// bccmis::stuff::statistics_json: S13's report of a run as one JSON object,
// the object `bccmis stuff --json` prints and the Python module's
// TetMesh.stats holds (spec/cli.md, stuff; spec/python.md P5).
#pragma once

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "bccmis/stuff/mesh_shape.h"

namespace bccmis::stuff {

/// The counts of a run `m` made with Settings::statistics, by the names
/// both reports give them: leaves, lattice_tetrahedra, cut_points, warped,
/// vertices, tetrahedra, boundary_triangles, boundary_components,
/// nonmanifold_edges; with features (S33) feature_edges, feature_curves,
/// feature_corners, feature_corners_conformed, feature_curves_conformed;
/// with --crease-cuts (S35.8) crease_cuts_placed, crease_cuts_kept.
/// A count named in m.not_computed is printed as null (JSON) or "-" (text).
std::vector<std::pair<const char*, std::size_t>> statistics_counts(const Meshed& m);

/// The JSON object of a run `m` made with Settings::statistics: `shape` (a
/// description), the counts, volumes, the sampled Hausdorff distance, the
/// dihedral angles, S27's topology and warnings, S21's soup report (when
/// the shape has one) and `seconds` with their sums "meshing" (every phase
/// but statistics and write) and "total". A number that is not finite is
/// null. No newline at the end.
std::string statistics_json(const std::string& shape, const Meshed& m, const PhaseSeconds& seconds);

}  // namespace bccmis::stuff
